#include <irid/exchange/lut.h>

#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/io/output_file.h>
#include <irid/text_input.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <optional>

#ifndef IRID_VERSION
#error "IRID_VERSION (the project's version) must be defined by the build"
#endif

namespace irid {
namespace {

constexpr std::array<LutFormat, 3> formats{LutFormat::cube, LutFormat::clf, LutFormat::spi3d};
constexpr std::array<LutInterpolation, 2> interpolations{LutInterpolation::trilinear,
                                                          LutInterpolation::tetrahedral};

/// e of the log2 shaper: (max − min) · 2^−stops.
double log_offset(const LutDomain& d) noexcept { return (d.max - d.min) * std::exp2(-d.stops); }

/// log2(max − min + e) − log2(e) = log2(1 + 2^stops): the shaper's span in stops.
double log_span(const LutDomain& d) noexcept { return std::log2(1.0 + std::exp2(d.stops)); }

/// "[0, 1]", "log2 over [0, 16], 14 stops": the domain in words, and the matrix's space.
std::string describe_domain(const LutDomain& d) {
    const std::string range = fmt::format("[{}, {}]", format_shortest(d.min), format_shortest(d.max));
    const std::string space = d.matrix ? " in " + d.matrix_space : std::string();
    if (d.shaper == LutShaper::none) return fmt::format("uniform over {}{}", range, space);
    if (d.shaper == LutShaper::nodes) {
        std::string list;
        for (const double x : d.nodes) {
            if (!list.empty()) list += ' ';
            list += format_shortest(x);
        }
        return fmt::format("nodes over {}{} at {}", range, space, list);
    }
    return fmt::format("log2 shaper over {}, {} stops{}", range, d.stops, space);
}

/// The samples of the nodes shaper's LUT1D: one every `step` from min to max.
std::size_t node_samples(const LutDomain& d) noexcept {
    return static_cast<std::size_t>(std::llround((d.max - d.min) / d.step)) + 1;
}

std::string xml_escaped(std::string_view s) {
    std::string out;
    for (const char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

using Buffer = fmt::memory_buffer;

/// One node's output, shortest round-trip floats.
void append_triple(Buffer& out, const float* v) {
    fmt::format_to(std::back_inserter(out), "{} {} {}\n", v[0], v[1], v[2]);
}

std::string cube_text(const Lut3D& lut) {
    Buffer out;
    fmt::format_to(std::back_inserter(out), "# {}\n", lut.title);
    fmt::format_to(std::back_inserter(out), "# input: {}; output: {}\n", lut.source, lut.destination);
    if (lut.domain.min != 0.0 || lut.domain.max != 1.0) {
        // Ahead of LUT_3D_SIZE: ffmpeg skips what it does not know there, and fails after it.
        fmt::format_to(std::back_inserter(out), "LUT_3D_INPUT_RANGE {} {}\n", lut.domain.min,
                       lut.domain.max);
    }
    fmt::format_to(std::back_inserter(out), "LUT_3D_SIZE {}\n", lut.size);
    const std::size_t n = static_cast<std::size_t>(lut.size) * lut.size * lut.size;
    for (std::size_t i = 0; i < n; ++i) append_triple(out, &lut.values[3 * i]);  // red fastest
    return fmt::to_string(out);
}

std::string clf_text(const Lut3D& lut) {
    const LutDomain& d = lut.domain;
    Buffer out;
    const auto put = [&out]<class... A>(fmt::format_string<A...> f, A&&... a) {
        fmt::format_to(std::back_inserter(out), f, std::forward<A>(a)...);
    };
    put("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    put("<ProcessList compCLFversion=\"3.0\" id=\"irid-{}\" name=\"{}\">\n", irid_version(),
        xml_escaped(lut.title));
    put("    <Description>{}</Description>\n", xml_escaped(lut.title));
    put("    <InputDescriptor>{}</InputDescriptor>\n", xml_escaped(lut.source));
    put("    <OutputDescriptor>{}</OutputDescriptor>\n", xml_escaped(lut.destination));
    if (d.matrix) {
        // CLF 3.0 Matrix: out = M · in, the Array by rows.
        put("    <Matrix inBitDepth=\"32f\" outBitDepth=\"32f\">\n");
        put("        <Description>{} to {}, the cube's space</Description>\n", xml_escaped(lut.source),
            xml_escaped(d.matrix_space));
        put("        <Array dim=\"3 3\">\n");
        for (int i = 0; i < 3; ++i) put("{} {} {}\n", (*d.matrix)[i][0], (*d.matrix)[i][1], (*d.matrix)[i][2]);
        put("        </Array>\n    </Matrix>\n");
    }
    if (d.shaper == LutShaper::none) {
        // [min, max] → [0, 1], clamped: the cube's index space.
        put("    <Range inBitDepth=\"32f\" outBitDepth=\"32f\" style=\"Clamp\">\n");
        put("        <Description>the domain {} onto the cube</Description>\n", describe_domain(d));
        put("        <minInValue>{}</minInValue>\n        <maxInValue>{}</maxInValue>\n", d.min, d.max);
        put("        <minOutValue>0</minOutValue>\n        <maxOutValue>1</maxOutValue>\n");
        put("    </Range>\n");
    } else if (d.shaper == LutShaper::nodes) {
        // [min, max] → [0, 1], clamped; then each input to its place between the nodes (node i
        // at i / (size − 1)), linear between samples every `step`, all nodes among them.
        put("    <Range inBitDepth=\"32f\" outBitDepth=\"32f\" style=\"Clamp\">\n");
        put("        <Description>the domain [{}, {}] onto the shaper's input</Description>\n", d.min, d.max);
        put("        <minInValue>{}</minInValue>\n        <maxInValue>{}</maxInValue>\n", d.min, d.max);
        put("        <minOutValue>0</minOutValue>\n        <maxOutValue>1</maxOutValue>\n");
        put("    </Range>\n");
        const std::size_t samples = node_samples(d);
        put("    <LUT1D inBitDepth=\"32f\" outBitDepth=\"32f\" interpolation=\"linear\">\n");
        put("        <Description>{}</Description>\n", describe_domain(d));
        put("        <Array dim=\"{} 1\">\n", samples);
        for (std::size_t j = 0; j < samples; ++j) {
            const double x = j + 1 == samples ? d.max : d.min + static_cast<double>(j) * d.step;
            put("{}\n", static_cast<float>(lut_shape(d, x)));
        }
        put("        </Array>\n    </LUT1D>\n");
    } else {
        put("    <Range inBitDepth=\"32f\" outBitDepth=\"32f\" style=\"Clamp\">\n");
        put("        <Description>inputs clamped to the domain [{}, {}]</Description>\n", d.min, d.max);
        put("        <minInValue>{}</minInValue>\n        <maxInValue>{}</maxInValue>\n", d.min, d.max);
        put("        <minOutValue>{}</minOutValue>\n        <maxOutValue>{}</maxOutValue>\n", d.min, d.max);
        put("    </Range>\n");
        // y = logSideSlope · log2(linSideSlope · x + linSideOffset) + logSideOffset (CLF 3.0,
        // Log, style linToLog) with x + (e − min) inside the log: s(x) of lut.h.
        const double e = log_offset(d);
        const double slope = 1.0 / log_span(d);
        put("    <Log inBitDepth=\"32f\" outBitDepth=\"32f\" style=\"linToLog\">\n");
        put("        <Description>{}</Description>\n", describe_domain(d));
        put("        <LogParams base=\"2\" linSideSlope=\"1\" linSideOffset=\"{}\" logSideSlope=\"{}\" "
            "logSideOffset=\"{}\"/>\n",
            e - d.min, slope, -std::log2(e) * slope);
        put("    </Log>\n");
    }
    put("    <LUT3D inBitDepth=\"32f\" outBitDepth=\"32f\" interpolation=\"tetrahedral\">\n");
    put("        <Array dim=\"{0} {0} {0} 3\">\n", lut.size);
    const int n = lut.size;
    for (int r = 0; r < n; ++r) {  // blue fastest
        for (int g = 0; g < n; ++g) {
            for (int b = 0; b < n; ++b) {
                append_triple(out, &lut.values[3 * (static_cast<std::size_t>(r) +
                                                     static_cast<std::size_t>(n) * (g + static_cast<std::size_t>(n) * b))]);
            }
        }
    }
    put("        </Array>\n    </LUT3D>\n</ProcessList>\n");
    return fmt::to_string(out);
}

std::string spi3d_text(const Lut3D& lut) {
    Buffer out;
    fmt::format_to(std::back_inserter(out), "SPILUT 1.0\n3 3\n{0} {0} {0}\n", lut.size);
    const int n = lut.size;
    for (int b = 0; b < n; ++b) {
        for (int g = 0; g < n; ++g) {
            for (int r = 0; r < n; ++r) {
                const float* v = &lut.values[3 * (static_cast<std::size_t>(r) +
                                                  static_cast<std::size_t>(n) * (g + static_cast<std::size_t>(n) * b))];
                fmt::format_to(std::back_inserter(out), "{} {} {} {} {} {}\n", r, g, b, v[0], v[1], v[2]);
            }
        }
    }
    // OCIO's reader stops after the last entry: the one place a comment may go.
    fmt::format_to(std::back_inserter(out), "# {}; input: {}; output: {}\n", lut.title, lut.source,
                   lut.destination);
    return fmt::to_string(out);
}

}  // namespace

std::string_view irid_version() noexcept { return IRID_VERSION; }

std::string_view lut_format_name(LutFormat format) noexcept {
    switch (format) {
        case LutFormat::cube: return "cube";
        case LutFormat::clf: return "clf";
        case LutFormat::spi3d: return "spi3d";
    }
    return "cube";
}

LutFormat lut_format_for(const std::filesystem::path& path) {
    const std::string ext = ascii_lower(path.extension().string());
    std::vector<std::string> valid;
    for (const LutFormat f : formats) {
        std::string dotted = fmt::format(".{}", lut_format_name(f));
        if (ext == dotted) return f;
        valid.push_back(std::move(dotted));
    }
    throw UnknownNameError(
        "cannot tell the LUT format of " + quote_untrusted(path.string(), 200) +
            " from its extension; valid extensions: .cube (Resolve, Adobe; ffmpeg, OCIO), .clf "
            "(Academy/ASC Common LUT Format; OCIO), .spi3d (Sony; OCIO)",
        valid);
}

std::string_view lut_interpolation_name(LutInterpolation interpolation) noexcept {
    return interpolation == LutInterpolation::tetrahedral ? "tetrahedral" : "trilinear";
}

LutInterpolation parse_lut_interpolation(std::string_view name) {
    std::vector<std::string> valid;
    for (const LutInterpolation i : interpolations) {
        if (name == lut_interpolation_name(i)) return i;
        valid.emplace_back(lut_interpolation_name(i));
    }
    throw UnknownNameError("unknown LUT interpolation " + quote_untrusted(name) +
                               "; valid: trilinear, tetrahedral",
                           valid);
}

LutInterpolation lut_format_interpolation(LutFormat format) noexcept {
    return format == LutFormat::clf ? LutInterpolation::tetrahedral : LutInterpolation::trilinear;
}

void check_lut_format(LutFormat format, const LutDomain& d) {
    if (format != LutFormat::clf && d.matrix) {
        throw Error("." + std::string(lut_format_name(format)) + " carries no matrix ahead of its cube (this "
                    "LUT's cube is in " + d.matrix_space + "); write a .clf");
    }
    if (format == LutFormat::cube && d.shaper != LutShaper::none) {
        throw Error(".cube carries no shaper (only LUT_3D_INPUT_RANGE, a uniform range); write "
                    "a .clf for the " + std::string(d.shaper == LutShaper::log2 ? "log2 shaper" : "nodes shaper"));
    }
    if (format == LutFormat::spi3d && (d.shaper != LutShaper::none || d.min != 0.0 || d.max != 1.0)) {
        throw Error(".spi3d covers the inputs [0, 1] only, and this LUT's domain is " +
                    describe_domain(d) + "; write a .clf (or a .cube for a uniform range)");
    }
}

void check_lut_domain(const LutDomain& d) {
    if (!(std::isfinite(d.min) && std::isfinite(d.max) && d.min >= -1e6 && d.max <= 1e6 &&
          d.min < d.max)) {
        throw Error("LUT domain [" + format_shortest(d.min) + ", " + format_shortest(d.max) +
                    "]: needs finite -1e6 <= min < max <= 1e6");
    }
    if (d.matrix) {
        bool finite = true;
        for (const Vec3& row : d.matrix->m) {
            for (const double v : row) finite = finite && std::isfinite(v);
        }
        const double det = d.matrix->determinant();
        if (!finite || !(std::abs(det) >= 1e-12) || d.matrix_space.empty() ||
            d.matrix_space.find_first_of("\r\n") != std::string::npos) {
            throw Error("LUT matrix: needs finite values, a determinant that is not 0 (" + format_shortest(det) +
                        ") and the name of its output space (one line)");
        }
    }
    if (d.shaper == LutShaper::log2 && !(d.stops >= 1 && d.stops <= 40)) {
        throw Error("LUT shaper stops " + std::to_string(d.stops) + ": valid 1 to 40");
    }
    // Readers map [min, max] in float32: OpenColorIO refuses a Range narrower than 1e-6
    // ("maxInValue is too close to minInValue"), and nodes closer than float32 can tell apart
    // would be one node.
    const double ulps = 64.0 * std::exp2(std::ilogb(std::max({1.0, std::abs(d.min), std::abs(d.max)})) - 23);
    if (!(d.max - d.min >= std::max(1e-6, ulps))) {
        throw Error("LUT domain [" + format_shortest(d.min) + ", " + format_shortest(d.max) +
                    "]: max - min must be at least " + format_shortest(std::max(1e-6, ulps)) +
                    " (1e-6, which OpenColorIO requires, and 64 float32 steps at this magnitude)");
    }
    if (d.shaper == LutShaper::nodes) {
        if (!(d.step >= std::exp2(-20) && d.step <= 1.0) || (d.max - d.min) / d.step > std::exp2(20)) {
            throw Error("LUT nodes step " + format_shortest(d.step) +
                        ": valid 2^-20 to 1, with at most 2^20 steps from min to max");
        }
        const auto on_step = [&d](double x) {
            const double k = (x - d.min) / d.step;
            return std::abs(k - std::round(k)) <= 1e-6;
        };
        if (d.nodes.size() < 2 || d.nodes.front() != d.min || d.nodes.back() != d.max) {
            throw Error("LUT nodes: at least 2, from min to max");
        }
        for (std::size_t i = 0; i < d.nodes.size(); ++i) {
            if ((i > 0 && !(d.nodes[i] > d.nodes[i - 1])) || !on_step(d.nodes[i])) {
                throw Error("LUT node " + std::to_string(i) + " (" + format_shortest(d.nodes[i]) +
                            "): nodes must increase and lie on whole steps of " + format_shortest(d.step) +
                            " from min");
            }
        }
    }
}

void check_lut_domain(const LutDomain& d, int size) {
    check_lut_domain(d);
    if (d.shaper == LutShaper::nodes && d.nodes.size() != static_cast<std::size_t>(size)) {
        throw Error("LUT nodes: " + std::to_string(d.nodes.size()) + " positions for a LUT of " +
                    std::to_string(size) + " nodes per axis");
    }
}

double lut_shape(const LutDomain& d, double x) noexcept {
    if (!(x > d.min)) return 0.0;  // NaN too
    if (x >= d.max) return 1.0;
    if (d.shaper == LutShaper::none) return (x - d.min) / (d.max - d.min);
    if (d.shaper == LutShaper::nodes) {
        const auto& n = d.nodes;
        const std::size_t i = static_cast<std::size_t>(std::upper_bound(n.begin(), n.end(), x) - n.begin()) - 1;
        const double cells = static_cast<double>(n.size() - 1);
        return (static_cast<double>(i) + (x - n[i]) / (n[i + 1] - n[i])) / cells;
    }
    const double e = log_offset(d);
    return std::log2((x - d.min + e) / e) / log_span(d);
}

double lut_unshape(const LutDomain& d, double s) noexcept {
    if (!(s > 0.0)) return d.min;
    if (s >= 1.0) return d.max;
    if (d.shaper == LutShaper::none) return d.min + s * (d.max - d.min);
    if (d.shaper == LutShaper::nodes) {
        const double at = s * static_cast<double>(d.nodes.size() - 1);
        const auto i = std::min(static_cast<std::size_t>(at), d.nodes.size() - 2);
        const double f = at - static_cast<double>(i);
        return f == 0.0 ? d.nodes[i] : d.nodes[i] + f * (d.nodes[i + 1] - d.nodes[i]);
    }
    const double e = log_offset(d);
    return d.min + e * (std::exp2(s * log_span(d)) - 1.0);
}

Lut3D lut_grid(int size, const LutDomain& domain) {
    if (size < lut_min_size || size > lut_max_size) {
        throw Error("LUT size " + std::to_string(size) + ": valid " + std::to_string(lut_min_size) +
                    " to " + std::to_string(lut_max_size) + " (17, 33 and 65 are usual)");
    }
    check_lut_domain(domain, size);
    Lut3D lut;
    lut.size = size;
    lut.domain = domain;
    std::vector<float> axis(static_cast<std::size_t>(size));
    for (int i = 0; i < size; ++i) axis[static_cast<std::size_t>(i)] = static_cast<float>(lut.node(i));
    const std::size_t n = static_cast<std::size_t>(size) * size * size;
    lut.values.resize(3 * n);
    const Mat3 back = domain.matrix ? inverse(*domain.matrix, "LUT matrix") : Mat3::identity();
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t r = i % size, g = (i / size) % size, b = i / (static_cast<std::size_t>(size) * size);
        if (domain.matrix) {
            const Vec3 in = back * Vec3{lut.node(static_cast<int>(r)), lut.node(static_cast<int>(g)),
                                         lut.node(static_cast<int>(b))};
            for (int c = 0; c < 3; ++c) lut.values[3 * i + c] = static_cast<float>(in[c]);
            continue;
        }
        lut.values[3 * i + 0] = axis[r];
        lut.values[3 * i + 1] = axis[g];
        lut.values[3 * i + 2] = axis[b];
    }
    return lut;
}

std::string describe_lut_domain(const LutDomain& domain) { return describe_domain(domain); }

Lut3D bake_lut(const ClipPipeline& pipeline, int size, const LutDomain& domain, int threads) {
    Lut3D lut = lut_grid(size, domain);
    if (threads < 0) throw Error("threads " + std::to_string(threads) + " must be >= 0 (0: all)");
    const ColorSpace& from = pipeline.from();
    if (!from.is_rgb() && from.family != SpaceFamily::xyz) {
        throw Error("a LUT's input must be an RGB space or xyz (one range on every axis), not " +
                    color_space_name(from));
    }
    lut.source = color_space_name(pipeline.from());
    lut.destination = color_space_name(pipeline.to());
    std::string params;
    for (const auto& [name, value] : pipeline.clipper().parameters()) {
        params += " --param " + name + "=" + format_shortest(value);
    }
    if (pipeline.clipper().inverse()) params += " --inverse";
    const double peak = pipeline.clipper().gamut().max();
    lut.title = fmt::format("irid {} lut --method {}{} --from {} --to {}{} --size {}; domain {}",
                            irid_version(), clip_method_name(pipeline.clipper().method()), params,
                            lut.source, lut.destination,
                            peak != 1.0 ? " --max " + format_shortest(peak) : std::string(), size,
                            describe_domain(domain));
    if (const auto bad = pipeline.find_unconvertible(std::span<const float>(lut.values))) {
        throw Error("the LUT's node " + std::to_string(*bad) + " cannot be converted from " +
                    lut.source + " (an xyY y of 0)");
    }
    pipeline.clip(std::span<const float>(lut.values), std::span<float>(lut.values),
                  BatchOptions{.threads = threads});
    for (std::size_t i = 0; i < lut.values.size(); ++i) {
        if (!std::isfinite(lut.values[i])) {
            throw Error("the method gave a non-finite value at the LUT's node " +
                        std::to_string(i / 3) + "; nothing was written");
        }
    }
    return lut;
}

std::string lut_text(const Lut3D& lut, LutFormat format) {
    if (lut.size < lut_min_size || lut.size > lut_max_size ||
        lut.values.size() != 3 * static_cast<std::size_t>(lut.size) * lut.size * lut.size) {
        throw Error("not a LUT: size " + std::to_string(lut.size) + " with " +
                    std::to_string(lut.values.size()) + " values");
    }
    check_lut_domain(lut.domain, lut.size);
    check_lut_format(format, lut.domain);
    for (const char c : lut.title + lut.source + lut.destination) {
        if (c == '\n' || c == '\r') throw Error("a LUT's title and spaces must be single lines");
    }
    switch (format) {
        case LutFormat::cube: return cube_text(lut);
        case LutFormat::clf: return clf_text(lut);
        case LutFormat::spi3d: return spi3d_text(lut);
    }
    return cube_text(lut);
}

void write_lut(const std::filesystem::path& path, const Lut3D& lut) {
    const LutFormat format = lut_format_for(path);
    std::string text;
    try {
        text = lut_text(lut, format);
    } catch (const UnknownNameError&) {
        throw;
    } catch (const Error& e) {
        throw Error(quote_untrusted(path.string(), 200) + ": " + e.what());
    }
    io::write_output_file(path, text);
}

Rgb apply_lut(const Lut3D& lut, const Vec3& in, LutInterpolation interpolation) noexcept {
    const int n = lut.size;
    std::array<int, 3> i0{};
    std::array<double, 3> f{};
    const Vec3 cube = lut.domain.matrix ? *lut.domain.matrix * in : in;
    for (int c = 0; c < 3; ++c) {
        const double x = lut_shape(lut.domain, cube[c]) * (n - 1);
        const int i = std::min(static_cast<int>(x), n - 2);
        i0[c] = i;
        f[c] = x - i;
    }
    auto node = [&](int dr, int dg, int db) {
        const std::size_t k = static_cast<std::size_t>(i0[0] + dr) +
                              static_cast<std::size_t>(n) *
                                  (static_cast<std::size_t>(i0[1] + dg) +
                                   static_cast<std::size_t>(n) * static_cast<std::size_t>(i0[2] + db));
        const float* v = &lut.values[3 * k];
        return std::array<double, 3>{v[0], v[1], v[2]};
    };
    std::array<double, 3> out{};
    const double fr = f[0], fg = f[1], fb = f[2];
    if (interpolation == LutInterpolation::trilinear) {
        for (int db = 0; db < 2; ++db) {
            for (int dg = 0; dg < 2; ++dg) {
                for (int dr = 0; dr < 2; ++dr) {
                    const double w = (dr ? fr : 1 - fr) * (dg ? fg : 1 - fg) * (db ? fb : 1 - fb);
                    const auto v = node(dr, dg, db);
                    for (int c = 0; c < 3; ++c) out[c] += w * v[c];
                }
            }
        }
        return Rgb{out[0], out[1], out[2]};
    }
    // Tetrahedral: the cell cut into six tetrahedra along its diagonal from (0,0,0) to (1,1,1);
    // the walk from c000 to c111 takes the axes in decreasing order of their fractions.
    std::array<std::pair<double, int>, 3> order{{{fr, 0}, {fg, 1}, {fb, 2}}};
    std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::array<int, 3> at{0, 0, 0};
    std::array<double, 3> prev = node(0, 0, 0);
    out = prev;
    for (const auto& [frac, axis] : order) {
        at[static_cast<std::size_t>(axis)] = 1;
        const auto next = node(at[0], at[1], at[2]);
        for (int c = 0; c < 3; ++c) out[c] += frac * (next[c] - prev[c]);
        prev = next;
    }
    return Rgb{out[0], out[1], out[2]};
}

}  // namespace irid
