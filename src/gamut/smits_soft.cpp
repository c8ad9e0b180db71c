// smits-soft: the thesis' direction (Smits 1990, §4.3: constant luminance Y, toward the grey w of
// equal luminance) with a soft compression of the distance instead of the hard stop.
//
// Along the ray from w through the colour c (both of luminance Y), the relative distance
//   r = max over channels of (c_i − w)/(max − w) where c_i > w, and (w − c_i)/w where c_i < w
// is 0 at the grey and 1 where the ray leaves the cube [0, max]³ (each term is the fraction of
// the way from w to that channel's face: w lies strictly inside (0, max) here). The colour moves
// to w + (r'/r)(c − w), so Y and the direction from the grey are kept exactly, with
//   r' = r                          for r <= threshold (nothing inside the threshold moves),
//   r' = f(r)                       for threshold < r < limit,
//   r' = 1 (the boundary: smits' own answer, its face channel set exactly) for r >= limit,
// f the power curve of the ACES 1.3 Reference Gamut Compression (Academy
// LMT.Academy.ReferenceGamutCompress.ctl, function compress(); also OpenColorIO 2.1
// FixedFunction ACES_GamutComp13): with x = (r − threshold)/scale,
//   f(r) = threshold + scale x / (1 + x^power)^(1/power),
//   scale = (limit − threshold) / ((( 1 − threshold)/(limit − threshold))^(−power) − 1)^(1/power),
// the scale chosen so that f(limit) = 1. f is continuous and increasing, f(threshold) =
// threshold with slope 1, so the curve has no kink at the threshold and reaches the boundary
// exactly at the limit. Y <= 0 gives black and w >= max white, as smits.
//
// Inverse (ClipSettings::inverse): with r' the input's relative distance, r = r' for
// r' <= threshold, r = f⁻¹(r') = threshold + scale (−y/(y − 1))^(1/power), y = ((r' −
// threshold)/scale)^power, for threshold < r' < 1, and r = limit for r' >= 1: the boundary maps
// to the limit (where the forward direction first reaches it; every colour beyond the limit also
// went there, so it is the nearest preimage), and a colour outside the cube (never an output of
// the forward direction) is first taken to the boundary along its ray, as smits does. So the
// inverse is continuous (also where the grey nears black or white: a colour there has a large
// r' and goes to w + (limit/r')(c − w), near the grey) and bounded by the limit's shell.
// inverse(forward(c)) = c for every colour whose r < limit.
// The inverse's output is not confined to the cube (confines_to_cube() is false).


#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/gamut/clip.h>

#include <cmath>
#include <string>

namespace irid {

void GamutClipper::prepare_smits_soft() {
    const double threshold = m_parameters[0].second;
    const double limit = m_parameters[1].second;
    const double power = m_parameters[2].second;
    // limit > 1 > threshold by the parameters' ranges, so the base is in (0, 1); a large power
    // and a limit far from a threshold near 1 overflow it (e.g. threshold 0.9999, limit 1000,
    // power 100: 1e-7^-100).
    const double base = std::pow((1.0 - threshold) / (limit - threshold), -power) - 1.0;
    const double scale = (limit - threshold) / std::pow(base, 1.0 / power);
    if (!(std::isfinite(base) && base > 0.0 && std::isfinite(scale) && scale > 0.0)) {
        throw Error(
            "method smits-soft: threshold " + format_shortest(threshold) + ", limit " +
            format_shortest(limit) + " and power " + format_shortest(power) +
            " give no finite compression curve (((1 - threshold)/(limit - threshold))^-power"
            " overflows); lower the power or bring the limit nearer the threshold");
    }
    m_smits_soft = {threshold, limit, power, scale, 1.0 / power};
}

Rgb GamutClipper::smits_soft(const Rgb& c) const noexcept {
    const double max = m_gamut.max();
    const Vec3& lum = m_gamut.luminance_row();
    const double y = lum[0] * c.r + lum[1] * c.g + lum[2] * c.b;
    if (!(y > 0.0)) return {0.0, 0.0, 0.0};
    const double w = y / (lum[0] + lum[1] + lum[2]);
    if (!(w < max)) return {max, max, max};
    const double v[3] = {c.r, c.g, c.b};
    // The relative distance r, and the channel (and face) that gives it.
    double r = 0.0;
    int face = 0;
    for (int i = 0; i < 3; ++i) {
        const double ri = v[i] > w ? (v[i] - w) / (max - w) : (w - v[i]) / w;
        if (ri > r) r = ri, face = i;
    }
    const SmitsSoftPrepared& prepared = m_smits_soft;
    const double threshold = prepared.threshold, limit = prepared.limit, power = prepared.power;
    const double scale = prepared.scale, inv_power = prepared.inverse_power;
    if (!(r > threshold)) return c;
    double target = 0.0;  // the new relative distance
    if (!m_inverse) {
        if (r >= limit) {
            target = 1.0;
        } else {
            const double x = (r - threshold) / scale;
            target = threshold + scale * x / std::pow(1.0 + std::pow(x, power), inv_power);
        }
    } else if (r >= 1.0) {
        target = limit;
    } else {
        const double yp = std::pow((r - threshold) / scale, power);
        target = threshold + scale * std::pow(-yp / (yp - 1.0), inv_power);
    }
    const double k = target / r;
    double out[3] = {w + k * (v[0] - w), w + k * (v[1] - w), w + k * (v[2] - w)};
    // On the boundary (forward, r >= limit) the face channel is exactly its bound.
    if (!m_inverse && r >= limit) out[face] = v[face] > w ? max : 0.0;
    return {out[0], out[1], out[2]};
}

}  // namespace irid
