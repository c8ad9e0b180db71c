#include <irid/exchange/image_colours.h>

#include <irid/error.h>
#include <irid/parallel.h>
#include <irid/text_input.h>

#include <cstddef>
#include <vector>

namespace irid {
namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

/// body(begin, end) over [0, n) pixels on up to `threads` threads (0: all), in pieces of 16384.
void for_pixels(std::size_t n, int threads, const std::function<void(std::size_t, std::size_t)>& body) {
    parallel_ranges(n, threads, body, std::size_t{1} << 14);
}

}  // namespace

ImageColourChannels image_colour_channels(const io::Image& image, const std::string& what, const std::string& purpose) {
    const std::array<int, 3> rgb{image.channel_index("R"), image.channel_index("G"),
                                 image.channel_index("B")};
    if (rgb[0] >= 0 && rgb[1] >= 0 && rgb[2] >= 0) return {rgb, false};
    const std::array<int, 3> xyz{image.channel_index("X"), image.channel_index("Y"),
                                 image.channel_index("Z")};
    if (xyz[0] >= 0 && xyz[1] >= 0 && xyz[2] >= 0) return {xyz, true};
    throw Error(what + ": channels " + quote_untrusted(joined(image.channel_names), 80) + "; " + purpose +
                " needs colour channels named R, G and B (or X, Y and Z for CIE XYZ)");
}

void change_image_colours(io::Image& image, const ImageColourChannels& channels, const ImageColourOptions& options,
                          const std::function<void(std::span<float>)>& change) {
    const std::size_t pixels = image.pixel_count();
    const std::size_t stride = static_cast<std::size_t>(image.channels);
    const std::array<int, 3>& c3 = channels.index;
    const int alpha = image.channel_index("A");
    const bool unpremultiply = options.premultiplied_in && alpha >= 0;
    const bool premultiply = options.premultiplied_out && alpha >= 0;
    // Gather the colour channels (unpremultiplied where alpha is above 0).
    std::vector<float> colours(pixels * 3);
    for_pixels(pixels, options.threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const float* s = &image.pixels[i * stride];
            const float a = unpremultiply ? s[alpha] : 1.0f;
            const float k = a > 0.0f ? 1.0f / a : 1.0f;
            for (std::size_t c = 0; c < 3; ++c) colours[i * 3 + c] = s[c3[c]] * k;
        }
    });
    change(colours);
    // Scatter back, premultiplied for EXR (a transparent EXR pixel was never divided).
    for_pixels(pixels, options.threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            float* d = &image.pixels[i * stride];
            float k = 1.0f;
            if (premultiply && (d[alpha] > 0.0f || !unpremultiply)) k = d[alpha];
            for (std::size_t c = 0; c < 3; ++c) {
                d[c3[c]] = premultiply ? static_cast<float>(double{colours[i * 3 + c]} * k)
                                       : colours[i * 3 + c];
            }
        }
    });
    if (channels.xyz) {  // the colour channels now hold RGB of the destination
        const char* const names[] = {"R", "G", "B"};
        for (std::size_t c = 0; c < 3; ++c) image.channel_names[static_cast<std::size_t>(c3[c])] = names[c];
    }
}

}  // namespace irid
