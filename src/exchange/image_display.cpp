#include <irid/exchange/image_display.h>

#include <irid/color/convert.h>
#include <irid/error.h>
#include <irid/exchange/icc.h>
#include <irid/gamut/display_transform.h>
#include <irid/text_input.h>

#include <fmt/core.h>

#include <algorithm>
#include <atomic>

namespace irid {

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
    std::atomic<std::size_t> clipped{0};
    change_image_colours(image, channels,
                         ImageColourOptions{.premultiplied_in = options.premultiplied_in,
                                            .premultiplied_out = options.premultiplied_out,
                                            .threads = options.threads},
                         [&](std::span<float> colours) {
                             if (profile != nullptr) profile->to_xyz(colours, colours, d65_xy, options.threads);
                             to_aces.convert(colours, colours);
                             transform.apply(colours, colours, options.threads);
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
