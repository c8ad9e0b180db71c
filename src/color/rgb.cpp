#include <irid/color/hdr_transfer.h>
#include <irid/color/numeric_table.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

namespace irid {
namespace {

// IEC 61966-2-1:1999 §4.2 (sRGB). The standard switches the decoding at 0.04045; irid switches
// at the encoding's own switch point 12.92 × 0.0031308 = 0.040449936, so decoding is the exact
// inverse of encoding (the two differ by < 3e-9 in the sliver between).
constexpr double srgb_linear_limit = 0.0031308;
constexpr double srgb_encoded_limit = 12.92 * srgb_linear_limit;
// ITU-R BT.709-6 Item 1.2 (also BT.601, SMPTE 170M). With these rounded constants the two
// pieces miss each other by 2e-7 at β, so values within 4e-5 of β round-trip to ~1e-7 only.
constexpr double rec709_alpha = 1.099;
constexpr double rec709_beta = 0.018;
// ITU-R BT.2020-2 Table 4: α and β to the precision that makes the two pieces meet (the
// standard rounds them to 1.099/0.018 for 10-bit and 1.0993/0.0181 for 12-bit systems).
constexpr double rec2020_alpha = 1.09929682680944;
constexpr double rec2020_beta = 0.018053968510807;

// ACEScct, Academy S-2016-001 §4.4: the break X_BRK = 0.0078125 (2^-7), its code value
// Y_BRK = 0.155251141552511, the toe's slope A = 10.5402377416545 and offset B =
// 0.0729055341958355, and the log piece (log2 v + 9.72) / 17.52.
constexpr double acescct_x_break = 0.0078125;
constexpr double acescct_y_break = 0.155251141552511;
constexpr double acescct_a = 10.5402377416545;
constexpr double acescct_b = 0.0729055341958355;

double acescct_encode(double v) noexcept {
    if (v <= acescct_x_break) return acescct_a * v + acescct_b;
    return (std::log2(v) + 9.72) / 17.52;
}

double acescct_decode(double e) noexcept {
    if (e <= acescct_y_break) return (e - acescct_b) / acescct_a;
    return std::exp2(e * 17.52 - 9.72);
}

/// The BT.709-style curve: slope 4.5 below beta, alpha v^0.45 - (alpha - 1) above.
double camera_encode(double v, double alpha, double beta) noexcept {
    return v < beta ? 4.5 * v : alpha * std::pow(v, 0.45) - (alpha - 1.0);
}
double camera_decode(double e, double alpha, double beta) noexcept {
    return e < 4.5 * beta ? e / 4.5 : std::pow((e + (alpha - 1.0)) / alpha, 1.0 / 0.45);
}

/// Primaries may be imaginary (ACES AP0's blue has y < 0) but need y ≠ 0 to have an XYZ; the
/// white must be a real colour, y > 0.
void check_chromaticity(const Xy& c, const char* what, bool must_be_real) {
    const bool ok = std::isfinite(c.x) && std::isfinite(c.y) && (must_be_real ? c.y > 0.0 : c.y != 0.0);
    if (!ok) {
        throw Error(std::string(what) + " chromaticity (" + format_shortest(c.x) + ", " +
                    format_shortest(c.y) + ") must be finite with " +
                    (must_be_real ? "y > 0" : "y != 0"));
    }
}

}  // namespace

TransferFunction::TransferFunction(Kind kind, double gamma) : m_kind(kind), m_gamma(gamma) {
    if (kind == Kind::gamma && !(gamma > 0.0 && gamma <= 10.0)) {
        throw Error("transfer function: gamma " + format_shortest(gamma) + " must be in (0, 10]");
    }
    if (kind == Kind::parametric || kind == Kind::sampled) {
        throw Error("transfer function: a parametric or sampled curve is built with "
                    "TransferFunction::parametric or TransferFunction::sampled");
    }
}

TransferFunction::TransferFunction(Kind kind, const Parameters& params,
                                   std::shared_ptr<const std::vector<double>> samples)
    : m_kind(kind), m_gamma(kind == Kind::parametric ? params[0] : 1.0), m_params(params),
      m_samples(std::move(samples)) {}

TransferFunction TransferFunction::parametric(int function_type, std::span<const double> p) {
    if (function_type < 0 || function_type > 4) {
        throw Error("parametric curve: function type " + std::to_string(function_type) +
                    " is not one of ICC.1's 0 to 4");
    }
    const std::size_t count = parametric_counts[static_cast<std::size_t>(function_type)];
    if (p.size() != count) {
        throw Error("parametric curve: function type " + std::to_string(function_type) + " takes " +
                    std::to_string(count) + " parameters, not " + std::to_string(p.size()));
    }
    for (const double v : p) {
        if (!std::isfinite(v)) throw Error("parametric curve: a parameter is not finite");
    }
    const double g = p[0];
    // The general form (g, a, b, c, d, e, f) of each type.
    Parameters q{g, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    if (function_type >= 1) {
        q[1] = p[1];
        q[2] = p[2];
        if (!(p[1] > 0.0)) {
            throw Error("parametric curve: a = " + format_shortest(p[1]) +
                        " must be > 0 (the curve must rise)");
        }
    }
    switch (function_type) {
        case 1: q[4] = -p[2] / p[1]; break;
        case 2: q[4] = -p[2] / p[1], q[5] = p[3], q[6] = p[3]; break;
        case 3: q[3] = p[3], q[4] = p[4]; break;
        case 4: q[3] = p[3], q[4] = p[4], q[5] = p[5], q[6] = p[6]; break;
        default: break;
    }
    if (!(g > 0.0 && g <= 10.0)) {
        throw Error("parametric curve: g = " + format_shortest(g) + " must be in (0, 10]");
    }
    if (q[3] < 0.0) {
        throw Error("parametric curve: c = " + format_shortest(q[3]) +
                    " must be >= 0 (the curve must not fall)");
    }
    // Where the pieces meet (d in [0, 1]), the upper one must not start below the lower one by
    // more than the rounding of published constants leaves (BT.709's pieces miss by 5.5e-5, the
    // L* curves of eciRGB by 6e-7).
    if (q[4] > 0.0 && q[4] <= 1.0) {
        const double lower = q[3] * q[4] + q[6];
        const double upper = std::pow(std::max(0.0, q[1] * q[4] + q[2]), g) + q[5];
        if (upper < lower - 1e-3) {
            throw Error("parametric curve: it falls at d = " + format_shortest(q[4]) + " (from " +
                        format_shortest(lower) + " to " + format_shortest(upper) +
                        "); a decoding must not fall");
        }
    }
    return TransferFunction(Kind::parametric, q, nullptr);
}

TransferFunction TransferFunction::sampled(std::vector<double> linear) {
    if (linear.size() < 2 || linear.size() > 65536) {
        throw Error("sampled curve: " + std::to_string(linear.size()) +
                    " samples; a sampled curve has 2 to 65536");
    }
    for (std::size_t i = 0; i < linear.size(); ++i) {
        if (!std::isfinite(linear[i])) {
            throw Error("sampled curve: sample " + std::to_string(i) + " is not finite");
        }
        if (i > 0 && linear[i] < linear[i - 1]) {
            throw Error("sampled curve: sample " + std::to_string(i) + " (" +
                        format_shortest(linear[i]) + ") is below the one before it (" +
                        format_shortest(linear[i - 1]) + "); a decoding must not fall");
        }
    }
    if (!(linear.back() > linear.front())) {
        throw Error("sampled curve: the samples do not rise (every one is " +
                    format_shortest(linear.front()) + ")");
    }
    return TransferFunction(Kind::sampled, Parameters{},
                            std::make_shared<const std::vector<double>>(std::move(linear)));
}

std::optional<TransferFunction::Parameters> TransferFunction::parameters() const noexcept {
    const auto camera = [](double alpha, double beta) {
        return Parameters{1.0 / 0.45, 1.0 / alpha, (alpha - 1.0) / alpha, 1.0 / 4.5, 4.5 * beta,
                          0.0, 0.0};
    };
    switch (m_kind) {
        case Kind::linear: return Parameters{1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        case Kind::srgb:
            return Parameters{2.4, 1.0 / 1.055, 0.055 / 1.055, 1.0 / 12.92, srgb_encoded_limit, 0.0, 0.0};
        case Kind::rec709: return camera(rec709_alpha, rec709_beta);
        case Kind::rec2020: return camera(rec2020_alpha, rec2020_beta);
        case Kind::gamma: return Parameters{m_gamma, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        case Kind::parametric: return m_params;
        case Kind::sampled:
        case Kind::pq:
        case Kind::hlg:
        case Kind::acescct: return std::nullopt;
    }
    return std::nullopt;
}

std::span<const double> TransferFunction::samples() const noexcept {
    if (!m_samples) return {};
    return *m_samples;
}

double TransferFunction::max_difference(const TransferFunction& other) const noexcept {
    double worst = 0.0;
    for (int i = 0; i <= 1023; ++i) {
        const double e = i / 1023.0;
        worst = std::max(worst, std::abs(decode(e) - other.decode(e)));
    }
    return worst;
}

double TransferFunction::decode_magnitude(double e) const noexcept {
    if (m_kind == Kind::parametric) {
        const auto& [g, a, b, c, d, oe, of] = m_params;
        return e >= d ? std::pow(std::max(0.0, a * e + b), g) + oe : c * e + of;
    }
    // Sampled: linear interpolation, the last segment extended beyond 1.
    const std::vector<double>& s = *m_samples;
    const double last = static_cast<double>(s.size() - 1);
    const double at = e * last;
    const std::size_t i = at >= last ? s.size() - 2 : static_cast<std::size_t>(at);
    const double t = at - static_cast<double>(i);
    return s[i] + (s[i + 1] - s[i]) * t;
}

double TransferFunction::encode_magnitude(double v) const noexcept {
    if (m_kind == Kind::parametric) {
        const auto& [g, a, b, c, d, oe, of] = m_params;
        const double at_d = std::pow(std::max(0.0, a * d + b), g) + oe;
        // The upper piece starts at d: rounding must not put its inverse below (where decoding
        // would take the other piece).
        if (v >= at_d) return std::max({0.0, d, (std::pow(std::max(0.0, v - oe), 1.0 / g) - b) / a});
        // Below the upper piece: the linear piece, or d where it is flat (or jumps past v).
        if (c <= 0.0) return std::max(0.0, d);
        return std::clamp((v - of) / c, 0.0, std::max(0.0, d));
    }
    const std::vector<double>& s = *m_samples;
    const double last = static_cast<double>(s.size() - 1);
    if (v <= s.front()) return 0.0;
    if (v >= s.back()) {
        const double slope = s[s.size() - 1] - s[s.size() - 2];
        return slope > 0.0 ? 1.0 + (v - s.back()) / slope / last : 1.0;
    }
    // The first segment that reaches v (the lowest encoded value of a flat run).
    const auto upper = std::lower_bound(s.begin(), s.end(), v);
    const auto i = static_cast<std::size_t>(upper - s.begin()) - 1;
    const double t = (v - s[i]) / (s[i + 1] - s[i]);
    return (static_cast<double>(i) + t) / last;
}

namespace {

/// Linear 1.0 is this many cd/m² for the PQ and HLG kinds (irid's display-light scale).
constexpr double pq_linear_nits = 100.0;

/// HLG on the neutral axis (R = G = B, where the OOTF's Y_S is E): display light [linear] to
/// signal and back, on the 1000 cd/m² display (BT.2100-2 Table 5).
double hlg_grey_encode(double linear) noexcept {
    const double nits = std::isnan(linear) ? 0.0 : linear * pq_linear_nits;
    return hlg_encode({nits, nits, nits}, hlg_nominal_peak_nits)[0];
}
double hlg_grey_decode(double signal) noexcept {
    return hlg_decode({signal, signal, signal}, hlg_nominal_peak_nits)[0] / pq_linear_nits;
}

}  // namespace

double TransferFunction::encode(double linear) const noexcept {
    const double v = std::abs(linear);
    double e = v;
    switch (m_kind) {
        case Kind::linear: return linear;
        case Kind::pq: return pq_encode(std::isnan(linear) ? 0.0 : linear * pq_linear_nits);
        case Kind::hlg: return hlg_grey_encode(linear);
        case Kind::acescct: return acescct_encode(linear);
        case Kind::parametric:
        case Kind::sampled:
            // Mirrored by the sign of the input (a curve may decode below 0: negative offsets);
            // NaN passes through.
            if (std::isnan(linear)) return linear;
            return linear < 0.0 ? -encode_magnitude(v) : encode_magnitude(v);
        default: break;
    }
    // Every built-in curve maps 1 to 1; the formulas' last bit does not (1.055 − 0.055 rounds
    // below 1).
    if (v == 1.0) return linear;
    switch (m_kind) {
        case Kind::srgb:
            e = v <= srgb_linear_limit ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
            break;
        case Kind::rec709: e = camera_encode(v, rec709_alpha, rec709_beta); break;
        case Kind::rec2020: e = camera_encode(v, rec2020_alpha, rec2020_beta); break;
        case Kind::gamma: e = std::pow(v, 1.0 / m_gamma); break;
        default: break;
    }
    return std::copysign(e, linear);
}

double TransferFunction::decode(double encoded) const noexcept {
    const double e = std::abs(encoded);
    double v = e;
    switch (m_kind) {
        case Kind::linear: return encoded;
        case Kind::pq: return pq_decode(encoded) / pq_linear_nits;
        case Kind::hlg: return hlg_grey_decode(encoded);
        case Kind::acescct: return acescct_decode(encoded);
        case Kind::parametric:
        case Kind::sampled:
            if (std::isnan(encoded)) return encoded;
            return encoded < 0.0 ? -decode_magnitude(e) : decode_magnitude(e);
        default: break;
    }
    switch (m_kind) {
        case Kind::srgb:
            v = e <= srgb_encoded_limit ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
            break;
        case Kind::rec709: v = camera_decode(e, rec709_alpha, rec709_beta); break;
        case Kind::rec2020: v = camera_decode(e, rec2020_alpha, rec2020_beta); break;
        case Kind::gamma: v = std::pow(e, m_gamma); break;
        default: break;
    }
    return std::copysign(v, encoded);
}

Mat3 rgb_to_xyz_matrix(const RgbPrimaries& p, const Xy& white) {
    check_chromaticity(p.red, "red primary", false);
    check_chromaticity(p.green, "green primary", false);
    check_chromaticity(p.blue, "blue primary", false);
    check_chromaticity(white, "white point", true);
    // Twice the signed areas of the primaries' triangle and of the three triangles the white
    // makes with two of them: the white is inside when all have the same sign.
    const auto area2 = [](const Xy& a, const Xy& b, const Xy& c) {
        return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    };
    const double whole = area2(p.red, p.green, p.blue);
    if (!(std::abs(whole) > 1e-6)) {
        throw Error("RGB primaries are (nearly) collinear in chromaticity; they span no gamut");
    }
    for (const double part : {area2(white, p.green, p.blue), area2(p.red, white, p.blue),
                              area2(p.red, p.green, white)}) {
        if (!(part / whole > 0.0)) {
            throw Error("white point (" + format_shortest(white.x) + ", " +
                        format_shortest(white.y) + ") must lie inside the triangle of the primaries");
        }
    }
    const Xyz r = xy_to_xyz(p.red);
    const Xyz g = xy_to_xyz(p.green);
    const Xyz b = xy_to_xyz(p.blue);
    const Mat3 primaries =
        Mat3::from_columns({r.X, r.Y, r.Z}, {g.X, g.Y, g.Z}, {b.X, b.Y, b.Z});
    const Xyz w = xy_to_xyz(white);
    const Vec3 scale = inverse(primaries, "primary matrix") * Vec3{w.X, w.Y, w.Z};
    return primaries * Mat3::diagonal(scale);
}

RgbSpace::RgbSpace(std::string name, const RgbPrimaries& primaries, const Xy& white,
                   TransferFunction transfer)
    : m_name(std::move(name)),
      m_primaries(primaries),
      m_white(white),
      m_white_xyz(xy_to_xyz(white)),
      m_transfer(transfer),
      m_to_xyz(rgb_to_xyz_matrix(primaries, white)),
      m_from_xyz(inverse(m_to_xyz, "RGB to XYZ matrix")) {}

Xyz RgbSpace::to_xyz(const Rgb& c) const noexcept {
    const Vec3 v = m_to_xyz * Vec3{c.r, c.g, c.b};
    return {v[0], v[1], v[2]};
}

Rgb RgbSpace::from_xyz(const Xyz& c) const noexcept {
    const Vec3 v = m_from_xyz * Vec3{c.X, c.Y, c.Z};
    return {v[0], v[1], v[2]};
}

Rgb RgbSpace::encode(const Rgb& c) const noexcept {
    if (m_transfer.kind() == TransferFunction::Kind::hlg) {
        const auto nits = [](double v) { return std::isnan(v) ? 0.0 : v * pq_linear_nits; };
        const std::array<double, 3> e = hlg_encode({nits(c.r), nits(c.g), nits(c.b)}, hlg_nominal_peak_nits);
        return {e[0], e[1], e[2]};
    }
    return {m_transfer.encode(c.r), m_transfer.encode(c.g), m_transfer.encode(c.b)};
}

Rgb RgbSpace::decode(const Rgb& c) const noexcept {
    if (m_transfer.kind() == TransferFunction::Kind::hlg) {
        const std::array<double, 3> d = hlg_decode({c.r, c.g, c.b}, hlg_nominal_peak_nits);
        return {d[0] / pq_linear_nits, d[1] / pq_linear_nits, d[2] / pq_linear_nits};
    }
    return {m_transfer.decode(c.r), m_transfer.decode(c.g), m_transfer.decode(c.b)};
}

namespace {

using Kind = TransferFunction::Kind;
/// Illuminant C as the FCC 1953 NTSC standard gives it.
constexpr Xy c_xy{0.310, 0.316};
/// The ACES white point (SMPTE ST 2065-1:2012 §4.1; Academy S-2008-001), near but not D60.
constexpr Xy aces_white_xy{0.32168, 0.33767};

}  // namespace

const RgbSpace& srgb() {
    // ITU-R BT.709-6 Item 1.3 primaries; IEC 61966-2-1:1999.
    static const RgbSpace space("srgb", {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}}, d65_xy,
                                TransferFunction(Kind::srgb));
    return space;
}

const RgbSpace& display_p3() {
    // SMPTE EG 432-1:2010 (P3 primaries) with a D65 white and the sRGB curve.
    static const RgbSpace space("display-p3", {{0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}},
                                d65_xy, TransferFunction(Kind::srgb));
    return space;
}

const RgbSpace& rec2020() {
    // ITU-R BT.2020-2 Table 3.
    static const RgbSpace space("rec2020", {{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}},
                                d65_xy, TransferFunction(Kind::rec2020));
    return space;
}

const RgbSpace& adobe_rgb() {
    // Adobe RGB (1998) Color Image Encoding, version 2005-05, §4.2-4.3: γ = 563/256.
    static const RgbSpace space("adobe-rgb", {{0.64, 0.33}, {0.21, 0.71}, {0.15, 0.06}}, d65_xy,
                                TransferFunction(Kind::gamma, 563.0 / 256.0));
    return space;
}

const RgbSpace& smpte_c() {
    // SMPTE RP 145-2004 primaries, SMPTE 170M-2004 transfer.
    static const RgbSpace space("smpte-c", {{0.630, 0.340}, {0.310, 0.595}, {0.155, 0.070}},
                                d65_xy, TransferFunction(Kind::rec709));
    return space;
}

const RgbSpace& ntsc1953() {
    // FCC 1953 (47 CFR §73.682) primaries and illuminant C; display gamma 2.2.
    static const RgbSpace space("ntsc1953", {{0.67, 0.33}, {0.21, 0.71}, {0.14, 0.08}}, c_xy,
                                TransferFunction(Kind::gamma, 2.2));
    return space;
}

const RgbSpace& aces2065_1() {
    // SMPTE ST 2065-1:2012 §4 (Academy S-2008-001): AP0 primaries, the ACES white; linear.
    static const RgbSpace space("aces2065-1", {{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}},
                                aces_white_xy, TransferFunction(Kind::linear));
    return space;
}

const RgbSpace& acescg() {
    // Academy S-2014-004 (ACEScg) §4.1: AP1 primaries, the ACES white; linear.
    static const RgbSpace space("acescg", {{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}},
                                aces_white_xy, TransferFunction(Kind::linear));
    return space;
}

const RgbSpace& rec1886() {
    // ITU-R BT.709-6 Item 1.3 primaries; ITU-R BT.1886 Annex 1 EOTF with L_B = 0: γ = 2.4.
    static const RgbSpace space("rec1886", {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}}, d65_xy,
                                TransferFunction(Kind::gamma, 2.4));
    return space;
}

const RgbSpace& rec1886_rec2020() {
    // ITU-R BT.2020-2 Table 3 primaries; ITU-R BT.1886 Annex 1 EOTF with L_B = 0: γ = 2.4.
    static const RgbSpace space("rec1886-rec2020", {{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}},
                                d65_xy, TransferFunction(Kind::gamma, 2.4));
    return space;
}

const RgbSpace& p3_d65() {
    // SMPTE EG 432-1:2010 primaries with D65; SMPTE RP 431-2:2011 §7.1 decoding γ = 2.6.
    static const RgbSpace space("p3-d65", {{0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}}, d65_xy,
                                TransferFunction(Kind::gamma, 2.6));
    return space;
}

const RgbSpace& rec2100_pq() {
    // ITU-R BT.2100-2 Table 1 (the BT.2020 primaries, D65) and Table 4 (PQ).
    static const RgbSpace space("rec2100-pq", {{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}},
                                d65_xy, TransferFunction(Kind::pq));
    return space;
}

const RgbSpace& p3_d65_pq() {
    // SMPTE EG 432-1:2010 primaries with D65; SMPTE ST 2084:2014.
    static const RgbSpace space("p3-d65-pq", {{0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}},
                                d65_xy, TransferFunction(Kind::pq));
    return space;
}

const RgbSpace& rec2100_hlg() {
    // ITU-R BT.2100-2 Table 1 (the BT.2020 primaries, D65) and Table 5 (HLG, its reference OOTF at
    // 1000 cd/m²).
    static const RgbSpace space("rec2100-hlg", {{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}},
                                d65_xy, TransferFunction(Kind::hlg));
    return space;
}

const RgbSpace& acescct() {
    // Academy S-2016-001 (ACEScct) §4.1 and §4.4: AP1 primaries, the ACES white, the ACEScct curve.
    static const RgbSpace space("acescct", {{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}},
                                aces_white_xy, TransferFunction(Kind::acescct));
    return space;
}

std::span<const RgbSpace* const> log_rgb_spaces() {
    static const std::array<const RgbSpace*, 1> spaces{&acescct()};
    return spaces;
}

std::span<const RgbSpace* const> display_rgb_spaces() {
    static const std::array<const RgbSpace*, 6> spaces{&rec1886(),    &rec1886_rec2020(), &p3_d65(),
                                                       &rec2100_pq(), &p3_d65_pq(),       &rec2100_hlg()};
    return spaces;
}

std::span<const RgbSpace* const> builtin_rgb_spaces() {
    static const std::array<const RgbSpace*, 8> spaces{
        &srgb(),     &display_p3(), &rec2020(),    &adobe_rgb(),
        &smpte_c(),  &ntsc1953(),   &aces2065_1(), &acescg()};
    return spaces;
}

std::vector<std::string> rgb_space_names() {
    std::vector<std::string> names;
    for (const auto list : {builtin_rgb_spaces(), log_rgb_spaces(), display_rgb_spaces()})
        for (const RgbSpace* s : list) names.push_back(s->name());
    return names;
}

bool same_name(std::string_view given, std::string_view canonical) noexcept {
    if (given.size() != canonical.size()) return false;
    for (std::size_t i = 0; i < given.size(); ++i) {
        char c = given[i];
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
        if (c != canonical[i]) return false;
    }
    return true;
}

const RgbSpace* find_rgb_space(std::string_view name) noexcept {
    for (const auto list : {builtin_rgb_spaces(), log_rgb_spaces(), display_rgb_spaces()}) {
        for (const RgbSpace* space : list) {
            if (same_name(name, space->name())) return space;
        }
    }
    return nullptr;
}

}  // namespace irid
