// FilmShader::evaluate(): the GLSL chunk (film_shader_glsl.cpp) in single precision on the CPU,
// function by function and line by line, so that its accuracy can be measured without a GPU.

#include <irid/optics/film_shader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace irid {
namespace {

// GLSL's vec3 and built-ins in float, then the chunk's functions in the same order and with the
// same names (irid_ dropped).

struct vec3 {
    float r = 0.0f, g = 0.0f, b = 0.0f;
    vec3() = default;
    constexpr vec3(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
    explicit constexpr vec3(float s) : r(s), g(s), b(s) {}
};
vec3 operator+(vec3 a, vec3 b) {
    return {a.r + b.r, a.g + b.g, a.b + b.b};
}
vec3 operator-(vec3 a, vec3 b) {
    return {a.r - b.r, a.g - b.g, a.b - b.b};
}
vec3 operator*(vec3 a, vec3 b) {
    return {a.r * b.r, a.g * b.g, a.b * b.b};
}
vec3 operator/(vec3 a, vec3 b) {
    return {a.r / b.r, a.g / b.g, a.b / b.b};
}
vec3 operator+(float s, vec3 a) {
    return vec3(s) + a;
}
vec3 operator-(float s, vec3 a) {
    return vec3(s) - a;
}
vec3 operator-(vec3 a, float s) {
    return a - vec3(s);
}
vec3 operator+(vec3 a, float s) {
    return a + vec3(s);
}
vec3 operator*(float s, vec3 a) {
    return vec3(s) * a;
}
vec3 operator*(vec3 a, float s) {
    return a * vec3(s);
}
vec3 operator/(float s, vec3 a) {
    return vec3(s) / a;
}
template <class F>
vec3 map(vec3 a, F f) {
    return {f(a.r), f(a.g), f(a.b)};
}
template <class F>
vec3 map(vec3 a, vec3 b, F f) {
    return {f(a.r, b.r), f(a.g, b.g), f(a.b, b.b)};
}
vec3 sqrt(vec3 a) {
    return map(a, [](float x) { return std::sqrt(x); });
}
vec3 abs(vec3 a) {
    return map(a, [](float x) { return std::fabs(x); });
}
vec3 max(vec3 a, float s) {
    return map(a, [s](float x) { return std::max(x, s); });
}
vec3 min(vec3 a, float s) {
    return map(a, [s](float x) { return std::min(x, s); });
}
vec3 max(vec3 a, vec3 b) {
    return map(a, b, [](float x, float y) { return std::max(x, y); });
}
vec3 clamp(vec3 a, float lo, float hi) {
    return map(a, [lo, hi](float x) { return std::clamp(x, lo, hi); });
}
float fract(float x) {
    return x - std::floor(x);
}
vec3 cos(vec3 a) {
    return map(a, [](float x) { return std::cos(x); });
}
/// mix(a, b, vec3(bvec)) with a boolean selector per channel.
vec3 select(vec3 a, vec3 b, vec3 q2sq, bool (*pick)(float)) {
    return {pick(q2sq.r) ? b.r : a.r, pick(q2sq.g) ? b.g : a.g, pick(q2sq.b) ? b.b : a.b};
}
bool non_positive(float x) {
    return x <= 0.0f;
}
bool negative(float x) {
    return x < 0.0f;
}

Rgb to_rgb(vec3 v) {
    Rgb out;
    out.r = v.r;
    out.g = v.g;
    out.b = v.b;
    return out;
}

std::array<float, 4> catmull_rom(float f) {
    const float f2 = f * f;
    const float f3 = f2 * f;
    return {0.5f * (-f3 + 2.0f * f2 - f), 0.5f * (3.0f * f3 - 5.0f * f2 + 2.0f),
            0.5f * (-3.0f * f3 + 4.0f * f2 + f), 0.5f * (f3 - f2)};
}

vec3 base_index(vec3 f0) {
    const vec3 s = sqrt(clamp(f0, 0.0f, 0.9999f));
    return (1.0f + s) / (1.0f - s);
}

vec3 bare(float n0, vec3 n2, float q0, vec3 q2sq) {
    const vec3 q2 = sqrt(max(q2sq, 0.0f));
    const vec3 rs = (q0 - q2) / max(q0 + q2, 1e-30f);
    const vec3 up = n0 * n0 * q2;
    const vec3 vp = n2 * n2 * q0;
    const vec3 rp = (up - vp) / max(up + vp, 1e-30f);
    const vec3 r = 0.5f * (rs * rs + rp * rp);
    return select(r, vec3(1.0f), q2sq, non_positive);
}

float face(float u, float v, float& t) {
    const float s = u + v;
    t = 4.0f * u * v / (s * s);
    return (u - v) / s;
}

void base_face(vec3 x, vec3 k, vec3 q2sq, float sgn, vec3& re, vec3& im, vec3& t) {
    const vec3 w = k * sqrt(abs(q2sq));
    const vec3 s = x + w;
    const vec3 d = x * x + w * w;
    re = sgn * select((x - w) / s, (x * x - w * w) / d, q2sq, negative);
    im = sgn * select(vec3(0.0f), -2.0f * x * w / d, q2sq, negative);
    t = select(4.0f * x * w / (s * s), vec3(0.0f), q2sq, negative);
}

struct Coefficients {
    vec3 a0, gre, gim, qre, qim, bnd, mq;
};
Coefficients coefficients(float r01, float t01, vec3 r12re, vec3 r12im, vec3 t12) {
    Coefficients c;
    c.qre = -r01 * r12re;
    c.qim = -r01 * r12im;
    const vec3 omq = t01 + r01 * r01 * t12;
    const vec3 e = (r12re * r12re + r12im * r12im) * t01 * min(t01 / max(omq, 1e-30f), 1.0f);
    c.a0 = r01 * r01 + e;
    c.gre = r01 * t01 * r12re + e * c.qre;
    c.gim = r01 * t01 * r12im + e * c.qim;
    c.mq = sqrt(c.qre * c.qre + c.qim * c.qim);
    c.bnd = sqrt(c.gre * c.gre + c.gim * c.gim) * (1.0f + c.mq) / max(omq, 1e-30f);
    return c;
}


void resonance(float u, float v, vec3 x, vec3 k, vec3 q2sq, float sgn, vec3& re, vec3& im) {
    const vec3 w = k * sqrt(abs(q2sq));
    const vec3 tir = select(vec3(0.0f), vec3(1.0f), q2sq, negative);
    const vec3 wr = w * (1.0f - tir);
    const vec3 wi = w * tir;
    const float a = (sgn > 0.0f ? u : v) / (u + v);
    const float b = (sgn > 0.0f ? v : u) / (u + v);
    const vec3 nre = 2.0f * (a * x + b * wr);
    const vec3 nim = 2.0f * b * wi;
    const vec3 dre = x + wr;
    const vec3 m = max(dre * dre + wi * wi, 1e-30f);
    re = (nre * dre + nim * wi) / m;
    im = (nim * dre - nre * wi) / m;
}

void ratio(vec3 ar, vec3 ai, vec3 br, vec3 bi, vec3& re, vec3& im) {
    const vec3 nr = ar - br;
    const vec3 ni = ai - bi;
    const vec3 dr = ar + br;
    const vec3 di = ai + bi;
    const vec3 m = max(dr * dr + di * di, 1e-30f);
    re = (nr * dr + ni * di) / m;
    im = (ni * dr - nr * di) / m;
}

void quotient(vec3 ar, vec3 ai, vec3 br, vec3 bi, vec3 cr, vec3 ci, vec3& re, vec3& im) {
    vec3 m = max(br * br + bi * bi, 1e-30f);
    const vec3 xr = (ar * br + ai * bi) / m;
    const vec3 xi = (ai * br - ar * bi) / m;
    m = max(cr * cr + ci * ci, 1e-30f);
    re = (xr * cr + xi * ci) / m;
    im = (xi * cr - xr * ci) / m;
}

float centred(float x) {
    const float f = fract(x);
    return f > 0.5f ? f - 1.0f : f;
}
vec3 centred(vec3 x) {
    return map(x, [](float v) { return centred(v); });
}

float taylor_sin(float h) {
    const float h2 = h * h;
    return std::fabs(h) < 0.5f ? h * (1.0f - h2 / 6.0f * (1.0f - h2 / 20.0f * (1.0f - h2 / 42.0f)))
                               : std::sin(h);
}
vec3 taylor_sin(vec3 h) {
    return map(h, [](float x) { return taylor_sin(x); });
}

float expm1_neg(float x) {
    return x < 0.1f ? -x * (1.0f - x / 2.0f * (1.0f - x / 3.0f * (1.0f - x / 4.0f * (1.0f - x / 5.0f))))
                    : std::exp(-x) - 1.0f;
}

vec3 node(vec3 are, vec3 aim, vec3 bre, vec3 bim, vec3 t, float yre, float yim) {
    const vec3 wre = are + bre * yre - bim * yim;
    const vec3 wim = aim + bre * yim + bim * yre;
    return clamp(1.0f + t / max(wre * wre + wim * wim, 1e-30f), 0.0f, 1.0f);
}

float largest(vec3 v) {
    return std::max(v.r, std::max(v.g, v.b));
}

}  // namespace

FilmShader::Transform FilmShader::interpolated_transform(float tau_nm) const noexcept {
    const float x = tau_nm * static_cast<float>(1.0 / table_step_nm());
    const float fx = std::min(std::floor(x), static_cast<float>(m_width - 4));
    const std::array<float, 4> w = catmull_rom(x - fx);
    const int j = static_cast<int>(fx);
    Transform v{};
    for (std::size_t c = 0; c < 3; ++c) {
        float re = 0.0f, im = 0.0f;
        for (int t = 0; t < 4; ++t) {
            const auto k = static_cast<std::size_t>(j + t);
            re += w[static_cast<std::size_t>(t)] * m_table[4 * k + c];
            im += w[static_cast<std::size_t>(t)] * m_table[4 * (m_width + k) + c];
        }
        v.re[c] = re;
        v.im[c] = im;
    }
    return v;
}

FilmShader::Evaluation FilmShader::evaluate(float outside_ior, float eta2, float cos_theta1,
                                            float thickness_nm,
                                            const std::array<float, 3>& base_f0) const noexcept {
    const vec3 centre(static_cast<float>(m_centre[0]), static_cast<float>(m_centre[1]),
                      static_cast<float>(m_centre[2]));
    const auto max_index_f = static_cast<float>(max_index);
    const auto node_weight = [this](std::size_t j) {
        return vec3(static_cast<float>(m_node_weight[j][0]), static_cast<float>(m_node_weight[j][1]),
                    static_cast<float>(m_node_weight[j][2]));
    };
    // std::clamp's comparisons, like GLSL's clamp, leave NaN to the implementation: NaN inputs
    // are outside the chunk's contract (three.js never passes them).
    const float n0 = std::clamp(outside_ior, 1e-3f, max_index_f);
    const float n1 = std::clamp(eta2, 1e-3f, max_index_f);
    const float c0 = std::clamp(cos_theta1, 0.0f, 1.0f);
    const float d = std::clamp(thickness_nm, 0.0f, static_cast<float>(max_thickness_nm));
    const vec3 n2 = base_index(vec3(base_f0[0], base_f0[1], base_f0[2]));
    const float q0 = n0 * c0;
    const vec3 q2sq = (n2 - n0) * (n2 + n0) + q0 * q0;
    if (!(d > 0.0f)) return {to_rgb(bare(n0, n2, q0, q2sq)), 0, Path::bare};
    const float q1sq = (n1 - n0) * (n1 + n0) + q0 * q0;
    const float eps = static_cast<float>(min_film_q_sq) * n1 * n1;
    vec3 colour(0.0f);
    int terms = 0;
    vec3 asre, asim, bsre, bsim, ts, apre, apim, bpre, bpim, tp;
    float opd = 0.0f;
    float kappa = 0.0f;
    Path path = Path::fringes;
    if (q1sq > -eps) {
        const float q1 = std::sqrt(std::max(q1sq, eps));
        float t01s = 0.0f, t01p = 0.0f;
        const float r01s = face(q0, q1, t01s);
        const float r01p = face(n0 * n0 * q1, n1 * n1 * q0, t01p);
        vec3 r12sre, r12sim, t12s, r12pre, r12pim, t12p;
        base_face(vec3(q1), vec3(1.0f), q2sq, 1.0f, r12sre, r12sim, t12s);
        base_face(n2 * n2 * q1, vec3(n1 * n1), q2sq, -1.0f, r12pre, r12pim, t12p);
        const Coefficients s = coefficients(r01s, t01s, r12sre, r12sim, t12s);
        const Coefficients p = coefficients(r01p, t01p, r12pre, r12pim, t12p);
        opd = std::max(2.0f * d * q1, 1e-30f);
        const auto table_end = static_cast<float>(table_end_nm);
        const auto tolerance = static_cast<float>(term_tolerance);
        const float bound =
            std::max(largest(s.bnd + p.bnd) * static_cast<float>(m_envelope[0]), 1e-30f);
        const float mq = std::clamp(largest(max(s.mq, p.mq)), 1e-30f, 0.99999994f);
        const float needed =
            std::min(std::log(tolerance / bound) / std::log(mq), table_end / opd);
        if (needed <= static_cast<float>(max_terms)) {
            colour = 0.5f * (s.a0 + p.a0);
            const vec3 h = 3.14159265f * centred(opd * centre);
            const vec3 sh = taylor_sin(h);
            const vec3 er = 1.0f - 2.0f * sh * sh;
            const vec3 ei = 2.0f * sh * cos(h);
            vec3 psre = s.gre * er - s.gim * ei;
            vec3 psim = s.gre * ei + s.gim * er;
            vec3 ppre = p.gre * er - p.gim * ei;
            vec3 ppim = p.gre * ei + p.gim * er;
            const vec3 zsre = s.qre * er - s.qim * ei;
            const vec3 zsim = s.qre * ei + s.qim * er;
            const vec3 zpre = p.qre * er - p.qim * ei;
            const vec3 zpim = p.qre * ei + p.qim * er;
            vec3 bs = s.bnd, bp = p.bnd;
            const auto envelope_scale = static_cast<float>(envelope_count / table_end_nm);
            for (int m = 1; m <= max_terms; ++m) {
                const float tau = static_cast<float>(m) * opd;
                if (tau >= table_end) break;
                const vec3 b = bs + bp;
                const auto e = static_cast<float>(m_envelope[std::min(
                    static_cast<std::size_t>(tau * envelope_scale), m_envelope.size() - 1)]);
                if (largest(b) * e < tolerance) break;
                const Transform v = interpolated_transform(tau);
                const vec3 vre(static_cast<float>(v.re[0]), static_cast<float>(v.re[1]),
                               static_cast<float>(v.re[2]));
                const vec3 vim(static_cast<float>(v.im[0]), static_cast<float>(v.im[1]),
                               static_cast<float>(v.im[2]));
                colour = colour + ((psre + ppre) * vre - (psim + ppim) * vim);
                vec3 t = psre * zsre - psim * zsim;
                psim = psre * zsim + psim * zsre;
                psre = t;
                t = ppre * zpre - ppim * zpim;
                ppim = ppre * zpim + ppim * zpre;
                ppre = t;
                bs = bs * s.mq;
                bp = bp * p.mq;
                ++terms;
            }
            return {to_rgb(max(colour, 0.0f)), terms, Path::series};
        }
        resonance(q0, q1, vec3(q1), vec3(1.0f), q2sq, 1.0f, asre, asim);
        resonance(n0 * n0 * q1, n1 * n1 * q0, n2 * n2 * q1, vec3(n1 * n1), q2sq, -1.0f, apre,
                  apim);
        bsre = r01s * r12sre;
        bsim = r01s * r12sim;
        bpre = r01p * r12pre;
        bpim = r01p * r12pim;
        ts = 0.0f - t01s * t12s;
        tp = 0.0f - t01p * t12p;
    } else {
        path = Path::tunnelling;
        kappa = std::sqrt(-q1sq);
        const vec3 q2re = sqrt(max(q2sq, 0.0f));
        const vec3 q2im = sqrt(max(0.0f - q2sq, 0.0f));
        const vec3 k(kappa);
        vec3 r01sre, r01sim, r01pre, r01pim, r12sre, r12sim, r12pre, r12pim;
        ratio(vec3(q0), vec3(0.0f), vec3(0.0f), k, r01sre, r01sim);
        ratio(vec3(0.0f), vec3(n0 * n0 * kappa), vec3(n1 * n1 * q0), vec3(0.0f), r01pre, r01pim);
        ratio(vec3(0.0f), k, q2re, q2im, r12sre, r12sim);
        ratio(n1 * n1 * q2re, n1 * n1 * q2im, vec3(0.0f), n2 * n2 * kappa, r12pre, r12pim);
        quotient(-2.0f * k * q2im, 2.0f * k * (q0 + q2re), vec3(q0), k, q2re, k + q2im, asre,
                 asim);
        quotient(-2.0f * n1 * n1 * k * n0 * n0 * q2im,
                 2.0f * n1 * n1 * k * (n0 * n0 * q2re + n2 * n2 * q0), vec3(n1 * n1 * q0),
                 vec3(n0 * n0 * kappa), n1 * n1 * q2re, n2 * n2 * kappa + n1 * n1 * q2im, apre,
                 apim);
        bsre = r01sre * r12sre - r01sim * r12sim;
        bsim = r01sre * r12sim + r01sim * r12sre;
        bpre = r01pre * r12pre - r01pim * r12pim;
        bpim = r01pre * r12pim + r01pim * r12pre;
        ts = 4.0f * r01sim * r12sim;
        tp = 4.0f * r01pim * r12pim;
    }
    for (std::size_t j = 0; j < m_node_nu.size(); ++j) {
        const auto nu = static_cast<float>(m_node_nu[j]);
        vec3 r;
        if (kappa > 0.0f) {
            const float yre = expm1_neg(12.5663706f * d * kappa * nu);
            const float z = 1.0f + yre;
            r = node(asre, asim, bsre, bsim, z * ts, yre, 0.0f) +
                node(apre, apim, bpre, bpim, z * tp, yre, 0.0f);
        } else {
            const float h = 3.14159265f * centred(opd * nu);
            const float sh = taylor_sin(h);
            const float yre = -2.0f * sh * sh;
            const float yim = 2.0f * sh * std::cos(h);
            r = node(asre, asim, bsre, bsim, ts, yre, yim) +
                node(apre, apim, bpre, bpim, tp, yre, yim);
        }
        colour = colour + 0.5f * node_weight(j) * r;
    }
    return {to_rgb(max(colour, 0.0f)), terms, path};
}

}  // namespace irid
