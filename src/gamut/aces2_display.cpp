// The built-in ACES 2.0 displays and the chain around the rendering (aces2_display.h).

#include <irid/error.h>
#include <irid/gamut/aces2_display.h>
#include <irid/text_input.h>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>

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

}  // namespace

std::span<const Aces2DisplaySpec> aces2_displays() {
    static const std::vector<Aces2DisplaySpec> displays = build_displays();
    return displays;
}

const Aces2DisplaySpec& aces2_display(std::string_view name) {
    std::string key = ascii_lower(name);
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
    Vec3 ap1 = m_ap0_to_ap1 * aces;
    const double limit = m_rendering.forward_limit();
    for (double& v : ap1) v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, limit);
    Vec3 rgb = m_rendering.forward(m_ap1_to_ap0 * ap1);
    const double peak = m_spec.peak_nits / 100.0;
    for (double& v : rgb) v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, peak);
    const Vec3 xyz = m_limiting_to_xyz * rgb;
    return {xyz[0] * m_scale, xyz[1] * m_scale, xyz[2] * m_scale};
}

Vec3 Aces2Output::inverse(const Xyz& xyz) const noexcept {
    Vec3 rgb = m_xyz_to_limiting * Vec3{xyz.X / m_scale, xyz.Y / m_scale, xyz.Z / m_scale};
    const double peak = m_spec.peak_nits / 100.0;
    for (double& v : rgb) v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, peak);
    Vec3 ap1 = m_ap0_to_ap1 * m_rendering.inverse(rgb);
    const double limit = m_rendering.forward_limit();
    for (double& v : ap1) v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, limit);
    return m_ap1_to_ap0 * ap1;
}

}  // namespace irid
