// Ottosson's adaptive projections (Björn Ottosson, "sRGB gamut clipping", 2021,
// bottosson.github.io/posts/gamutclipping/): an out-of-gamut colour moves in its Oklab hue plane
// along the segment from (L0, 0) to itself, L0 chosen adaptively, and stops where the segment
// leaves the gamut.
//
// Ottosson's own cusp and intersection are polynomial fits to sRGB; here both are exact for any
// RGB space and peak:
// - The segment: along (L0 + t (L − L0), t a, t b) Oklab's cube-root LMS are linear in t, so each
//   RGB channel is a cubic in t, whose crossings of 0 and max are found to double's resolution
//   (as GamutClipper::oklab does for constant L, L0 = L).
// - The cusp of a hue (its largest chroma in the gamut): at a fixed saturation S = C / L the
//   colours of a hue are a ray from black in RGB (LMS scale with L³), so the hue plane's part of
//   the cube is swept by the rays of S in [0, S_max], S_max where the first channel reaches 0; the
//   ray of S leaves the cube through a face at max at L(S) = cbrt(max / m(S)), m(S) the largest
//   channel of Oklab (1, S a', S b'), and the chroma there is S L(S). Its maximum over
//   [0, S_max] lies at S_max (Ottosson's cusp: one channel 0 and one at max, an edge of the cube),
//   at a critical point of one channel's S³ / p(S) (the quadratic c2 S² + 2 c1 S + 3 c0 = 0 of
//   the channel's cubic p = c0 + c1 S + c2 S² + c3 S³), or where two channels are equal (the
//   largest switches); every candidate is evaluated and the largest chroma kept.

#include <irid/color/matrix.h>
#include <irid/color/spaces.h>
#include <irid/gamut/clip.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace irid {
namespace {

using Cubic = std::array<double, 4>;  // c0 + c1 s + c2 s² + c3 s³

double eval(const Cubic& c, double s) noexcept { return c[0] + s * (c[1] + s * (c[2] + s * c[3])); }

/// The roots in [0, 1] of the cubic where it changes sign, in increasing order (at most three;
/// returns how many): [0, 1] is cut at the derivative's roots into monotonic pieces and the root
/// of each piece whose ends have opposite signs is found to a double's resolution by Newton
/// steps kept inside the shrinking bracket (bisection when a step would leave it), to the
/// bracket's end beyond the root. A root where the cubic only touches 0 is skipped (it changes
/// no side of a face).
int sign_changes(const Cubic& c, std::array<double, 3>& roots) noexcept {
    std::array<double, 4> cuts{0.0, 1.0, 1.0, 1.0};
    int n = 1;
    const double qa = 3.0 * c[3], qb = 2.0 * c[2], qc = c[1];  // f'(s) = qc + qb s + qa s²
    const auto add_cut = [&](double s) {
        if (s > 0.0 && s < 1.0) cuts[static_cast<std::size_t>(n++)] = s;
    };
    if (std::abs(qa) > 1e-300) {
        const double disc = qb * qb - 4.0 * qa * qc;
        if (disc >= 0.0) {
            const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
            if (q != 0.0) add_cut(qc / q);
            add_cut(q / qa);
        }
    } else if (std::abs(qb) > 1e-300) {
        add_cut(-qc / qb);
    }
    if (n == 3 && cuts[2] < cuts[1]) std::swap(cuts[1], cuts[2]);
    cuts[static_cast<std::size_t>(n)] = 1.0;
    int found = 0;
    for (int k = 0; k < n; ++k) {
        double lo = cuts[static_cast<std::size_t>(k)], hi = cuts[static_cast<std::size_t>(k + 1)];
        const bool negative_at_lo = eval(c, lo) < 0.0;
        if (negative_at_lo == (eval(c, hi) < 0.0)) continue;
        double x = 0.5 * (lo + hi);
        bool settled = false;  // once Newton has settled, bisection closes the bracket
        for (int it = 0; it < 200; ++it) {
            const double fx = eval(c, x);
            ((fx < 0.0) == negative_at_lo ? lo : hi) = x;
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;  // lo and hi adjacent doubles
            double next = mid;
            if (!settled) {
                const double slope = c[1] + x * (2.0 * c[2] + 3.0 * x * c[3]);
                const double newton = x - fx / slope;
                if (newton > lo && newton < hi) next = newton;
                if (std::abs(next - x) <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(x)) {
                    settled = true;
                    // Bracket the settled point tightly, then bisect what is left.
                    const double e = 8.0 * std::numeric_limits<double>::epsilon() * std::abs(x);
                    const double below = std::max(lo, next - e), above = std::min(hi, next + e);
                    ((eval(c, below) < 0.0) == negative_at_lo ? lo : hi) = below;
                    ((eval(c, above) < 0.0) == negative_at_lo ? lo : hi) = above;
                    next = 0.5 * (lo + hi);
                    if (next <= lo || next >= hi) break;
                }
            }
            x = next;
        }
        roots[static_cast<std::size_t>(found++)] = hi;
    }
    return found;
}

/// The three RGB channels along Oklab p + s q (p, q Oklab vectors) as cubics in s:
/// channel_i(s) = Σ_j lms_to_rgb_ij (P_j + s Q_j)³ with (P, Q) = M2⁻¹ (p, q).
std::array<Cubic, 3> channel_cubics(const Mat3& lms_to_rgb, const Vec3& p_lab,
                                    const Vec3& q_lab) noexcept {
    const Vec3 p = oklab_m2_inverse * p_lab;
    const Vec3 q = oklab_m2_inverse * q_lab;
    std::array<Cubic, 3> k{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double m = lms_to_rgb[i][j];
            auto& c = k[static_cast<std::size_t>(i)];
            c[0] += m * p[j] * p[j] * p[j];
            c[1] += m * 3.0 * p[j] * p[j] * q[j];
            c[2] += m * 3.0 * p[j] * q[j] * q[j];
            c[3] += m * q[j] * q[j] * q[j];
        }
    }
    return k;
}

/// The cubic c(scale · u) in u.
Cubic rescaled(const Cubic& c, double scale) noexcept {
    return {c[0], c[1] * scale, c[2] * scale * scale, c[3] * scale * scale * scale};
}

/// Saturations S = C / L up to this are searched for the first zero of a channel; beyond it a
/// hue's rays would be inside the cube for ever (none of the built-in spaces comes near: their
/// most saturated colours have S below 3, ACES2065-1's imaginary blue included).
constexpr double saturation_search_limit = 64.0;

/// oklab-cusp's centre is kept within [cusp_centre_low, cusp_centre_high] × the white's L.
constexpr double cusp_centre_low = 0.01;
constexpr double cusp_centre_high = 0.99;

/// Ottosson's adaptive L0 for a colour of lightness l and chroma c, around l_cusp.
double oklab_adaptive_l0(double l, double c, double l_cusp, double l_white,
                         double alpha) noexcept {
    // Ottosson 2021, gamut_clip_adaptive_L0_L_cusp, in lightness relative to the white's
    // (Ottosson's white has L = 1): with l_cusp = 1/2 it is gamut_clip_adaptive_L0_0_5.
    const double lr = l / l_white, cr = c / l_white, lc = l_cusp / l_white;
    const double ld = lr - lc;
    // Every lightness takes the formula, below 0 and above the white's too: its L0 stays inside
    // (0, l_cusp) below the cusp and (l_cusp, 1) above it, so a colour brighter than the white
    // moves toward a point inside the gamut, as Ottosson's code does (it has no white rule).
    const double k = 2.0 * (ld > 0.0 ? 1.0 - lc : lc);
    const double a = 0.5 * k + std::abs(ld), b = alpha * cr / k;
    const double e1 = a + b;
    // e1² − 2 k |ΔL| = (½ k − |ΔL|)² + b (2a + b): no cancellation near the white's lightness.
    const double gap = 0.5 * k - std::abs(ld);
    const double root = std::sqrt(gap * gap + b * (2.0 * a + b));
    const double sign = ld > 0.0 ? 1.0 : (ld < 0.0 ? -1.0 : 0.0);
    // e1 − root, written without the cancellation of two large numbers (HDR and far colours).
    const double step = 2.0 * k * std::abs(ld) / (e1 + root);
    return l_white * (lc + 0.5 * sign * step);
}

}  // namespace

GamutClipper::OklabCusp GamutClipper::oklab_cusp_of_hue(double a_unit, double b_unit,
                                                        Branches* branches) const noexcept {
    const double max = m_gamut.max();
    const std::array<Cubic, 3> k =
        channel_cubics(m_lms_to_rgb, {1.0, 0.0, 0.0}, {0.0, a_unit, b_unit});
    // The saturations whose rays are inside the octant (every channel >= 0): pieces of
    // [0, S_cap] between the channels' zeros, the first from grey (S = 0, positive) to S_max.
    // With real primaries there is only that piece; ACES2065-1's imaginary blue gives hues whose
    // rays come back into the octant beyond it.
    std::array<double, 12> cuts{0.0, saturation_search_limit};
    std::size_t n_cuts = 2;
    double s_max = saturation_search_limit;
    int zero_channel = -1;
    for (int i = 0; i < 3; ++i) {
        std::array<double, 3> roots{};
        const Cubic c = rescaled(k[static_cast<std::size_t>(i)], saturation_search_limit);
        const int n = sign_changes(c, roots);
        for (int r = 0; r < n; ++r) {
            cuts[n_cuts++] = roots[static_cast<std::size_t>(r)] * saturation_search_limit;
        }
        if (n > 0 && roots[0] * saturation_search_limit < s_max) {
            s_max = roots[0] * saturation_search_limit;
            zero_channel = i;
        }
    }
    std::sort(cuts.begin(), cuts.begin() + static_cast<std::ptrdiff_t>(n_cuts));
    const auto in_octant = [&](double s) {
        return eval(k[0], s) >= 0.0 && eval(k[1], s) >= 0.0 && eval(k[2], s) >= 0.0;
    };
    const auto largest_channel = [&](double s) {
        return std::max({eval(k[0], s), eval(k[1], s), eval(k[2], s)});
    };
    // Candidates for the largest S³ / m(S) on the inside pieces: their ends, and the stationary
    // points and switches of the largest channel within them.
    std::array<double, 64> candidates{};
    std::array<std::uint64_t, 64> kinds{};  // which kind of candidate (for branch_signature)
    std::size_t n = 0;
    for (std::size_t piece = 0; piece + 1 < n_cuts; ++piece) {
        const double lo = cuts[piece], hi = cuts[piece + 1];
        if (!(hi > lo) || !in_octant(0.5 * (lo + hi))) continue;
        kinds[n] = 1;
        candidates[n++] = lo;
        kinds[n] = 2;
        candidates[n++] = hi;
        std::uint64_t kind = 0;
        const auto add = [&](double s) {
            if (s > lo && s < hi && n < candidates.size()) {
                kinds[n] = kind;
                candidates[n++] = s;
            }
        };
        kind = 3;
        for (const Cubic& c : k) {
            ++kind;  // a stationary point of channel 0, 1, 2: kinds 4, 5, 6
            // S p' − 3 p = −(3 c0 + 2 c1 S + c2 S²): zero where S³ / p is stationary.
            const double qa = c[2], qb = 2.0 * c[1], qc = 3.0 * c[0];
            if (std::abs(qa) > 1e-300) {
                const double disc = qb * qb - 4.0 * qa * qc;
                if (disc >= 0.0) {
                    const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
                    if (q != 0.0) add(qc / q);
                    add(q / qa);
                }
            } else if (std::abs(qb) > 1e-300) {
                add(-qc / qb);
            }
        }
        for (int i = 0; i < 3; ++i) {
            for (int j = i + 1; j < 3; ++j) {
                const auto& ci = k[static_cast<std::size_t>(i)];
                const auto& cj = k[static_cast<std::size_t>(j)];
                const Cubic diff{ci[0] - cj[0], ci[1] - cj[1], ci[2] - cj[2], ci[3] - cj[3]};
                // The difference on [lo, hi] as a cubic on [0, 1]: shift then scale.
                const double w = hi - lo;
                const Cubic shifted{eval(diff, lo),
                                    diff[1] + lo * (2.0 * diff[2] + 3.0 * lo * diff[3]),
                                    diff[2] + 3.0 * lo * diff[3], diff[3]};
                std::array<double, 3> roots{};
                const int found = sign_changes(rescaled(shifted, w), roots);
                kind = 7 + static_cast<std::uint64_t>(i + j);  // channels i and j switch
                for (int r = 0; r < found; ++r) add(lo + roots[static_cast<std::size_t>(r)] * w);
            }
        }
    }
    OklabCusp best{0.0, 0.0, s_max, s_max, zero_channel};
    std::uint64_t best_kind = 0;
    for (std::size_t c = 0; c < n; ++c) {
        const double s = candidates[c];
        const double m = largest_channel(s);
        if (!(m > 0.0)) continue;
        const double l = std::cbrt(max / m);
        if (s * l > best.C) {
            best.L = l;
            best.C = s * l;
            best.S = s;
            best_kind = kinds[c];
        }
    }
    take(branches, best_kind);
    return best;
}

double GamutClipper::oklab_segment_exit(double l0, const Oklab& lab,
                                        Branches* branches) const noexcept {
    const double max = m_gamut.max();
    const std::array<Cubic, 3> channel =
        channel_cubics(m_lms_to_rgb, {l0, 0.0, 0.0}, {lab.L - l0, lab.a, lab.b});
    // How far the point at t is outside the cube (0 inside): the largest excess of a channel.
    const auto outside = [&](double t) {
        double e = 0.0;
        for (const auto& k : channel) {
            const double v = eval(k, t);
            e = std::max({e, -v, v - max});
        }
        return e;
    };
    // The segment enters or leaves the cube only where a channel crosses 0 or max; between two
    // consecutive crossings (and 0, 1) it is inside throughout or outside throughout. The
    // boundary nearest the colour is the upper end of the last piece inside (the cube is not
    // convex in Oklab: the segment may leave and come back).
    std::array<double, 20> cuts{};
    std::size_t n = 0;
    cuts[n++] = 0.0;
    cuts[n++] = 1.0;
    for (const auto& k : channel) {
        for (const double bound : {0.0, max}) {
            std::array<double, 3> roots{};
            const int found = sign_changes({k[0] - bound, k[1], k[2], k[3]}, roots);
            for (int r = 0; r < found; ++r) cuts[n++] = roots[static_cast<std::size_t>(r)];
        }
    }
    std::sort(cuts.begin(), cuts.begin() + static_cast<std::ptrdiff_t>(n));
    // The pieces inside, counted from the colour's end: the result is the first of them.
    double t = -1.0;
    std::uint64_t pieces = 0;
    bool after_inside = false;  // the interval above (toward the colour) was inside
    for (std::size_t k = n - 1; k >= 1; --k) {
        if (!(cuts[k] > cuts[k - 1])) continue;  // two crossings at one t: no interval
        const bool inside = outside(0.5 * (cuts[k - 1] + cuts[k])) == 0.0;
        if (inside && t < 0.0) t = cuts[k];
        if (inside && !after_inside) ++pieces;
        after_inside = inside;
    }
    take(branches, pieces);
    if (t < 0.0) {
        // No point of the segment is inside: the grey (L0, 0, 0) is inside the cube for every L0
        // in [0, the white's L] (clip.h: CSS Color 4's Oklab), so only through rounding at the
        // ends of that range, or for a grey beyond it (ACES2065-1, whose cube holds colours of
        // Oklab L below 0 and above the white's). The crossing (or end) nearest the cube, which
        // clip clamps.
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < n; ++k) {
            const double e = outside(cuts[k]);
            if (e < nearest) {
                nearest = e;
                t = cuts[k];
            }
        }
    }
    return t;
}

Rgb GamutClipper::oklab_projection(const Rgb& c, bool around_cusp, Branches* branches) const noexcept {
    const double max = m_gamut.max();
    // Within rounding of the cube, the colour is on it (clip.h's rule, as for oklab), tested
    // first: inside ACES2065-1's cube (imaginary blue) Oklab L goes below 0 and above the
    // white's, where the rule below would send a colour a hair outside to black or white.
    const double tol = oklab_rounding_tolerance * max;
    if (c.r >= -tol && c.g >= -tol && c.b >= -tol && c.r <= max + tol && c.g <= max + tol &&
        c.b <= max + tol) {
        take(branches, 1);
        return clamp(c);
    }
    const Oklab lab = to_oklab(c);
    const double chroma = std::hypot(lab.a, lab.b);
    double l_centre = 0.5 * m_white_oklab_l;
    if (around_cusp) {
        // A grey has no hue; its segment is along L whatever the cusp, take hue a' = 1.
        const double au = chroma > 0.0 ? lab.a / chroma : 1.0;
        const double bu = chroma > 0.0 ? lab.b / chroma : 0.0;
        // Ottosson's L0 needs its centre inside the neutral range (0, the white's L): a gamut
        // with imaginary primaries (ACES2065-1) has hues whose cusp lies above the white's
        // lightness; there the centre is the nearest end of [0.01, 0.99] × the white's L.
        l_centre = std::clamp(oklab_cusp_of_hue(au, bu, branches).L, cusp_centre_low * m_white_oklab_l,
                              cusp_centre_high * m_white_oklab_l);
    }
    const double alpha = m_parameters[0].second;
    const double l0 = oklab_adaptive_l0(lab.L, chroma, l_centre, m_white_oklab_l, alpha);
    const double t = oklab_segment_exit(l0, lab, branches);
    Rgb out = from_oklab({l0 + t * (lab.L - l0), t * lab.a, t * lab.b});
    // The point is on a face to within rounding (a few ulps): put the channel nearest its bound
    // exactly on it.
    double* channels[3] = {&out.r, &out.g, &out.b};
    double nearest = 1e-9 * max, bound = 0.0;
    double* on_face = nullptr;
    for (double* v : channels) {
        for (const double b : {0.0, max}) {
            if (std::abs(*v - b) < nearest) {
                nearest = std::abs(*v - b);
                bound = b;
                on_face = v;
            }
        }
    }
    if (on_face != nullptr) *on_face = bound;
    return out;
}

// OklabProjectionPrepared (clip.h), read by the SIMD kernels (batch_simd_oklab.cpp).
void GamutClipper::prepare_oklab_projection() {
    m_oklab_projection = {};
    const double max = m_gamut.max();
    std::array<std::array<double, 2>, 3>& primary = m_oklab_projection.primary_hue;
    for (int i = 0; i < 3; ++i) {
        Rgb c{0.0, 0.0, 0.0};
        (i == 0 ? c.r : i == 1 ? c.g : c.b) = max;
        const Oklab lab = to_oklab(c);
        const double chroma = std::hypot(lab.a, lab.b);
        primary[static_cast<std::size_t>(i)] = {lab.a / chroma, lab.b / chroma};
    }
    const auto cross = [](const std::array<double, 2>& u, const std::array<double, 2>& v) {
        return u[0] * v[1] - u[1] * v[0];
    };
    bool structured = true;
    constexpr int samples = 48;
    for (int sector = 0; sector < 3; ++sector) {
        // Sector from primary `sector` to the next counter-clockwise; its zero channel is the
        // remaining one (red → green: blue).
        const auto& from = primary[static_cast<std::size_t>(sector)];
        const auto& to = primary[static_cast<std::size_t>((sector + 1) % 3)];
        const int zero = (sector + 2) % 3;
        if (!(cross(from, to) > 0.0)) {
            structured = false;
            continue;
        }
        const double h0 = std::atan2(from[1], from[0]);
        double h1 = std::atan2(to[1], to[0]);
        if (h1 < h0) h1 += 2.0 * 3.14159265358979323846;
        Mat3 normal{};
        Vec3 rhs{0.0, 0.0, 0.0};
        for (int k = 0; k < samples; ++k) {
            const double h = h0 + (h1 - h0) * (k + 0.5) / samples;
            const double a = std::cos(h), b = std::sin(h);
            const OklabCusp cusp = oklab_cusp_of_hue(a, b);
            if (cusp.zero_channel != zero || cusp.S != cusp.s_max) structured = false;
            const Vec3 x{1.0, a, b};
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j) normal[i][j] += x[i] * x[j];
                rhs[i] += x[i] * cusp.s_max;
            }
        }
        const Vec3 fit = irid::inverse(normal, "oklab cusp fit") * rhs;
        m_oklab_projection.s_max_fit[static_cast<std::size_t>(zero)] = {fit[0], fit[1], fit[2]};
    }
    m_oklab_projection.structured = structured;
}


}  // namespace irid
