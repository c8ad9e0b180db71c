#include <irid/exchange/display_lut.h>

#include <irid/error.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <span>

namespace irid {
namespace {

/// Light: XYZ, linear RGB, or an RGB space whose curve is the identity (aces2065-1, acescg).
bool is_light(const ColorSpace& s) noexcept {
    return s.family == SpaceFamily::xyz || s.family == SpaceFamily::rgb_linear ||
           (s.family == SpaceFamily::rgb_encoded && s.rgb->transfer().kind() == TransferFunction::Kind::linear);
}

/// What a refused source's axes are, for the message.
const char* axes_of(SpaceFamily f) noexcept {
    switch (f) {
        case SpaceFamily::xyy: return "chromaticity x, y and luminance Y";
        case SpaceFamily::luv:
        case SpaceFamily::lab:
        case SpaceFamily::oklab: return "lightness and two opponent chromas, negative for half the hues";
        case SpaceFamily::lchuv:
        case SpaceFamily::lchab:
        case SpaceFamily::oklch: return "lightness, chroma and a hue angle that wraps at 360";
        default: return "not light";
    }
}

}  // namespace

void check_display_lut_source(std::string_view source) {
    const ColorSpace s = color_space(source);
    if (is_light(s) || s.family == SpaceFamily::rgb_encoded) return;
    throw Error(fmt::format(
        "a display LUT's source must be light (xyz or an RGB space's linear light, through a log2 shaper "
        "over [0, the rendering's forward limit]) or an RGB space's code values (acescct, over [0, 1]), not "
        "{}: its axes are {}, which no per-channel range in light lays out; convert the colours to "
        "aces2065-1 or acescct ahead of the LUT",
        color_space_name(s), axes_of(s.family)));
}

DisplayTransformOptions display_lut_options(std::string_view view, std::string_view display,
                                            std::string_view source, std::string_view target) {
    check_display_lut_source(source);
    DisplayTransformOptions o;
    o.view = std::string(view);
    o.display = std::string(display);
    o.source = std::string(source);
    if (!target.empty()) {
        o.target = std::string(target);
        return o;
    }
    const Aces2DisplaySpec spec = aces2_display(display);
    const RgbSpace* encoding = default_display_encoding(spec);
    if (encoding == nullptr) {
        throw Error("display " + spec.name +
                    " has no default encoding among irid's RGB spaces (its signal is CIE XYZ or "
                    "other primaries); name the LUT's output space (xyz or an RGB space)");
    }
    o.target = encoding->name();
    return o;
}

LutDomain display_lut_domain(const DisplayTransform& transform, LutFormat format) {
    check_display_lut_source(transform.options().source);
    const ColorSpace source = color_space(transform.options().source);
    const bool light = is_light(source);
    const bool log = !light && source.rgb->transfer().kind() == TransferFunction::Kind::acescct;
    if (format != LutFormat::clf && !log) {
        throw Error("a ." + std::string(lut_format_name(format)) +
                    " carries no shaper, so it takes the source acescct (ACEScct code values, its "
                    "nodes uniform over [0, 1]), not " + transform.options().source +
                    "; or write a .clf (a log2 shaper over a linear source)");
    }
    LutDomain d;
    if (!light) return d;  // its code values [0, 1]
    d.shaper = LutShaper::log2;
    d.max = transform.output().rendering().forward_limit();
    d.stops = display_lut_stops;
    // The source to AP1 as the transform goes: to ACES2065-1 (DisplayTransform's converter: D65
    // reference white, Bradford), then to AP1 (the chain's first step; the same white).
    const ColorSpace aces = color_space("aces2065-1-linear"), ap1 = color_space(display_lut_cube_space);
    const Mat3 m = *Converter(aces, ap1, d65_xy).linear_matrix() * *Converter(source, aces, d65_xy).linear_matrix();
    double off_identity = 0.0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) off_identity = std::max(off_identity, std::abs(m[i][j] - (i == j ? 1.0 : 0.0)));
    }
    if (off_identity > 1e-12) {
        d.matrix = m;
        d.matrix_space = std::string(display_lut_cube_space);
    }
    return d;
}

Lut3D bake_display_lut(const DisplayTransform& transform, int size, const LutDomain& domain,
                       int threads) {
    const DisplayTransformOptions& o = transform.options();
    if (o.inverse) throw Error("a display LUT bakes the forward transform, not the inverse");
    check_display_lut_source(o.source);
    if (threads < 0) throw Error("threads " + std::to_string(threads) + " must be >= 0 (0: all)");
    Lut3D lut = lut_grid(size, domain);
    lut.source = o.source;
    lut.destination = o.target;
    lut.title = fmt::format("irid {} lut --view {} --display {} --from {} --to {} --size {}; domain {}",
                            irid_version(), o.view, transform.output().spec().name, o.source,
                            o.target, size, describe_lut_domain(domain));
    transform.apply(std::span<const float>(lut.values), std::span<float>(lut.values), threads);
    for (std::size_t i = 0; i < lut.values.size(); ++i) {
        if (!std::isfinite(lut.values[i])) {
            throw Error("the display transform gave a non-finite value at the LUT's node " +
                        std::to_string(i / 3) + "; nothing was written");
        }
    }
    return lut;
}

}  // namespace irid
