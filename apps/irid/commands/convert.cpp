// irid convert --from SPACE --to SPACE [--white NAME] [--adaptation METHOD]
//
// One colour per line on stdin, the same colours in the other space on stdout. XYZ is relative
// to the reference white given by --white (Y = 1); CIELUV and CIELAB use that white. RGB
// spaces and Oklab have whites of their own (Oklab: D65); where it differs from --white the XYZ
// is chromatically adapted between the two (Bradford unless --adaptation says otherwise).
#include "../cli_common.h"

#include <irid/color.h>

#include <iostream>
#include <optional>

namespace irid::cli {
namespace {

enum class Family { xyz, xyy, luv, lab, lchuv, lchab, oklab, oklch, rgb_linear, rgb_encoded };

struct Space {
    Family family;
    const RgbSpace* rgb = nullptr;
};

std::vector<std::string> space_names() {
    std::vector<std::string> names{"xyz", "xyy", "luv", "lab", "lchuv", "lchab", "oklab", "oklch"};
    for (const RgbSpace* s : builtin_rgb_spaces()) {
        names.push_back(s->name());
        names.push_back(s->name() + "-linear");
    }
    return names;
}

Space parse_space(const std::string& name, const char* option) {
    static const std::pair<const char*, Family> fixed[] = {
        {"xyz", Family::xyz},     {"xyy", Family::xyy},     {"luv", Family::luv},
        {"lab", Family::lab},     {"lchuv", Family::lchuv}, {"lchab", Family::lchab},
        {"oklab", Family::oklab}, {"oklch", Family::oklch}};
    for (const auto& [n, f] : fixed) {
        if (name == n) return {f};
    }
    if (const RgbSpace* s = find_rgb_space(name)) return {Family::rgb_encoded, s};
    constexpr std::string_view suffix = "-linear";
    if (name.size() > suffix.size() && name.ends_with(suffix)) {
        if (const RgbSpace* s = find_rgb_space(name.substr(0, name.size() - suffix.size()))) {
            return {Family::rgb_linear, s};
        }
    }
    throw UsageError("unknown space '" + name + "' for " + option + "; valid names: " +
                     join(space_names()));
}

const char* header_of(const Space& s) {
    switch (s.family) {
        case Family::xyz: return "X,Y,Z";
        case Family::xyy: return "x,y,Y";
        case Family::luv: return "L,u,v";
        case Family::lab: return "L,a,b";
        case Family::lchuv: return "L,C,h";
        case Family::lchab: return "L,C,h";
        case Family::oklab: return "L,a,b";
        case Family::oklch: return "L,C,h";
        case Family::rgb_linear:
        case Family::rgb_encoded: return "R,G,B";
    }
    return "";
}

/// The conversion of one triple through XYZ relative to the reference white.
class Converter {
public:
    Converter(const Space& from, const Space& to, const Xy& white, ChromaticAdaptation cat)
        : m_from(from),
          m_to(to),
          m_white_xy(white),
          m_white(xy_to_xyz(white)),
          m_from_native(adaptation_from(native_white(from), cat)),
          m_to_native(adaptation_to(native_white(to), cat)) {}

    [[nodiscard]] Vec3 operator()(const Vec3& in) const { return from_xyz(to_xyz(in)); }

private:
    /// The white a space's XYZ is relative to, when it has one of its own.
    static std::optional<Xy> native_white(const Space& s) {
        if (s.family == Family::oklab || s.family == Family::oklch) return oklab_white;
        if (s.rgb != nullptr) return s.rgb->white();
        return std::nullopt;
    }
    bool is_reference(const Xy& w) const { return w.x == m_white_xy.x && w.y == m_white_xy.y; }
    /// XYZ under a space's native white → XYZ under the reference white (identity when equal).
    Mat3 adaptation_from(const std::optional<Xy>& native, ChromaticAdaptation cat) const {
        if (!native || is_reference(*native)) return Mat3::identity();
        return adaptation_matrix(xy_to_xyz(*native), m_white, cat);
    }
    Mat3 adaptation_to(const std::optional<Xy>& native, ChromaticAdaptation cat) const {
        if (!native || is_reference(*native)) return Mat3::identity();
        return adaptation_matrix(m_white, xy_to_xyz(*native), cat);
    }
    /// XYZ → XYZ by an adaptation matrix.
    static Xyz apply(const Mat3& m, const Xyz& c) {
        const Vec3 v = m * Vec3{c.X, c.Y, c.Z};
        return {v[0], v[1], v[2]};
    }

    Xyz to_xyz(const Vec3& v) const {
        switch (m_from.family) {
            case Family::xyz: return {v[0], v[1], v[2]};
            case Family::xyy:
                if (v[1] == 0.0 && v[2] != 0.0) {
                    throw Error("chromaticity y = 0 with luminance Y = " + format_shortest(v[2]) +
                                " has no XYZ (only black may have y = 0)");
                }
                return xyy_to_xyz({v[0], v[1], v[2]});
            case Family::luv: return luv_to_xyz({v[0], v[1], v[2]}, m_white);
            case Family::lab: return lab_to_xyz({v[0], v[1], v[2]}, m_white);
            case Family::lchuv: return luv_to_xyz(lch_to_luv({v[0], v[1], v[2]}), m_white);
            case Family::lchab: return lab_to_xyz(lch_to_lab({v[0], v[1], v[2]}), m_white);
            case Family::oklab: return apply(m_from_native, oklab_to_xyz({v[0], v[1], v[2]}));
            case Family::oklch:
                return apply(m_from_native, oklab_to_xyz(oklch_to_oklab({v[0], v[1], v[2]})));
            case Family::rgb_linear:
                return apply(m_from_native, m_from.rgb->to_xyz({v[0], v[1], v[2]}));
            case Family::rgb_encoded:
                return apply(m_from_native, m_from.rgb->to_xyz(m_from.rgb->decode({v[0], v[1], v[2]})));
        }
        return {};
    }

    Vec3 from_xyz(const Xyz& c) const {
        switch (m_to.family) {
            case Family::xyz: return {c.X, c.Y, c.Z};
            case Family::xyy: {
                const Xyy r = xyz_to_xyy(c, m_white_xy);
                return {r.x, r.y, r.Y};
            }
            case Family::luv: {
                const Luv r = xyz_to_luv(c, m_white);
                return {r.L, r.u, r.v};
            }
            case Family::lab: {
                const Lab r = xyz_to_lab(c, m_white);
                return {r.L, r.a, r.b};
            }
            case Family::lchuv: {
                const LchUv r = luv_to_lch(xyz_to_luv(c, m_white));
                return {r.L, r.C, r.h};
            }
            case Family::lchab: {
                const LchAb r = lab_to_lch(xyz_to_lab(c, m_white));
                return {r.L, r.C, r.h};
            }
            case Family::oklab: {
                const Oklab r = xyz_to_oklab(apply(m_to_native, c));
                return {r.L, r.a, r.b};
            }
            case Family::oklch: {
                const Oklch r = oklab_to_oklch(xyz_to_oklab(apply(m_to_native, c)));
                return {r.L, r.C, r.h};
            }
            case Family::rgb_linear: {
                const Rgb r = m_to.rgb->from_xyz(apply(m_to_native, c));
                return {r.r, r.g, r.b};
            }
            case Family::rgb_encoded: {
                const Rgb r = m_to.rgb->encode(m_to.rgb->from_xyz(apply(m_to_native, c)));
                return {r.r, r.g, r.b};
            }
        }
        return {};
    }

    /// Oklab is defined on XYZ relative to D65 (Ottosson 2020).
    static constexpr Xy oklab_white{0.3127, 0.3290};

    Space m_from;
    Space m_to;
    Xy m_white_xy;
    Xyz m_white;
    Mat3 m_from_native;
    Mat3 m_to_native;
};

struct ConvertOptions {
    std::string from;
    std::string to;
    std::string white = "D65";
    std::string adaptation = "bradford";
};

int run_convert(const ConvertOptions& o) {
    const Space from = parse_space(o.from, "--from");
    const Space to = parse_space(o.to, "--to");
    Xy white;
    ChromaticAdaptation cat{};
    try {
        white = white_point_xy(o.white);
        cat = parse_chromatic_adaptation(o.adaptation);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    const Converter convert(from, to, white, cat);

    const NumericTable table = read_stdin_table(3);
    std::string out = std::string(header_of(to)) + "\n";
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
        const auto& row = table.rows[r];
        Vec3 result{};
        try {
            result = convert({row[0], row[1], row[2]});
        } catch (const Error& e) {
            throw Error("<stdin>:" + std::to_string(table.line_numbers[r]) + ": " + e.what());
        }
        for (int i = 0; i < 3; ++i) {
            if (!std::isfinite(result[i])) {
                throw Error("<stdin>:" + std::to_string(table.line_numbers[r]) + ": the colour (" +
                            format_shortest(row[0]) + ", " + format_shortest(row[1]) + ", " +
                            format_shortest(row[2]) + ") has no finite value in " + o.to);
            }
        }
        append_csv_line(out, result);
    }
    write_stdout(out);
    return exit_success;
}

}  // namespace

void add_convert_command(CLI::App& app, Runner& runner) {
    auto options = std::make_shared<ConvertOptions>();
    CLI::App* cmd = app.add_subcommand(
        "convert", "Convert colours (CSV triples on stdin) from one colour space to another");
    cmd->add_option("--from", options->from, "Source space: " + join(space_names()))->required();
    cmd->add_option("--to", options->to, "Destination space (same names)")->required();
    cmd->add_option("--white", options->white,
                    "Reference white of XYZ, CIELUV and CIELAB: " + join(white_point_names()) +
                        " or x,y")
        ->capture_default_str();
    cmd->add_option("--adaptation", options->adaptation,
                    "Chromatic adaptation where whites differ: bradford, cat02, von-kries, none")
        ->capture_default_str();
    cmd->callback([options, &runner] { runner = [options] { return run_convert(*options); }; });
}

}  // namespace irid::cli
