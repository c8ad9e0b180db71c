// The built-in ACES 2.0 displays and the chain around the rendering (aces2_display.h).

#include <irid/color/illuminant.h>
#include <irid/color/numeric_table.h>
#include <irid/color/observer.h>
#include <irid/error.h>
#include <irid/gamut/aces2_display.h>
#include <irid/text_input.h>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>

namespace irid {
namespace {

// Primaries: ITU-R BT.709-6, SMPTE EG 432-1 (P3), ITU-R BT.2020-2; whites D65 (d65_xy) and the
// ACES white "D60" (SMPTE ST 2065-1).
constexpr RgbPrimaries rec709{{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
constexpr RgbPrimaries p3{{0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}};
constexpr RgbPrimaries rec2020{{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}};
constexpr Xy d60{0.32168, 0.33767};
constexpr RgbPrimaries ap0{{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}};
constexpr RgbPrimaries ap1{{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}};

/// The cinema presets render for a peak 1/0.48 times the nominal and scale by 0.48
/// (OpenColorIO: 108 cd/m² renders for 225, 300 for 625).
constexpr double cinema_scale = 0.48;

Aces2DisplaySpec display(std::string name, double peak, RgbPrimaries lim, Xy lim_white, RgbPrimaries enc,
                         Xy enc_white, double scale = 1.0) {
    return {std::move(name), peak, lim, lim_white, enc, enc_white, false, scale, true};
}

std::vector<Aces2DisplaySpec> build_displays() {
    std::vector<Aces2DisplaySpec> d;
    d.push_back(display("sdr-100nit-rec709", 100, rec709, d65_xy, rec709, d65_xy));
    d.push_back(display("sdr-100nit-p3-d65", 100, p3, d65_xy, p3, d65_xy));
    d.push_back(display("hdr-108nit-p3-d65", 225, p3, d65_xy, p3, d65_xy, cinema_scale));
    d.push_back(display("hdr-300nit-p3-d65", 625, p3, d65_xy, p3, d65_xy, cinema_scale));
    for (int peak : {500, 1000, 2000, 4000})
        d.push_back(display(fmt::format("hdr-{}nit-p3-d65", peak), peak, p3, d65_xy, p3, d65_xy));
    for (int peak : {500, 1000, 2000, 4000})
        d.push_back(display(fmt::format("hdr-{}nit-rec2020", peak), peak, rec2020, d65_xy, rec2020, d65_xy));
    d.push_back(display("sdr-100nit-rec709-d60-in-rec709-d65", 100, rec709, d60, rec709, d65_xy));
    d.push_back(display("sdr-100nit-rec709-d60-in-p3-d65", 100, rec709, d60, p3, d65_xy));
    d.push_back(display("sdr-100nit-rec709-d60-in-rec2020-d65", 100, rec709, d60, rec2020, d65_xy));
    d.push_back(display("sdr-100nit-p3-d60-in-p3-d65", 100, p3, d60, p3, d65_xy));
    Aces2DisplaySpec xyz_sdr = display("sdr-100nit-p3-d60-in-xyz-e", 100, p3, d60, {}, {});
    xyz_sdr.encoding_xyz = true;
    xyz_sdr.scale_white = false;  // as OpenColorIO's built-in (its published values hold it)
    d.push_back(xyz_sdr);
    d.push_back(display("hdr-108nit-p3-d60-in-p3-d65", 225, p3, d60, p3, d65_xy, cinema_scale));
    Aces2DisplaySpec xyz_300 = display("hdr-300nit-p3-d60-in-xyz-e", 625, p3, d60, {}, {}, cinema_scale);
    xyz_300.encoding_xyz = true;
    d.push_back(xyz_300);
    for (int peak : {500, 1000, 2000, 4000})
        d.push_back(display(fmt::format("hdr-{}nit-p3-d60-in-p3-d65", peak), peak, p3, d60, p3, d65_xy));
    for (int peak : {500, 1000, 2000, 4000})
        d.push_back(display(fmt::format("hdr-{}nit-p3-d60-in-rec2020-d65", peak), peak, p3, d60, rec2020, d65_xy));
    for (int peak : {500, 1000, 2000, 4000})
        d.push_back(
            display(fmt::format("hdr-{}nit-rec2020-d60-in-rec2020-d65", peak), peak, rec2020, d60, rec2020, d65_xy));
    return d;
}

constexpr std::string_view ocio_prefix = "aces-output - aces2065-1_to_cie-xyz-d65 - ";
constexpr std::string_view ocio_suffix = "_2.0";
constexpr std::string_view custom_prefix = "custom:";
constexpr std::string_view custom_form = aces2_custom_form;

const RgbSpace& custom_space(std::string_view value, const char* key) {
    if (const RgbSpace* s = find_rgb_space(value)) return *s;
    std::vector<std::string> valid = rgb_space_names();
    throw UnknownNameError(fmt::format("custom display: unknown {} space {}; valid: {}", key,
                                       quote_untrusted(value, 40), fmt::join(valid, ", ")),
                           valid);
}

/// A number of the custom form, or nothing.
std::optional<double> custom_number(std::string_view value) {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (value.empty() || ec != std::errc() || end != value.data() + value.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

/// The limiting white: a white point's name, "aces", or its chromaticity as x,y or x:y.
Xy custom_white(std::string_view value) {
    if (value == "aces") return d60;
    const std::size_t split = value.find_first_of(",:");
    const std::string text(value);
    try {
        if (split != std::string_view::npos) {
            const std::optional<double> x = custom_number(value.substr(0, split));
            const std::optional<double> y = custom_number(value.substr(split + 1));
            if (x && y) {
                const Xy xy{*x, *y};
                check_white_chromaticity(xy, "white point " + quote_untrusted(value, 40));
                return xy;
            }
        } else if (!custom_number(value)) {
            return white_point_xy(text);
        }
    } catch (const UnknownNameError&) {
    } catch (const Error& e) {
        throw Error(std::string("custom display: white: ") + e.what());
    }
    throw Error(fmt::format("custom display: white {}: give a white point's name ({}), aces (the ACES white), or "
                            "the chromaticity as x,y or x:y; e.g. white=D65, white=aces, white=0.3127,0.329 or "
                            "white=0.3127:0.329",
                            quote_untrusted(value, 40), fmt::join(white_point_names(), ", ")));
}

/// The custom form (see aces2_display), lower case without its prefix.
Aces2DisplaySpec parse_custom(std::string_view name, std::string_view body) {
    std::optional<double> peak;
    const RgbSpace* limiting = nullptr;
    const RgbSpace* encoding = nullptr;
    bool encoding_xyz = false;
    std::optional<Xy> white;
    double linear_scale = 1.0;
    bool scale_white = true;
    // The items between commas, each a view into `body` (a final comma ends with an empty one).
    std::vector<std::string_view> items;
    for (std::size_t start = 0; !body.empty();) {
        const std::size_t comma = body.find(',', start);
        items.push_back(body.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    std::vector<std::string_view> seen;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const std::string_view item = items[i];
        const std::size_t eq = item.find('=');
        if (eq == std::string_view::npos || eq == 0) {
            throw Error(fmt::format("custom display {}: {} is not key=value; the form is {}", quote_untrusted(name, 80),
                                    quote_untrusted(item, 40), custom_form));
        }
        const std::string_view key = item.substr(0, eq);
        std::string_view value = item.substr(eq + 1);
        if (std::find(seen.begin(), seen.end(), key) != seen.end())
            throw Error(fmt::format("custom display: {} is given twice", quote_untrusted(key, 20)));
        seen.push_back(key);
        if (key == "peak") {
            const std::optional<double> v = custom_number(value);
            if (!v) throw Error(fmt::format("custom display: peak {} is not a number", quote_untrusted(value, 40)));
            peak = *v;
        } else if (key == "limiting") {
            limiting = &custom_space(value, "limiting");
        } else if (key == "encoding") {
            if (value == "xyz") {
                encoding_xyz = true;
            } else {
                encoding = &custom_space(value, "encoding");
            }
        } else if (key == "white") {
            // white=x,y: the ',' that separates keys also separates x from y. A number followed
            // by an item without '=' is unambiguous: that item is y.
            if (custom_number(value) && i + 1 < items.size() && items[i + 1].find('=') == std::string_view::npos) {
                value = std::string_view(value.data(), static_cast<std::size_t>(items[i + 1].data() - value.data()) +
                                                           items[i + 1].size());
                ++i;
            }
            white = custom_white(value);
        } else if (key == "linear-scale") {
            const std::optional<double> v = custom_number(value);
            if (!v || !(*v > 0.0 && *v <= 1.0))
                throw Error(fmt::format("custom display: linear-scale {} must be a number in (0, 1]",
                                        quote_untrusted(value, 40)));
            linear_scale = *v;
        } else if (key == "scale-white") {
            if (value != "yes" && value != "no")
                throw Error(fmt::format("custom display: scale-white {}: give yes or no", quote_untrusted(value, 20)));
            scale_white = value == "yes";
        } else {
            throw Error(fmt::format("custom display: unknown key {}; the form is {}", quote_untrusted(key, 20),
                                    custom_form));
        }
    }
    if (!peak || limiting == nullptr) {
        const char* missing = !peak && limiting == nullptr ? "peak= and limiting=" : !peak ? "peak=" : "limiting=";
        throw Error(fmt::format("custom display {} has no {}; the form is {}", quote_untrusted(name, 80), missing,
                                custom_form));
    }
    if (encoding == nullptr && !encoding_xyz) encoding = limiting;
    return custom_aces2_display(*peak, *limiting, white.value_or(limiting->white()), encoding, linear_scale,
                                scale_white);
}

}  // namespace

Aces2DisplaySpec custom_aces2_display(double peak_nits, const RgbSpace& limiting, const Xy& limiting_white,
                                      const RgbSpace* encoding, double linear_scale, bool scale_white) {
    if (!(peak_nits >= 100.0 && peak_nits <= 10000.0)) {
        throw Error(fmt::format("custom display: peak {} cd/m² is outside 100 to 10000, the ACES 2.0 "
                                "rendering's range",
                                format_shortest(peak_nits)));
    }
    if (!(linear_scale > 0.0 && linear_scale <= 1.0))
        throw Error(fmt::format("custom display: linear-scale {} must be in (0, 1]", format_shortest(linear_scale)));
    (void)rgb_to_xyz_matrix(limiting.primaries(), limiting_white);  // the white inside the primaries
    Aces2DisplaySpec d;
    d.name = fmt::format("custom:peak={},limiting={}", format_shortest(peak_nits), limiting.name());
    if (limiting_white.x != limiting.white().x || limiting_white.y != limiting.white().y)
        d.name += fmt::format(",white={}:{}", format_shortest(limiting_white.x), format_shortest(limiting_white.y));
    d.name += ",encoding=" + (encoding != nullptr ? encoding->name() : std::string("xyz"));
    if (linear_scale != 1.0) d.name += ",linear-scale=" + format_shortest(linear_scale);
    if (!scale_white) d.name += ",scale-white=no";
    d.linear_scale = linear_scale;
    d.scale_white = scale_white;
    d.peak_nits = peak_nits;
    d.limiting = limiting.primaries();
    d.limiting_white = limiting_white;
    if (encoding != nullptr) {
        d.encoding = encoding->primaries();
        d.encoding_white = encoding->white();
    } else {
        d.encoding_xyz = true;
    }
    return d;
}

std::span<const Aces2DisplaySpec> aces2_displays() {
    static const std::vector<Aces2DisplaySpec> displays = build_displays();
    return displays;
}

const RgbSpace* default_display_encoding(const Aces2DisplaySpec& spec) noexcept {
    if (spec.encoding_xyz) return nullptr;
    const auto same = [&](const RgbSpace& s) {
        const auto near = [](const Xy& a, const Xy& b) { return std::abs(a.x - b.x) < 1e-4 && std::abs(a.y - b.y) < 1e-4; };
        return near(spec.encoding.red, s.primaries().red) && near(spec.encoding.green, s.primaries().green) &&
               near(spec.encoding.blue, s.primaries().blue) && near(spec.encoding_white, s.white());
    };
    const bool hdr = spec.peak_nits * spec.linear_scale > 100.0;
    if (hdr) {
        if (same(p3_d65_pq())) return &p3_d65_pq();
        // BT.2100's container holds any D65 gamut inside BT.2020's triangle (Rec.709 too).
        const RgbSpace& bt2100 = rec2100_pq();
        const auto inside = [&](const Xy& c) {
            const Mat3& to_rgb = bt2100.from_xyz_matrix();
            const Vec3 rgb = to_rgb * Vec3{c.x / c.y, 1.0, (1.0 - c.x - c.y) / c.y};
            return rgb[0] >= -1e-9 && rgb[1] >= -1e-9 && rgb[2] >= -1e-9;
        };
        const bool d65 = std::abs(spec.encoding_white.x - d65_xy.x) < 1e-4 &&
                         std::abs(spec.encoding_white.y - d65_xy.y) < 1e-4;
        if (d65 && inside(spec.encoding.red) && inside(spec.encoding.green) && inside(spec.encoding.blue))
            return &bt2100;
        return nullptr;
    }
    for (const RgbSpace* s : {&srgb(), &display_p3(), &rec1886_rec2020()})
        if (same(*s)) return s;
    for (const RgbSpace* s : builtin_rgb_spaces())
        if (same(*s)) return s;
    return nullptr;
}

Aces2DisplaySpec aces2_display(std::string_view name) {
    std::string key = ascii_lower(name);
    if (key.starts_with(custom_prefix)) return parse_custom(name, std::string_view(key).substr(custom_prefix.size()));
    if (key.starts_with(ocio_prefix) && key.ends_with(ocio_suffix))
        key = key.substr(ocio_prefix.size(), key.size() - ocio_prefix.size() - ocio_suffix.size());
    for (const Aces2DisplaySpec& d : aces2_displays())
        if (d.name == key) return d;
    std::vector<std::string> names;
    for (const Aces2DisplaySpec& d : aces2_displays()) names.push_back(d.name);
    const std::string message =
        fmt::format("unknown ACES 2.0 display {}; known: {}", quote_untrusted(name, 80), fmt::join(names, ", "));
    throw UnknownNameError(message, std::move(names));
}

Aces2Output::Aces2Output(const Aces2DisplaySpec& spec)
    : m_spec(spec), m_rendering(Aces2Display{spec.peak_nits, spec.limiting, spec.limiting_white}) {
    const Mat3 ap0_to_xyz = rgb_to_xyz_matrix(ap0, d60);
    const Mat3 ap1_to_xyz = rgb_to_xyz_matrix(ap1, d60);
    m_ap0_to_ap1 = irid::inverse(ap1_to_xyz, "AP1") * ap0_to_xyz;
    m_ap1_to_ap0 = irid::inverse(m_ap0_to_ap1, "AP0 to AP1");
    m_limiting_to_xyz = rgb_to_xyz_matrix(spec.limiting, spec.limiting_white);
    m_xyz_to_limiting = irid::inverse(m_limiting_to_xyz, "limiting primaries");
    double white_scale = 1.0;
    if (spec.scale_white) {
        // The limiting white in the encoding's RGB; its largest channel brought to 1
        // (aces-core Lib.Academy.DisplayEncoding, apply_white_scale).
        const Mat3 xyz_to_encoding = spec.encoding_xyz ? Mat3::identity()
                                                       : irid::inverse(rgb_to_xyz_matrix(spec.encoding, spec.encoding_white),
                                                                 "encoding primaries");
        const Vec3 w = xyz_to_encoding * (m_limiting_to_xyz * Vec3{1.0, 1.0, 1.0});
        white_scale = 1.0 / std::max({w[0], w[1], w[2]});
    }
    m_scale = white_scale * spec.linear_scale;
}

Xyz Aces2Output::forward(const Vec3& aces) const noexcept {
    Vec3 ap1 = m_ap0_to_ap1 * Vec3{aces2_finite_input(aces[0]), aces2_finite_input(aces[1]), aces2_finite_input(aces[2])};
    const double limit = m_rendering.forward_limit();
    for (double& v : ap1) v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, limit);
    Vec3 rgb = m_rendering.forward(m_ap1_to_ap0 * ap1);
    const double peak = m_spec.peak_nits / 100.0;
    for (double& v : rgb) v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, peak);
    const Vec3 xyz = m_limiting_to_xyz * rgb;
    return {xyz[0] * m_scale, xyz[1] * m_scale, xyz[2] * m_scale};
}

Vec3 Aces2Output::inverse(const Xyz& xyz) const noexcept {
    Vec3 rgb = m_xyz_to_limiting * Vec3{aces2_finite_input(xyz.X) / m_scale, aces2_finite_input(xyz.Y) / m_scale,
                                        aces2_finite_input(xyz.Z) / m_scale};
    const double peak = m_spec.peak_nits / 100.0;
    for (double& v : rgb) v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, peak);
    Vec3 ap1 = m_ap0_to_ap1 * m_rendering.inverse(rgb);
    const double limit = m_rendering.forward_limit();
    for (double& v : ap1) v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, limit);
    return m_ap1_to_ap0 * ap1;
}

double Aces2Output::inverse_miss(const Xyz& xyz) const noexcept {
    const Vec3 rgb = m_xyz_to_limiting * Vec3{xyz.X / m_scale, xyz.Y / m_scale, xyz.Z / m_scale};
    const Xyz x = forward(inverse(xyz));
    const Vec3 back = m_xyz_to_limiting * Vec3{x.X / m_scale, x.Y / m_scale, x.Z / m_scale};
    double miss = 0.0;
    for (int c = 0; c < 3; ++c) miss = std::max(miss, std::abs(back[c] - rgb[c]));
    return miss / (m_spec.peak_nits / 100.0);
}

bool Aces2Output::has_scene_value(const Xyz& xyz, double tolerance) const noexcept {
    const Vec3 rgb = m_xyz_to_limiting * Vec3{xyz.X / m_scale, xyz.Y / m_scale, xyz.Z / m_scale};
    const double peak = m_spec.peak_nits / 100.0;
    bool exact = true;
    // Inside the cube, but for the rounding of the matrix (1e-12 of the peak), which the clamp
    // moves by as little.
    for (const double v : rgb) exact = exact && v >= -1e-12 * peak && v <= peak * (1.0 + 1e-12);
    if (exact) exact = m_rendering.reaches(rgb);
    if (exact) {
        // Its source inside the AP1 clamp, but for the rounding of a source on its boundary
        // (1e-12 of the source's largest channel), which the clamp moves by as little.
        const Vec3 ap1 = m_ap0_to_ap1 * m_rendering.inverse(rgb);
        const double limit = m_rendering.forward_limit();
        const double slack = 1e-12 * std::max({1.0, std::abs(ap1[0]), std::abs(ap1[1]), std::abs(ap1[2])});
        for (const double v : ap1) exact = exact && v >= -slack && v <= limit + slack;
    }
    if (exact) return true;
    // Not quite a value the chain gives: within `tolerance` of one?
    return tolerance > 0.0 && inverse_miss(xyz) <= tolerance;
}

}  // namespace irid
