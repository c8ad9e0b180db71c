#include <irid/exchange/image_display.h>

#include <irid/color/convert.h>
#include <irid/error.h>
#include <irid/exchange/icc.h>
#include <irid/gamut/display_transform.h>
#include <irid/parallel.h>
#include <irid/text_input.h>

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

namespace irid {
namespace {

/// Colours shown per block of show_encoded (their ACES2065-1 kept for the double chain).
constexpr std::size_t encoded_block = 1024;
/// How far from a rounding boundary, in codes, a channel's interval must stay (float's rounding
/// of the encoded value, 6e-8 of the signal, is 0.004 of a 16-bit code).
constexpr double code_margin = 0.01;

/// Whether every encoded value in [lo, hi] is stored as one code by a writer of `levels` + 1
/// levels (clamped to [0, 1], rounded to nearest), with code_margin to spare.
bool one_code(double lo, double hi, double levels) noexcept {
    return std::floor(std::clamp(lo, 0.0, 1.0) * levels + 0.5 - code_margin) ==
           std::floor(std::clamp(hi, 0.0, 1.0) * levels + 0.5 + code_margin);
}

/// ACES2065-1 colours to the codes of `bits` the double chain `exact` (to an encoded space)
/// would give, fast: the float kernel to the encoding's linear light (`linear`), the curve in
/// double; each colour with a channel whose interval [encode(v − e), encode(v + e)], e the
/// kernel's error bound times the colour's largest channel, holds a rounding boundary is
/// recomputed by `exact`. Writes the encoded values (not yet rounded) in place.
void show_encoded(std::span<float> colours, const DisplayTransform& linear, const DisplayTransform& exact,
                  const TransferFunction& curve, double bound, int bits, int threads) {
    const double levels = std::ldexp(1.0, bits) - 1.0;
    parallel_ranges(
        colours.size() / 3, threads,
        [&](std::size_t begin, std::size_t end) {
            std::array<float, 3 * encoded_block> scene{};
            for (std::size_t b = begin; b < end; b += encoded_block) {
                const std::size_t n = std::min(encoded_block, end - b);
                const std::span<float> part = colours.subspan(3 * b, 3 * n);
                std::copy(part.begin(), part.end(), scene.begin());
                linear.apply(part, part, 1);
                for (std::size_t i = 0; i < n; ++i) {
                    float* c = &part[3 * i];
                    const double e = bound * std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])});
                    std::array<double, 3> encoded{};
                    bool exact_needed = false;
                    for (std::size_t k = 0; k < 3; ++k) {
                        encoded[k] = curve.encode(c[k]);
                        exact_needed = exact_needed ||
                                       !one_code(curve.encode(c[k] - e), curve.encode(c[k] + e), levels);
                    }
                    if (exact_needed) {
                        const Vec3 x = exact({scene[3 * i], scene[3 * i + 1], scene[3 * i + 2]});
                        encoded = {x[0], x[1], x[2]};
                    }
                    for (std::size_t k = 0; k < 3; ++k) c[k] = static_cast<float>(encoded[k]);
                }
            }
        },
        encoded_block);
}

}  // namespace

DisplayImagePlan plan_display_image(const std::string& view, const std::string& display,
                                    const std::optional<std::string>& to, io::ImageFormat format) {
    if (view != "aces2") (void)DisplayTransform(DisplayTransformOptions{.view = view, .display = display});
    DisplayImagePlan plan;
    plan.view = view;
    plan.display = aces2_display(display);
    plan.encoded = io::is_integer_format(format);
    if (to) {
        const ColorSpace s = color_space(*to);
        if (!s.is_rgb())
            throw Error(fmt::format("{} is not an RGB space; an image of a display's signal is written in one "
                                    "(irid display --list names each display's)",
                                    quote_untrusted(*to)));
        plan.encoding = s.rgb;
    } else {
        plan.encoding = default_display_encoding(plan.display);
        if (plan.encoding == nullptr)
            throw Error(fmt::format("display {} has no RGB encoding of its own (its signal is CIE XYZ or of other "
                                    "primaries); name one with --to",
                                    plan.display.name));
    }
    const bool pq = plan.encoding->transfer().kind() == TransferFunction::Kind::pq;
    plan.bits = pq && format != io::ImageFormat::jpeg ? 16 : 8;
    return plan;
}

DisplayImageReport display_image(io::Image& image, const DisplayImagePlan& plan, const DisplayImageOptions& options,
                                 io::ImageFormat format, const std::string& what) {
    const ImageColourChannels channels = image_colour_channels(image, what, "display");
    // A file that says nothing about its space holds ACES2065-1, the scene space of the view.
    std::optional<ColorSpace> given = options.from;
    const bool says_nothing = image.icc_profile.empty() && !image.icc_profile_rejected && image.chromaticities.empty() &&
                              !image.stored_cmyk;
    if (!given && says_nothing && !channels.xyz) given = color_space("aces2065-1-linear");
    DisplayImageReport report;
    report.source = decide_image_source(image, channels.xyz, given, what, "--from");
    const IccProfile* profile = report.source.file ? report.source.file->profile.get() : nullptr;

    const Converter to_aces(report.source.space, color_space("aces2065-1-linear"), d65_xy);
    const std::string target = plan.encoding->name() + (plan.encoded ? "" : "-linear");
    const DisplayTransform transform(DisplayTransformOptions{
        .view = plan.view, .display = plan.display.name, .source = "aces2065-1-linear", .target = target});
    // An 8-bit file: the float kernel to the encoding's linear light where that stores the
    // double chain's codes (show_encoded). A 16-bit code is finer than the float kernel's error,
    // so most colours of a 16-bit file go to the double chain after the kernel and the curve's
    // checks: it gains nothing (a 4096² PQ file took 17.9 s that way, 18.7 s by the double
    // chain alone, docs/PERFORMANCE.md), and the double chain alone is the simpler.
    std::optional<DisplayTransform> linear;
    if (plan.encoded && plan.bits == 8) {
        linear.emplace(DisplayTransformOptions{.view = plan.view,
                                               .display = plan.display.name,
                                               .source = "aces2065-1-linear",
                                               .target = plan.encoding->name() + "-linear"});
        if (!linear->kernel_error_of_largest()) linear.reset();
    }
    std::atomic<std::size_t> clipped{0};
    change_image_colours(image, channels,
                         ImageColourOptions{.premultiplied_in = options.premultiplied_in,
                                            .premultiplied_out = options.premultiplied_out,
                                            .threads = options.threads},
                         [&](std::span<float> colours) {
                             if (profile != nullptr) profile->to_xyz(colours, colours, d65_xy, options.threads);
                             to_aces.convert(colours, colours);
                             if (linear) {
                                 show_encoded(colours, *linear, transform, plan.encoding->transfer(),
                                              *linear->kernel_error_of_largest(), plan.bits, options.threads);
                             } else {
                                 transform.apply(colours, colours, options.threads);
                             }
                             if (!plan.encoded) return;
                             std::size_t n = 0;
                             for (std::size_t i = 0; i < colours.size(); i += 3)
                                 n += std::max({colours[i], colours[i + 1], colours[i + 2]}) > 1.0f ? 1 : 0;
                             clipped = n;
                         });
    report.clipped = clipped;
    tag_image(image, *plan.encoding, format);
    return report;
}

}  // namespace irid
