#include <irid/exchange/ocio_config.h>

#include <irid/error.h>
#include <irid/exchange/display_lut.h>
#include <irid/exchange/image_display.h>
#include <irid/gamut/aces2_display.h>
#include <irid/gamut/pipeline.h>
#include <irid/io/output_file.h>
#include <irid/color/numeric_table.h>
#include <irid/text_input.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <iterator>
#include <system_error>

namespace irid {
namespace {

using Buffer = fmt::memory_buffer;

/// The OCIO transform that encodes linear light with the space's transfer function (an
/// inverse-direction decode), or "" for a linear space.
std::string encode_transform(const RgbSpace& space) {
    const TransferFunction& t = space.transfer();
    // OCIO 2.1 ExponentWithLinearTransform, forward = decode: the power (γ) and offset of the
    // encodings (IEC 61966-2-1: γ 2.4, 0.055; ITU-R BT.709-6: 1/0.45, 0.099; ITU-R BT.2020-2:
    // 1/0.45, α − 1 = 0.09929682680944).
    auto exponent_with_linear = [](double gamma, double offset) {
        return fmt::format("!<ExponentWithLinearTransform> {{gamma: [{0}, {0}, {0}, 1], offset: "
                           "[{1}, {1}, {1}, 0], direction: inverse}}",
                           gamma, offset);
    };
    switch (t.kind()) {
        case TransferFunction::Kind::linear: return "";
        case TransferFunction::Kind::srgb: return exponent_with_linear(2.4, 0.055);
        case TransferFunction::Kind::rec709: return exponent_with_linear(1.0 / 0.45, 0.099);
        case TransferFunction::Kind::rec2020: return exponent_with_linear(1.0 / 0.45, 0.09929682680944);
        case TransferFunction::Kind::gamma:
            return fmt::format("!<ExponentTransform> {{value: [{0}, {0}, {0}, 1], style: mirror, "
                               "direction: inverse}}",
                               t.gamma());
        case TransferFunction::Kind::acescct:
            // OCIO 2.1 LogCameraTransform, forward = linear to log: y = log_side_slope · log2(x) +
            // log_side_offset above lin_side_break, the linear toe of slope linear_slope below
            // (its offset follows from continuity: 0.0729055341958355 of S-2016-001).
            return "!<LogCameraTransform> {log_side_slope: 0.0570776255707763, log_side_offset: "
                   "0.554794520547945, lin_side_break: 0.0078125, linear_slope: 10.5402377416545}";
        case TransferFunction::Kind::pq:
            // OCIO 2.1's built-in curve has irid's scale: linear 1.0 = 100 cd/m².
            return "!<BuiltinTransform> {style: \"CURVE - ST-2084_to_LINEAR\", direction: inverse}";
        case TransferFunction::Kind::hlg:  // its OOTF acts on luminance: no curve of OCIO 2.1 holds it
        case TransferFunction::Kind::parametric:
        case TransferFunction::Kind::sampled: break;
    }
    throw Error("the transfer function of " + space.name() + " has no OpenColorIO form");
}

/// The 4×4 row-major matrix of OCIO's MatrixTransform from one linear space to another.
std::string matrix_transform(const ColorSpace& from_linear, const ColorSpace& to_linear,
                             ChromaticAdaptation adaptation) {
    const Converter c(from_linear, to_linear, d65_xy, adaptation);
    std::array<Vec3, 3> columns{};
    for (int j = 0; j < 3; ++j) {
        Vec3 unit{0.0, 0.0, 0.0};
        unit[j] = 1.0;
        columns[static_cast<std::size_t>(j)] = c(unit);
    }
    Buffer out;
    fmt::format_to(std::back_inserter(out), "!<MatrixTransform> {{matrix: [");
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) fmt::format_to(std::back_inserter(out), "{}, ", columns[static_cast<std::size_t>(j)][i]);
        fmt::format_to(std::back_inserter(out), "0, ");
    }
    fmt::format_to(std::back_inserter(out), "0, 0, 0, 1]}}");
    return fmt::to_string(out);
}

/// An RGB space whose transfer function is linear (the alias "acescg" of ACEScg) as its linear
/// form: its values are linear light, and its LUT domain and OCIO encoding must say so.
ColorSpace canonical(const ColorSpace& s) {
    if (s.family == SpaceFamily::rgb_encoded && s.rgb->transfer().kind() == TransferFunction::Kind::linear) {
        return s.linear();
    }
    return s;
}

/// Throws unless the config's display space holds the light of an ACES 2.0 display: the code
/// value 1 of an encoded space (100 cd/m² for the SDR curves, 10000 for PQ) must decode to at
/// least what the display emits at its peak. A linear space holds any value.
void check_display_holds(const Aces2DisplaySpec& d, const ColorSpace& display) {
    const ColorSpace space = canonical(display);
    if (space.family != SpaceFamily::rgb_encoded) return;
    // irid's display light: 1.0 = 100 cd/m² (display_transform.h).
    const double holds = 100.0 * space.rgb->transfer().decode(1.0);
    const double peak = d.peak_nits * d.linear_scale;
    if (peak <= holds * (1.0 + 1e-9)) return;
    const RgbSpace* own = default_display_encoding(d);
    throw Error(fmt::format(
        "the ACES 2.0 display {} reaches {} cd/m², and the config's display {} holds {} cd/m² at its code "
        "value 1: the view would clip its highlights there, or need codes above 1 that the display does not "
        "show; make the config for {} (the display's own encoding), or name displays of at most {} cd/m²",
        d.name, fmt::format("{:g}", peak), color_space_name(space), fmt::format("{:g}", holds),
        own != nullptr ? own->name() : std::string("its encoding (CIE XYZ or other primaries)"),
        fmt::format("{:g}", holds)));
}

/// How far outside the config's display space a display's colours may reach, of its peak.
/// P3's red primary lies just outside Rec.2020 (its blue channel there is −0.12 % of the peak;
/// P3-D60's −0.13 %), and OpenColorIO's ACES configs show the P3-limited views on Rec.2100-PQ
/// displays; the nearest mismatch beyond, a Rec.709-D60 view whose white was scaled for P3-D65
/// shown on sRGB, reaches 0.93 %: its white clips (docs/DISPLAY.md, "OpenColorIO configs").
constexpr double config_display_margin = 0.002;

/// Refuses a display whose colours the config's display space does not hold: the view would
/// bake codes below 0 or above 1, which the display clips channel by channel.
void check_display_fits(const Aces2DisplaySpec& d, const ColorSpace& display) {
    const ColorSpace space = canonical(display);
    if (space.family != SpaceFamily::rgb_encoded) return;
    if (encoding_holds_display(*space.rgb, Aces2Output(d), config_display_margin)) return;
    const RgbSpace* own = default_display_encoding(d);
    throw Error(fmt::format(
        "the ACES 2.0 display {} shows colours outside the gamut of the config's display {}: the view "
        "would need codes below 0 or above 1, which the display clips; make the config for {} (the "
        "display's own encoding) or a wider display space, or name displays whose limiting gamut {} holds",
        d.name, color_space_name(space),
        own != nullptr ? own->name() : std::string("its encoding (CIE XYZ or other primaries)"),
        color_space_name(space)));
}

}  // namespace

std::pair<double, double> ocio_source_range(const OcioConfigOptions& o) {
    const bool linear = canonical(o.source).family == SpaceFamily::rgb_linear;
    const auto range = o.source_range.value_or(linear ? std::pair{-1.0, 16.0} : std::pair{0.0, 1.0});
    const auto [bottom, top] = range;
    if (!(std::isfinite(bottom) && std::isfinite(top) && bottom >= -1e5 && top <= 1e5 && bottom < top && top > 0.0)) {
        throw Error("source range [" + format_shortest(bottom) + ", " + format_shortest(top) +
                    "]: needs finite -1e5 <= min < max <= 1e5 with max > 0, and to reach an interval at most 4096 wide in "
                    "the display's linear space");
    }
    return range;
}

LutDomain ocio_look_domain(const OcioConfigOptions& o) {
    if (o.size < ocio_look_min_size || o.size > lut_max_size) {
        throw Error("LUT size " + std::to_string(o.size) + ": an OCIO config's looks take " +
                    std::to_string(ocio_look_min_size) + " to " + std::to_string(lut_max_size) + " nodes");
    }
    const ColorSpace source = canonical(o.source);
    // Named variables, not structured bindings: a lambda below captures them (clang 14 cannot).
    const std::pair<double, double> range = ocio_source_range(o);
    const double bottom = range.first, top = range.second;
    // The corners of the source cube in the display's linear space bound every source colour:
    // the conversion is one matrix, after decoding (which maps [0, 1] onto [0, 1] and keeps
    // order).
    const Converter to_display(source.linear(), o.display.linear(), d65_xy, o.adaptation);
    const auto decoded = [&source](double v) {
        return source.family == SpaceFamily::rgb_linear ? v : source.rgb->transfer().decode(v);
    };
    const double c0 = decoded(bottom), c1 = decoded(top);
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 8; ++k) {
        const Vec3 c = to_display(Vec3{(k & 1) ? c1 : c0, (k & 2) ? c1 : c0, (k & 4) ? c1 : c0});
        for (int i = 0; i < 3; ++i) {
            lo = std::min(lo, c[i]);
            hi = std::max(hi, c[i]);
        }
    }
    // Within 1e-3 of the cube the nodes would only cost resolution: such a range is the cube's.
    if (lo > -1e-3) lo = 0.0;
    if (hi < 1.0 + 1e-3) hi = 1.0;

    // Cells in proportion to the extent of each range: [0, 1] counts 1, below log2(1 + |lo|),
    // above log2(hi); [0, 1] gets at least 3/8, and each range beyond the cube at least one.
    const int cells = o.size - 1;
    const double m_below = std::log2(1.0 - lo), m_above = std::log2(hi);
    const int needed_outside = (lo < 0.0) + (hi > 1.0);
    int inside = static_cast<int>(std::lround(cells / (1.0 + m_below + m_above)));
    inside = std::clamp(inside, static_cast<int>(std::lround(0.375 * cells)), cells - needed_outside);
    const int rest = cells - inside;
    int below = lo < 0.0 ? static_cast<int>(std::lround(rest * m_below / (m_below + m_above))) : 0;
    if (lo < 0.0) below = std::clamp(below, 1, rest - (hi > 1.0));
    const int above = rest - below;

    std::vector<double> x;
    const double pi = std::acos(-1.0);
    std::vector<double> in(static_cast<std::size_t>(inside) + 1);
    for (int k = 0; k <= inside; ++k) in[static_cast<std::size_t>(k)] = 0.5 - 0.5 * std::cos(pi * k / inside);
    in.front() = 0.0;
    in.back() = 1.0;
    const double w = in[1];
    const double span_below = std::log2(1.0 - lo / w);
    for (int j = below; j >= 1; --j) x.push_back(-w * (std::exp2(span_below * j / below) - 1.0));
    x.insert(x.end(), in.begin(), in.end());
    for (int j = 1; j <= above && hi > 1.0; ++j) x.push_back(std::exp2(std::log2(hi) * j / above));

    // The step of the shaper's samples: a power of two at most a quarter of the closest two
    // nodes, but no finer than 2^18 samples over the domain (2.5 MB of text) and no coarser than
    // 1/64 (0, 1 and the nodes between them must lie on it); nodes are rounded to it and, where
    // two would meet, the upper is moved up one step.
    double closest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < x.size(); ++i) closest = std::min(closest, x[i] - x[i - 1]);
    constexpr double max_samples = 262144.0, max_step = 1.0 / 64.0;
    const double finest = std::exp2(std::ceil(std::log2((hi - lo) / max_samples)));
    const double step = std::max(std::min(std::exp2(std::floor(std::log2(closest / 4.0))), max_step), finest);
    const auto too_wide = [&] {
        return Error(fmt::format("the source range [{}, {}] reaches [{:.6g}, {:.6g}] in {}, wider than the looks' "
                                 "LUT can place {} nodes in with 0 and 1 among them (at most {:g} wide); "
                                 "narrow the range",
                                 format_shortest(bottom), format_shortest(top), lo, hi,
                                 color_space_name(o.display.linear()), o.size, max_samples * max_step));
    };
    if (step > max_step) throw too_wide();
    LutDomain d;
    d.shaper = LutShaper::nodes;
    d.step = step;
    d.min = std::floor(lo / step) * step;
    d.max = std::ceil(hi / step) * step;
    for (double& v : x) v = std::round(v / step) * step;
    x.front() = d.min;
    x.back() = d.max;
    for (std::size_t i = 1; i + 1 < x.size(); ++i) x[i] = std::max(x[i], x[i - 1] + step);
    if (x[x.size() - 2] >= d.max) throw too_wide();
    d.nodes = std::move(x);
    check_lut_domain(d, o.size);
    return d;
}

std::vector<std::string> ocio_aces2_displays(const OcioConfigOptions& o) {
    std::vector<std::string> names;
    if (!o.aces2_displays) {
        if (!o.display.is_rgb()) return names;
        const std::string shown = color_space_name(canonical(o.display));
        for (const Aces2DisplaySpec& d : aces2_displays()) {
            const RgbSpace* encoding = default_display_encoding(d);
            if (encoding != nullptr && color_space_name(canonical(color_space(encoding->name()))) == shown) {
                names.push_back(d.name);
            }
        }
        return names;
    }
    for (const std::string& name : *o.aces2_displays) {
        if (ascii_lower(name).rfind("custom:", 0) == 0) {
            throw Error("ACES 2.0 display " + quote_untrusted(name, 200) +
                        ": a config's views take built-in displays (irid display --list), whose names "
                        "name its views and LUT files");
        }
        const Aces2DisplaySpec d = aces2_display(name);
        if (std::find(names.begin(), names.end(), d.name) != names.end()) {
            throw Error("the ACES 2.0 display " + d.name + " is named twice; each view is offered once");
        }
        if (o.display.is_rgb()) {
            check_display_holds(d, o.display);
            check_display_fits(d, o.display);
        }
        names.push_back(d.name);
    }
    return names;
}

OcioConfig make_ocio_config(const OcioConfigOptions& o) {
    if (!o.source.is_rgb()) throw Error("the config's source must be an RGB space, not " + color_space_name(o.source));
    if (!o.display.is_rgb()) throw Error("the config's display must be an RGB space, not " + color_space_name(o.display));
    const ColorSpace source = canonical(o.source);
    const ColorSpace display = canonical(o.display);
    std::vector<ClipMethod> methods = o.methods;
    if (methods.empty()) methods.assign(clip_methods().begin(), clip_methods().end());
    for (std::size_t i = 0; i < methods.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (methods[i] == methods[j]) {
                throw Error("the method " + std::string(clip_method_name(methods[i])) +
                            " is named twice; each look is offered once");
            }
        }
    }
    const LutDomain domain = ocio_look_domain(o);

    // The spaces by name: the reference (the source's linear form), the source when encoded,
    // the looks' process space (the display's linear form) and the display when encoded. Names
    // that coincide are one colour space.
    const ColorSpace reference = source.linear();
    const ColorSpace process = display.linear();
    const std::string reference_name = color_space_name(reference);
    const std::string source_name = color_space_name(source);
    const std::string process_name = color_space_name(process);
    const std::string display_name = color_space_name(display);
    const bool same_linear = reference_name == process_name;
    const std::string to_process = same_linear ? std::string() : matrix_transform(reference, process, o.adaptation);

    OcioConfig result;
    for (const ClipMethod m : methods) {
        ClipPipelineOptions po;
        po.adaptation = o.adaptation;
        po.settings = display_clip_settings(m);
        const ClipPipeline p(m, process, process, po);
        Lut3D lut = bake_lut(p, o.size, domain, o.threads);
        lut.title += fmt::format("; the look irid-{} of an OCIO config, in {} (the {} display's linear space)",
                                 clip_method_name(m), process_name, display_name);
        result.luts.emplace_back(fmt::format("luts/irid-{}.clf", clip_method_name(m)), std::move(lut));
    }
    const std::vector<std::string> aces2 = ocio_aces2_displays(o);
    for (const std::string& name : aces2) {
        const DisplayTransform t(display_lut_options("aces2", name, reference_name, display_name));
        Lut3D lut = bake_display_lut(t, o.size, display_lut_domain(t, LutFormat::clf), o.threads);
        lut.title += "; the view 'ACES 2.0 " + name + "' of an OCIO config";
        result.display_luts.emplace_back(fmt::format("luts/aces2-{}.clf", name), std::move(lut));
    }

    Buffer out;
    const auto put = [&out]<class... A>(fmt::format_string<A...> f, A&&... a) {
        fmt::format_to(std::back_inserter(out), f, std::forward<A>(a)...);
    };
    // A name the user gave that differs from the canonical one ("acescg" for "acescg-linear")
    // stays usable as an alias.
    const auto aliases = [&put](const std::string& name, const ColorSpace& given) {
        const std::string given_name = color_space_name(given);
        if (given_name != name) put("    aliases: [{}]\n", given_name);
    };
    put("ocio_profile_version: 2.1\n\n");
    put("description: irid {} gamut looks, {} to the {} display; every clip method as a look "
        "(luts/irid-METHOD.clf, {}³, in {})\n\n",
        irid_version(), source_name, display_name, o.size, process_name);
    put("search_path: luts\n\n");
    put("roles:\n  default: {0}\n  reference: {1}\n  scene_linear: {1}\n  color_picking: {2}\n"
        "  data: raw\n",
        source_name, reference_name, display_name);
    put("\nfile_rules:\n  - !<Rule> {{name: Default, colorspace: {}}}\n\n", source_name);
    put("displays:\n  {} display:\n", display_name);
    for (const ClipMethod m : methods) {
        put("    - !<View> {{name: {0}, colorspace: {1}, looks: irid-{0}}}\n", clip_method_name(m), display_name);
    }
    put("    - !<View> {{name: unclipped, colorspace: {}}}\n", display_name);
    for (const std::string& name : aces2) put("    - !<View> {{name: ACES 2.0 {0}, colorspace: aces2-{0}}}\n", name);
    put("\n");
    put("active_displays: []\nactive_views: []\n\nlooks:\n");
    for (const ClipMethod m : methods) {
        put("  - !<Look>\n    name: irid-{0}\n    process_space: {1}\n"
            "    description: irid's {0} clip into the {2} gamut\n"
            "    transform: !<FileTransform> {{src: irid-{0}.clf, interpolation: tetrahedral}}\n\n",
            clip_method_name(m), process_name, display_name);
    }
    put("colorspaces:\n");
    put("  - !<ColorSpace>\n    name: {}\n", reference_name);
    if (source.family == SpaceFamily::rgb_linear) aliases(reference_name, o.source);
    put("    family: irid\n    encoding: scene-linear\n    description: the scene's linear light (the "
        "reference)\n    isdata: false\n\n");
    if (source.family == SpaceFamily::rgb_encoded) {
        put("  - !<ColorSpace>\n    name: {}\n    family: irid\n    encoding: sdr-video\n"
            "    description: the scene's space, encoded\n    isdata: false\n"
            "    from_scene_reference: {}\n\n",
            source_name, encode_transform(*source.rgb));
    }
    if (!same_linear) {
        put("  - !<ColorSpace>\n    name: {}\n", process_name);
        if (display.family == SpaceFamily::rgb_linear) aliases(process_name, o.display);
        put("    family: irid\n    encoding: scene-linear\n"
            "    description: the {} display's linear light, where the looks run\n    isdata: false\n"
            "    from_scene_reference: {}\n\n",
            display_name, to_process);
    }
    if (display.family == SpaceFamily::rgb_encoded && display_name != source_name) {
        put("  - !<ColorSpace>\n    name: {}\n    family: irid\n    encoding: sdr-video\n"
            "    description: the display, from {}\n    isdata: false\n    from_scene_reference: ",
            display_name, reference_name);
        const std::string encode = encode_transform(*display.rgb);
        if (same_linear) {
            put("{}\n\n", encode);
        } else {
            put("!<GroupTransform>\n      children:\n        - {}\n        - {}\n\n", to_process, encode);
        }
    }
    for (const std::string& name : aces2) {
        put("  - !<ColorSpace>\n    name: aces2-{0}\n    family: irid\n    encoding: {1}\n"
            "    description: the ACES 2.0 Output Transform for {0}, as {2}, baked by irid\n"
            "    isdata: false\n"
            "    from_scene_reference: !<FileTransform> {{src: aces2-{0}.clf, interpolation: tetrahedral}}\n\n",
            name, aces2_display(name).peak_nits > 100.0 ? "hdr-video" : "sdr-video", display_name);
    }
    put("  - !<ColorSpace>\n    name: raw\n    family: irid\n    description: data, not colour\n"
        "    isdata: true\n");
    result.config = fmt::to_string(out);
    return result;
}

std::vector<std::filesystem::path> write_ocio_config(const std::filesystem::path& dir, const OcioConfig& config) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_symlink(dir, ec) && !fs::exists(dir, ec)) {
        throw Error(quote_untrusted(dir.string(), 200) + " is a symbolic link to " +
                    quote_untrusted(fs::read_symlink(dir, ec).string(), 200) +
                    ", which does not exist; make that folder, or give another");
    }
    fs::create_directories(dir / "luts", ec);
    if (ec) throw Error("cannot make the folder " + quote_untrusted((dir / "luts").string(), 200) + ": " + ec.message());
    std::vector<std::pair<std::string, std::string>> files;
    for (const auto* set : {&config.luts, &config.display_luts}) {
        for (const auto& [name, lut] : *set) files.emplace_back(name, lut_text(lut, lut_format_for(name)));
    }
    files.emplace_back("config.ocio", config.config);
    io::write_output_files(dir, files);
    // What an earlier config wrote and this one does not: its looks' and views' LUTs.
    std::vector<fs::path> stale;
    for (const fs::directory_entry& e : fs::directory_iterator(dir / "luts", ec)) {
        const std::string name = e.path().filename().string();
        const bool irid_name = (name.starts_with("irid-") || name.starts_with("aces2-")) && name.ends_with(".clf");
        const bool written = std::any_of(files.begin(), files.end(),
                                         [&](const auto& f) { return f.first == "luts/" + name; });
        if (irid_name && !written && e.is_regular_file(ec)) stale.push_back(e.path());
    }
    std::vector<fs::path> removed;
    for (const fs::path& p : stale) {
        if (fs::remove(p, ec)) removed.push_back(p);
        else if (ec) throw Error("cannot remove " + quote_untrusted(p.string(), 200) + ", a LUT of an earlier config: " + ec.message());
    }
    return removed;
}

}  // namespace irid
