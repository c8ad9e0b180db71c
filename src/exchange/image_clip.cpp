#include <irid/exchange/image_clip.h>

#include <irid/color/numeric_table.h>
#include <irid/error.h>

#include <algorithm>
#include <cstddef>
#include <optional>

namespace irid {

void clip_image(io::Image& image, const ImageColourChannels& channels, const ClipPipeline& pipeline,
                const ImageClipOptions& options, const std::string& what) {
    if (options.profile != nullptr && pipeline.from().family != SpaceFamily::xyz) {
        throw Error(what + ": colours read through an ICC profile are XYZ; the pipeline starts from " +
                    color_space_name(pipeline.from()));
    }
    const ImageColourOptions around{.premultiplied_in = options.premultiplied_in,
                                    .premultiplied_out = options.premultiplied_out,
                                    .threads = options.threads};
    change_image_colours(image, channels, around, [&](std::span<float> colours) {
        if (options.profile != nullptr) options.profile->to_xyz(colours, colours, pipeline.white(), options.threads);
        if (const std::optional<std::size_t> bad = pipeline.find_unconvertible(colours)) {
            const std::size_t w = static_cast<std::size_t>(std::max(image.width, 1));
            const float Y = colours[3 * *bad + 2];
            throw Error(what + ": pixel (" + std::to_string(*bad % w) + ", " + std::to_string(*bad / w) +
                        "): chromaticity y = 0 with luminance Y = " + format_shortest(Y) +
                        " has no XYZ (only black may have y = 0)");
        }
        pipeline.to_linear(colours, colours, options.threads);
        clip_batch(pipeline.clipper(), colours, BatchOptions{.threads = options.threads, .simd = true});
        if (options.encode) pipeline.encode(colours, options.threads);
    });
}

}  // namespace irid
