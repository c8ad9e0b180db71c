#include <irid/exchange/ocio_config.h>

#include <irid/error.h>
#include <irid/gamut/pipeline.h>
#include <irid/io/output_file.h>

#include <fmt/format.h>

#include <array>
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
        case TransferFunction::Kind::parametric:
        case TransferFunction::Kind::sampled: break;
    }
    throw Error("the transfer function of " + space.name() + " has no OpenColorIO form");
}

std::string decode_transform(const RgbSpace& space) {
    std::string e = encode_transform(space);
    const std::size_t at = e.rfind("direction: inverse");
    if (at != std::string::npos) e.replace(at, 18, "direction: forward");
    return e;
}

/// The 4×4 row-major matrix of OCIO's MatrixTransform from one linear space to another.
std::string matrix_transform(const ColorSpace& from_linear, const ColorSpace& to_linear,
                             ChromaticAdaptation adaptation) {
    const Converter c(from_linear, to_linear, Xy{0.3127, 0.3290}, adaptation);
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

}  // namespace

LutDomain ocio_config_default_domain(const ColorSpace& source) noexcept {
    if (source.family == SpaceFamily::rgb_linear) return LutDomain{LutShaper::log2, 0.0, 16.0, 14};
    return LutDomain{};
}

OcioConfig make_ocio_config(const OcioConfigOptions& o) {
    if (!o.source.is_rgb()) throw Error("the config's source must be an RGB space, not " + color_space_name(o.source));
    if (!o.display.is_rgb()) throw Error("the config's display must be an RGB space, not " + color_space_name(o.display));
    const std::string source = color_space_name(o.source);
    const std::string display = color_space_name(o.display);
    if (source == display) throw Error("the source and the display are one space (" + source + "): nothing to clip");
    const LutDomain domain = o.domain.value_or(ocio_config_default_domain(o.source));
    std::vector<ClipMethod> methods = o.methods;
    if (methods.empty()) methods.assign(clip_methods().begin(), clip_methods().end());

    // The display from the reference: decode the source, one matrix, encode for the display.
    std::vector<std::string> steps;
    if (o.source.family == SpaceFamily::rgb_encoded) steps.push_back(decode_transform(*o.source.rgb));
    steps.push_back(matrix_transform(o.source.linear(), o.display.linear(), o.adaptation));
    if (o.display.family == SpaceFamily::rgb_encoded) {
        const std::string e = encode_transform(*o.display.rgb);
        if (!e.empty()) steps.push_back(e);
    }

    OcioConfig result;
    const Converter back(o.display.linear(), o.source, Xy{0.3127, 0.3290}, o.adaptation);
    for (const ClipMethod m : methods) {
        ClipPipelineOptions po;
        po.adaptation = o.adaptation;
        if (m == ClipMethod::aces_rgc) po.settings.set("clip", 1.0);  // a display holds the cube only
        const ClipPipeline p(m, o.source, o.display.linear(), po);
        Lut3D lut = bake_lut(p, o.size, domain, o.threads);
        back.convert(std::span<const float>(lut.values), std::span<float>(lut.values));
        lut.title += fmt::format("; output converted back to {} (an OCIO look in {})", source, source);
        lut.destination = source;
        result.luts.emplace_back(fmt::format("luts/irid-{}.clf", clip_method_name(m)), std::move(lut));
    }

    Buffer out;
    const auto put = [&out]<class... A>(fmt::format_string<A...> f, A&&... a) {
        fmt::format_to(std::back_inserter(out), f, std::forward<A>(a)...);
    };
    put("ocio_profile_version: 2\n\n");
    put("description: irid {} gamut looks, {} to the {} display; every clip method as a look "
        "(luts/irid-METHOD.clf, {}³)\n\n",
        irid_version(), source, display, o.size);
    put("search_path: luts\n\n");
    put("roles:\n  default: {0}\n  reference: {0}\n  color_picking: {1}\n  data: raw\n", source, display);
    if (o.source.family == SpaceFamily::rgb_linear) put("  scene_linear: {}\n", source);
    put("\nfile_rules:\n  - !<Rule> {{name: Default, colorspace: {}}}\n\n", source);
    put("displays:\n  {} display:\n", display);
    for (const ClipMethod m : methods) {
        put("    - !<View> {{name: {0}, colorspace: {1}, looks: irid-{0}}}\n", clip_method_name(m), display);
    }
    put("    - !<View> {{name: unclipped, colorspace: {}}}\n\n", display);
    put("active_displays: []\nactive_views: []\n\nlooks:\n");
    for (const ClipMethod m : methods) {
        put("  - !<Look>\n    name: irid-{0}\n    process_space: {1}\n"
            "    description: irid's {0} clip into the {2} gamut\n"
            "    transform: !<FileTransform> {{src: irid-{0}.clf, interpolation: tetrahedral}}\n\n",
            clip_method_name(m), source, display);
    }
    put("colorspaces:\n");
    put("  - !<ColorSpace>\n    name: {}\n    family: irid\n    encoding: {}\n"
        "    description: the scene's space (the reference)\n    isdata: false\n\n",
        source, o.source.family == SpaceFamily::rgb_linear ? "scene-linear" : "sdr-video");
    put("  - !<ColorSpace>\n    name: {}\n    family: irid\n    encoding: {}\n"
        "    description: the display, from {}\n    isdata: false\n    from_scene_reference: "
        "!<GroupTransform>\n      children:\n",
        display, o.display.family == SpaceFamily::rgb_linear ? "scene-linear" : "sdr-video", source);
    for (const std::string& s : steps) put("        - {}\n", s);
    put("\n  - !<ColorSpace>\n    name: raw\n    family: irid\n    description: data, not colour\n"
        "    isdata: true\n");
    result.config = fmt::to_string(out);
    return result;
}

void write_ocio_config(const std::filesystem::path& dir, const OcioConfig& config) {
    std::error_code ec;
    std::filesystem::create_directories(dir / "luts", ec);
    if (ec) throw Error("cannot make the folder " + (dir / "luts").string() + ": " + ec.message());
    for (const auto& [name, lut] : config.luts) write_lut(dir / name, lut);
    io::write_output_file(dir / "config.ocio", config.config);
}

}  // namespace irid
