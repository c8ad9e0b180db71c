#include <irid/exchange/display_lut.h>

#include <irid/error.h>

#include <fmt/format.h>

#include <cmath>
#include <span>

namespace irid {

DisplayTransformOptions display_lut_options(std::string_view view, std::string_view display,
                                            std::string_view source, std::string_view target) {
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
    const ColorSpace source = color_space(transform.options().source);
    const bool encoded = source.family == SpaceFamily::rgb_encoded &&
                         source.rgb->transfer().kind() != TransferFunction::Kind::linear;
    const bool log = encoded && source.rgb->transfer().kind() == TransferFunction::Kind::acescct;
    if (format != LutFormat::clf && !log) {
        throw Error("a ." + std::string(lut_format_name(format)) +
                    " carries no shaper, so it takes the source acescct (ACEScct code values, its "
                    "nodes uniform over [0, 1]), not " + transform.options().source +
                    "; or write a .clf (a log2 shaper over a linear source)");
    }
    LutDomain d;
    if (encoded) return d;  // its code values [0, 1]
    d.shaper = LutShaper::log2;
    d.max = transform.output().rendering().forward_limit();
    d.stops = display_lut_stops;
    return d;
}

Lut3D bake_display_lut(const DisplayTransform& transform, int size, const LutDomain& domain,
                       int threads) {
    const DisplayTransformOptions& o = transform.options();
    if (o.inverse) throw Error("a display LUT bakes the forward transform, not the inverse");
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
