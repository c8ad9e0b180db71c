#include <irid/exchange/image_display.h>

#include <irid/color/convert.h>
#include <irid/color/hdr_transfer.h>
#include <irid/color/numeric_table.h>
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
/// How far from a rounding boundary, in codes, a channel's interval must stay for the kernel's
/// value to be trusted with the double chain's code.
constexpr double code_margin = 0.01;
/// Bounds of the report's counts met within this much of the encoding's peak: the double chain's
/// rounding (about 1e-15 of a value) must not count a white as too bright.
constexpr double fit_tolerance = 1e-9;

/// Whether every encoded value in [lo, hi] is stored as one code by a writer of `levels` + 1
/// levels (clamped to [0, 1], rounded to nearest), with code_margin to spare.
bool one_code(double lo, double hi, double levels) noexcept {
    return std::floor(std::clamp(lo, 0.0, 1.0) * levels + 0.5 - code_margin) ==
           std::floor(std::clamp(hi, 0.0, 1.0) * levels + 0.5 + code_margin);
}

/// The code an encoded value rounds to, as a value the writer rounds to that code again
/// (code / levels in float is within 0.004 of a 16-bit code of it).
float snapped(double encoded, double levels) noexcept {
    return static_cast<float>(std::floor(std::clamp(encoded, 0.0, 1.0) * levels + 0.5) / levels);
}

/// What the report counts of a colour of the encoding's display light.
enum class Fit { inside, too_bright, out_of_gamut };

/// The bounds of an encoding's signal, in its linear RGB (DisplayImageReport).
struct SignalBounds {
    const RgbSpace* space = nullptr;
    /// The linear value of signal 1.
    double peak = 1.0;
    /// Luminance Y of linear RGB (the XYZ matrix's middle row; the white at 1 has Y = 1).
    std::array<double, 3> luminance{};
    double luminance_abs = 0.0;
    bool hlg = false;

    explicit SignalBounds(const RgbSpace& s) : space(&s), peak(s.transfer().decode(1.0)) {
        for (std::size_t k = 0; k < 3; ++k) {
            luminance[k] = s.to_xyz_matrix()[1][static_cast<int>(k)];
            luminance_abs += std::abs(luminance[k]);
        }
        hlg = s.transfer().kind() == TransferFunction::Kind::hlg;
    }

    /// The fit of `c`, with bounds met within `slack` more, and whether any colour within `e` of
    /// each channel could fit otherwise.
    [[nodiscard]] Fit fit(const Vec3& c, double e, bool& ambiguous, double slack = 0.0) const noexcept {
        const double tol = fit_tolerance * peak + slack;
        const double y = luminance[0] * c[0] + luminance[1] * c[1] + luminance[2] * c[2];
        const double ey = e * luminance_abs;
        ambiguous = (y - ey > peak + tol) != (y + ey > peak + tol);
        if (y > peak + tol) return Fit::too_bright;
        bool out = false;
        for (std::size_t k = 0; k < 3; ++k) {
            const bool below = c[k] < -tol, surely_below = c[k] + e < -tol,
                       maybe_below = c[k] - e < -tol;
            ambiguous = ambiguous || surely_below != maybe_below;
            out = out || below;
            if (!hlg) {
                const bool above = c[k] > peak + tol, surely_above = c[k] - e > peak + tol,
                           maybe_above = c[k] + e > peak + tol;
                ambiguous = ambiguous || surely_above != maybe_above;
                out = out || above;
            }
        }
        if (hlg && !out) {
            const double nits = 100.0;  // linear 1.0 = 100 cd/m²
            const std::array<double, 3> scene = hlg_scene_light_unclamped(
                {c[0] * nits, c[1] * nits, c[2] * nits}, hlg_nominal_peak_nits);
            for (const double s : scene) out = out || s > 1.0 + fit_tolerance;
        }
        return out ? Fit::out_of_gamut : Fit::inside;
    }
};

/// Counts of the report, gathered from threads.
struct Counts {
    std::atomic<std::size_t> too_bright{0}, out_of_gamut{0};
    std::atomic<std::size_t> positive_infinite{0}, negative_infinite{0}, not_a_number{0},
        non_finite{0};
};

/// Counts the colours with a non-finite channel and takes each such channel as
/// aces2_finite_input does, in the file's space, before any conversion mixes the channels.
void take_non_finite(std::span<float> colours, int threads, Counts& counts) {
    parallel_ranges(
        colours.size() / 3, threads,
        [&](std::size_t begin, std::size_t end) {
            std::size_t plus = 0, minus = 0, nan = 0, any = 0;
            for (std::size_t i = begin; i < end; ++i) {
                float* c = &colours[3 * i];
                if (std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])) continue;
                bool p = false, m = false, n = false;
                for (std::size_t k = 0; k < 3; ++k) {
                    p = p || (std::isinf(c[k]) && c[k] > 0.0f);
                    m = m || (std::isinf(c[k]) && c[k] < 0.0f);
                    n = n || std::isnan(c[k]);
                    c[k] = static_cast<float>(aces2_finite_input(c[k]));
                }
                plus += p ? 1 : 0;
                minus += m ? 1 : 0;
                nan += n ? 1 : 0;
                ++any;
            }
            counts.positive_infinite += plus;
            counts.negative_infinite += minus;
            counts.not_a_number += nan;
            counts.non_finite += any;
        },
        4096);
}

/// ACES2065-1 colours to the codes of `bits` the double chain (`linear`, to the encoding's
/// linear light, then the encoding's curve in double) gives, written in place as code / levels.
/// With `kernel`, the float kernel computes the linear light first, and a colour whose interval
/// [v − e, v + e] in any channel (e the kernel's error bound times the colour's largest channel)
/// holds a rounding boundary, or a bound of `bounds`, is recomputed by the double chain.
void show_encoded(std::span<float> colours, const DisplayTransform& linear, bool kernel,
                  const RgbSpace& encoding, const SignalBounds* bounds, int bits, int threads,
                  Counts& counts) {
    const double levels = std::ldexp(1.0, bits) - 1.0;
    const TransferFunction& curve = encoding.transfer();
    const double bound = kernel ? *linear.kernel_error_of_largest() : 0.0;
    parallel_ranges(
        colours.size() / 3, threads,
        [&](std::size_t begin, std::size_t end) {
            std::array<float, 3 * encoded_block> scene{};
            std::size_t bright = 0, outside = 0;
            for (std::size_t b = begin; b < end; b += encoded_block) {
                const std::size_t n = std::min(encoded_block, end - b);
                const std::span<float> part = colours.subspan(3 * b, 3 * n);
                std::copy(part.begin(), part.end(), scene.begin());
                if (kernel) linear.apply(part, part, 1);
                for (std::size_t i = 0; i < n; ++i) {
                    float* c = &part[3 * i];
                    bool exact = !kernel;
                    Vec3 shown{c[0], c[1], c[2]};
                    if (kernel) {
                        const double e = bound * std::max({std::abs(shown[0]), std::abs(shown[1]),
                                                           std::abs(shown[2])});
                        for (std::size_t k = 0; k < 3 && !exact; ++k)
                            exact = !one_code(curve.encode(shown[k] - e),
                                              curve.encode(shown[k] + e), levels);
                        bool ambiguous = false;
                        if (bounds != nullptr) (void)bounds->fit(shown, e, ambiguous);
                        exact = exact || ambiguous;
                    }
                    if (exact) shown = linear({scene[3 * i], scene[3 * i + 1], scene[3 * i + 2]});
                    if (bounds != nullptr) {
                        bool ambiguous = false;
                        const Fit fit = bounds->fit(shown, 0.0, ambiguous);
                        bright += fit == Fit::too_bright ? 1 : 0;
                        outside += fit == Fit::out_of_gamut ? 1 : 0;
                    }
                    const Rgb encoded = encoding.encode({shown[0], shown[1], shown[2]});
                    c[0] = snapped(encoded.r, levels);
                    c[1] = snapped(encoded.g, levels);
                    c[2] = snapped(encoded.b, levels);
                }
            }
            counts.too_bright += bright;
            counts.out_of_gamut += outside;
        },
        encoded_block);
}

std::string pixels(std::size_t n, const char* one, const char* many) {
    return fmt::format("{} {}", n, n == 1 ? one : many);
}

}  // namespace

bool encoding_holds_display(const RgbSpace& encoding, const Aces2Output& output, double margin) {
    const SignalBounds bounds(encoding);
    if (bounds.hlg) return false;
    const Aces2DisplaySpec& d = output.spec();
    const Mat3 to_xyz = rgb_to_xyz_matrix(d.limiting, d.limiting_white);
    const Converter to_encoding(color_space("xyz"), ColorSpace{SpaceFamily::rgb_linear, &encoding},
                                d65_xy);
    const double top = d.peak_nits / 100.0 * output.output_scale();
    for (int k = 0; k < 8; ++k) {
        const Vec3 xyz =
            to_xyz * Vec3{(k & 1) ? top : 0.0, (k & 2) ? top : 0.0, (k & 4) ? top : 0.0};
        bool ambiguous = false;
        if (bounds.fit(to_encoding(xyz), 0.0, ambiguous, margin * top) != Fit::inside) return false;
    }
    return true;
}

DisplayImagePlan plan_display_image(const std::string& view, const std::string& display,
                                    const std::optional<std::string>& to, io::ImageFormat format) {
    DisplayImagePlan plan;
    plan.view = display_view(view);
    plan.display = aces2_display(display);
    plan.encoded = io::is_integer_format(format);
    bool xyz = false;
    if (to) {
        const ColorSpace s = color_space(*to);
        if (!s.is_rgb() && s.family != SpaceFamily::xyz)
            throw Error(fmt::format(
                "{} is not an RGB space (nor xyz, CIE XYZ for an EXR); an image of a display's "
                "signal is written in one (irid display --list names each display's)",
                quote_untrusted(*to)));
        plan.encoding = s.rgb;
        xyz = s.family == SpaceFamily::xyz;
    } else {
        plan.encoding = default_display_encoding(plan.display);
        xyz = plan.encoding == nullptr && plan.display.encoding_xyz;
        if (plan.encoding == nullptr && !xyz)
            throw Error(fmt::format(
                "display {} has no RGB encoding of its own (its encoding's primaries are no "
                "named space's); name one with --to",
                plan.display.name));
    }
    if (xyz && plan.encoded) {
        throw Error(fmt::format(
            "CIE XYZ{}: PNG, TIFF and JPEG have no tagged encoding of it; write an EXR (linear "
            "CIE XYZ, 1.0 = 100 cd/m², with OpenEXR's chromaticities for XYZ), or name an RGB "
            "encoding with --to",
            to ? std::string() : " (the signal of display " + plan.display.name + ")"));
    }
    const TransferFunction::Kind kind = plan.encoding != nullptr ? plan.encoding->transfer().kind()
                                                                 : TransferFunction::Kind::linear;
    const bool hdr = kind == TransferFunction::Kind::pq || kind == TransferFunction::Kind::hlg;
    if (plan.encoding != nullptr) check_file_holds(*plan.encoding, format);
    plan.bits = hdr ? 16 : 8;
    return plan;
}

DisplayImageReport display_image(io::Image& image, const DisplayImagePlan& plan,
                                 const DisplayImageOptions& options, io::ImageFormat format,
                                 const std::string& what) {
    const ImageColourChannels channels = image_colour_channels(image, what, "display");
    // A file that says nothing about its space holds ACES2065-1, the scene space of the view.
    std::optional<ColorSpace> given = options.from;
    if (!given && !image_says_its_space(image) && !channels.xyz) given = color_space("aces2065-1-linear");
    DisplayImageReport report;
    report.source = decide_image_source(image, channels.xyz, given, what, "--from");
    const IccProfile* profile = report.source.file ? report.source.file->profile.get() : nullptr;

    const Converter to_aces(report.source.space, color_space("aces2065-1-linear"), d65_xy);
    // The double chain and, between linear sides, the float kernel, to the encoding's linear
    // light (or CIE XYZ); an integer file's curve and codes follow in double (show_encoded).
    const DisplayTransform linear(
        DisplayTransformOptions{.view = plan.view,
                                .display = plan.display.name,
                                .source = "aces2065-1-linear",
                                .target = plan.encoding_name() + (plan.encoding ? "-linear" : "")});
    // An 8-bit file: the float kernel where that stores the double chain's codes. A 16-bit code
    // is finer than the float kernel's error, so most colours of a 16-bit file would go to the
    // double chain after the kernel and the curve's checks: it gains nothing (a 4096² PQ file
    // took 17.9 s that way, 18.7 s by the double chain alone, docs/PERFORMANCE.md), and the
    // double chain alone is the simpler. HLG's curve acts on whole colours: the double chain.
    const bool kernel = plan.encoded && plan.bits == 8 && linear.kernel_error_of_largest() &&
                        plan.encoding->transfer().kind() != TransferFunction::Kind::hlg;
    std::optional<SignalBounds> bounds;
    if (plan.encoded && !encoding_holds_display(*plan.encoding, linear.output()))
        bounds.emplace(*plan.encoding);
    Counts counts;
    change_image_colours(image, channels,
                         ImageColourOptions{.premultiplied_in = options.premultiplied_in,
                                            .premultiplied_out = options.premultiplied_out,
                                            .threads = options.threads},
                         [&](std::span<float> colours) {
                             take_non_finite(colours, options.threads, counts);
                             if (profile != nullptr)
                                 profile->to_xyz(colours, colours, d65_xy, options.threads);
                             to_aces.convert(colours, colours);
                             if (plan.encoded) {
                                 show_encoded(colours, linear, kernel, *plan.encoding,
                                              bounds ? &*bounds : nullptr, plan.bits,
                                              options.threads, counts);
                             } else {
                                 linear.apply(colours, colours, options.threads);
                             }
                         });
    if (plan.encoding != nullptr) {
        tag_image(image, *plan.encoding, format);
    } else {
        tag_image_xyz(image);
    }

    report.too_bright = counts.too_bright;
    report.out_of_gamut = counts.out_of_gamut;
    report.positive_infinite = counts.positive_infinite;
    report.negative_infinite = counts.negative_infinite;
    report.not_a_number = counts.not_a_number;
    report.non_finite = counts.non_finite;
    report.notes = report.source.notes;
    if (report.non_finite > 0) {
        report.notes.push_back(
            fmt::format("{} a non-finite channel ({} with +Inf, {} with -Inf, {} with NaN): +Inf "
                        "is taken as 65504, half "
                        "float's largest value (a blown-out highlight), -Inf and NaN as 0",
                        pixels(report.non_finite, "pixel has", "pixels have"),
                        report.positive_infinite, report.negative_infinite, report.not_a_number));
    }
    if (report.too_bright + report.out_of_gamut > 0) {
        // What keeps them: the display's own encoding, when it holds every colour the display
        // shows, and always an EXR.
        const RgbSpace* own = default_display_encoding(plan.display);
        const std::string keeper =
            own != nullptr && own != plan.encoding && encoding_holds_display(*own, linear.output())
                ? fmt::format("the display's own encoding (--to {}) or an EXR keeps them",
                              own->name())
                : std::string("an EXR keeps them");
        const std::string name = plan.encoding->name();
        if (report.too_bright > 0) {
            report.notes.push_back(
                fmt::format("{} brighter than {}'s white at its peak ({} cd/m²) and clipped; {}",
                            pixels(report.too_bright, "pixel is", "pixels are"), name,
                            format_shortest(100.0 * SignalBounds(*plan.encoding).peak), keeper));
        }
        if (report.out_of_gamut > 0) {
            report.notes.push_back(
                fmt::format("{} outside {}'s gamut (a channel below 0, or above its peak at a "
                            "luminance it holds) and clipped; {}",
                            pixels(report.out_of_gamut, "pixel is", "pixels are"), name, keeper));
        }
    }
    return report;
}

}  // namespace irid
