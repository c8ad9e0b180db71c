// aces-rgc: the ACES 1.3 Reference Gamut Compression, scalar reference in double.
//
// Sources (formulas and constants; no code carried over):
// - Academy, aces-dev 1.3, LMT.Academy.ReferenceGamutCompress.ctl (and its inverse
//   InvLMT.Academy.ReferenceGamutCompress.ctl): the achromatic axis ach = max(r, g, b); the
//   per-channel distance d = (ach − c)/|ach| (0 for every channel when ach = 0); distances
//   below the threshold unchanged; beyond it the power curve
//       D(d) = thr + s · nd / (1 + nd^p)^(1/p),      nd = (d − thr)/s,
//   with the scale s chosen so that D(lim) = 1 ("scale factor for y = 1 intersect"),
//       s = (lim − thr) / (((1 − thr)/(lim − thr))^(−p) − 1)^(1/p);
//   the inverse thr + s · (u/(1 − u))^(1/p), u = nd^p, for d below the asymptote thr + s, and d
//   unchanged from there on ("avoid singularity"); the output ach − D |ach|. Published defaults
//   (ACEScg): limits 1.147 / 1.264 / 1.312, thresholds 0.815 / 0.803 / 0.880, power 1.2.
// - OpenColorIO 2.1, src/OpenColorIO/ops/fixedfunction/FixedFunctionOpCPU.cpp (functions
//   compress, uncompress, gamut_comp, Renderer_ACES_GamutComp13_Fwd/_Inv): the same, with the
//   inverse's test written d >= thr + s (the CTL has d > thr + s, which divides by zero at
//   equality) and ach == 0 giving 0 for every channel; FixedFunctionOpData.cpp (validate): the
//   parameter ranges used in clip.cpp's table (limits [1.001, 65504], thresholds [0, 0.9995],
//   power [1, 65504]).
//
// Evaluation (mathematically the same as the CTL, written so that no valid parameter set
// overflows): s = (1 − thr)/(1 − x^p)^(1/p) with x = (1 − thr)/(lim − thr) < 1 (divide the
// CTL's numerator and denominator by x^(−1)), and the curve as nd (1 + nd^p)^(−1/p) for nd <= 1,
// (1 + nd^(−p))^(−1/p) for nd > 1, so that nd^p never exceeds 1 (OCIO's float evaluation
// overflows for large powers, e.g. p = 100 beyond nd = 2.4; with the published power both agree).
//
// irid's additions (clip.h): the non-finite rule comes first (GamutClipper::clip), and a
// compressed channel beyond ±1e30 (the rule's stand-in for infinity) is capped there, so that every output is finite,
// also in float: the inverse grows without bound toward its asymptote, and the forward reaches
// 2.2 |ach| for an all-negative colour.

#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/gamut/clip.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace irid {
namespace {

/// The largest magnitude an output may have (the non-finite rule's stand-in for infinity).
constexpr double output_cap = 1e30;

/// The compressed distance D(d) for d >= thr: thr + s f(nd), f(nd) = nd / (1 + nd^p)^(1/p),
/// evaluated without overflow for any nd >= 0 (also +inf, where f = 1).
double compress_distance(double d, double thr, double s, double p) noexcept {
    const double nd = (d - thr) / s;
    const double f = nd <= 1.0 ? nd * std::pow(1.0 + std::pow(nd, p), -1.0 / p)
                               : std::pow(1.0 + std::pow(nd, -p), -1.0 / p);
    return thr + s * f;
}

/// The inverse of compress_distance for thr <= d < thr + s (the caller leaves d >= thr + s
/// unchanged): thr + s nd / (1 − nd^p)^(1/p), which is the CTL's thr + s (u/(1 − u))^(1/p).
/// Grows without bound as d approaches the asymptote (+inf where nd^p rounds to 1).
double uncompress_distance(double d, double thr, double s, double p) noexcept {
    const double nd = (d - thr) / s;
    const double u = std::pow(nd, p);
    return thr + s * nd * std::pow(1.0 - u, -1.0 / p);
}

}  // namespace

void GamutClipper::prepare_aces_rgc() {
    const double p = m_parameters[6].second;
    m_aces_rgc.power = p;
    m_aces_rgc.inverse_power = 1.0 / p;
    for (std::size_t k = 0; k < 3; ++k) {
        const double lim = m_parameters[k].second;
        const double thr = m_parameters[3 + k].second;
        // The table's ranges make lim >= 1.001 > 0.9995 >= thr, so 0 < x < 1 and s > 0; checked
        // all the same, naming both, should the ranges ever change.
        const double x = (1.0 - thr) / (lim - thr);
        const double s = (1.0 - thr) / std::pow(-std::expm1(p * std::log(x)), 1.0 / p);
        if (!(x > 0.0 && x < 1.0) || !(s > 0.0) || !std::isfinite(s)) {
            throw Error("method aces-rgc: " + m_parameters[k].first + " = " +
                        format_shortest(lim) + " must exceed 1 and " + m_parameters[3 + k].first +
                        " = " + format_shortest(thr) + " must be below 1");
        }
        m_aces_rgc.threshold[k] = thr;
        m_aces_rgc.scale[k] = s;
        m_aces_rgc.asymptote[k] = thr + s;
    }
}

Rgb GamutClipper::aces_rgc(const Rgb& c) const noexcept {
    const double ach = std::max({c.r, c.g, c.b});
    // OCIO's gamut_comp (and the CTL's dist = 0): no achromatic axis, every channel 0.
    if (ach == 0.0) return {0.0, 0.0, 0.0};
    const double abs_ach = std::abs(ach);
    const AcesRgcPrepared& a = m_aces_rgc;
    const double p = a.power;
    const auto channel = [&](double v, std::size_t k) {
        const double thr = a.threshold[k];
        const double d = (ach - v) / abs_ach;
        if (d < thr) return v;  // inside the protected core: untouched
        double compressed = 0.0;
        if (!m_inverse) {
            compressed = compress_distance(d, thr, a.scale[k], p);
        } else {
            if (d >= a.asymptote[k]) return v;  // at or beyond the asymptote: unchanged
            compressed = uncompress_distance(d, thr, a.scale[k], p);
        }
        const double out = ach - compressed * abs_ach;
        return std::clamp(out, -output_cap, output_cap);
    };
    return {channel(c.r, 0), channel(c.g, 1), channel(c.b, 2)};
}

}  // namespace irid
