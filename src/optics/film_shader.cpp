// FilmShader: the table, the GLSL chunk and its single-precision mirror. The GLSL body and the
// C++ mirror below follow each other function by function and line by line, so that a reviewer
// can check them side by side; docs/OPTICS.md ("In a renderer") derives the algorithm.

#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/color/spectrum.h>
#include <irid/error.h>
#include <irid/optics/film_shader.h>
#include <irid/text_input.h>

#include <fmt/core.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <complex>
#include <cstdint>
#include <numbers>

namespace irid {

ShaderLanguage parse_shader_language(std::string_view name) {
    if (name == "glsl") return ShaderLanguage::glsl;
    throw UnknownNameError("shader language " + quote_untrusted(name) + " is unknown; valid: glsl",
                           {"glsl"});
}

Colorimeter film_shader_colorimeter(std::string_view illuminant, std::string_view space) {
    const RgbSpace* rgb = find_rgb_space(space);
    if (rgb == nullptr) {
        throw UnknownNameError(fmt::format("space {} is unknown; valid: {}", quote_untrusted(space),
                                           fmt::join(rgb_space_names(), ", ")),
                               rgb_space_names());
    }
    return Colorimeter(illuminant_by_name(illuminant), Observer::cie1931_2deg, *rgb);
}

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

/// A GLSL float literal that reads back to the same float (9 significant digits; always with a
/// point or an exponent, as GLSL ES 3.00 §4.1.5 requires of a float constant).
std::string glsl_float(double v) {
    std::string s = fmt::format("{:.9g}", static_cast<float>(v));
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string glsl_vec3(const std::array<double, 3>& v) {
    return "vec3(" + glsl_float(v[0]) + ", " + glsl_float(v[1]) + ", " + glsl_float(v[2]) + ")";
}

// ---------------------------------------------------------------------------------------------
// The GLSL body. Constants (IRID_*) come before it, generated in FilmShader::glsl().
constexpr std::string_view glsl_body = R"glsl(
// Catmull-Rom weights of the four taps around a fraction f in [0, 1).
vec4 irid_catmull_rom(float f) {
    float f2 = f * f;
    float f3 = f2 * f;
    return 0.5 * vec4(-f3 + 2.0 * f2 - f, 3.0 * f3 - 5.0 * f2 + 2.0,
                      -3.0 * f3 + 4.0 * f2 + f, f3 - f2);
}

// V_c(tau), the demodulated transform of channel c's weights, interpolated through the table:
// texel k of row 0 (1) holds Re (Im) V at tau = (k - 1) * step. 0 <= tau < IRID_TABLE_END.
void irid_transform(float tau, out vec3 re, out vec3 im) {
    float x = tau * IRID_INV_STEP;
    float fx = min(floor(x), IRID_LAST_TAP);
    vec4 w = irid_catmull_rom(x - fx);
    int j = int(fx);
    re = w.x * texelFetch(iridFilmTable, ivec2(j, 0), 0).rgb
       + w.y * texelFetch(iridFilmTable, ivec2(j + 1, 0), 0).rgb
       + w.z * texelFetch(iridFilmTable, ivec2(j + 2, 0), 0).rgb
       + w.w * texelFetch(iridFilmTable, ivec2(j + 3, 0), 0).rgb;
    im = w.x * texelFetch(iridFilmTable, ivec2(j, 1), 0).rgb
       + w.y * texelFetch(iridFilmTable, ivec2(j + 1, 1), 0).rgb
       + w.z * texelFetch(iridFilmTable, ivec2(j + 2, 1), 0).rgb
       + w.w * texelFetch(iridFilmTable, ivec2(j + 3, 1), 0).rgb;
}

// The base's index per channel from glTF's F0 = ((n - 1) / (n + 1))^2.
vec3 irid_base_index(vec3 f0) {
    vec3 s = sqrt(clamp(f0, 0.0, 0.9999));
    return (1.0 + s) / (1.0 - s);
}

// The bare interface, ambient to base (q = N cos theta; past the base's critical angle, 1).
vec3 irid_bare(float n0, vec3 n2, float q0, vec3 q2sq) {
    vec3 q2 = sqrt(max(q2sq, 0.0));
    vec3 rs = (q0 - q2) / max(q0 + q2, 1e-30);
    vec3 up = n0 * n0 * q2;
    vec3 vp = n2 * n2 * q0;
    vec3 rp = (up - vp) / max(up + vp, 1e-30);
    vec3 r = 0.5 * (rs * rs + rp * rp);
    return mix(r, vec3(1.0), vec3(lessThanEqual(q2sq, vec3(0.0))));
}

// The film's top face (u - v) / (u + v), u, v >= 0, u + v > 0; t = 1 - r^2 without cancellation.
float irid_face(float u, float v, out float t) {
    float s = u + v;
    t = 4.0 * u * v / (s * s);
    return (u - v) / s;
}

// The base's face sgn (x - w) / (x + w) with w = k q2, q2 = sqrt(q2sq), x > 0; past the base's
// critical angle q2 = i sqrt(-q2sq) and the amplitude has modulus 1. t = 1 - |r|^2.
void irid_base_face(vec3 x, vec3 k, vec3 q2sq, float sgn, out vec3 re, out vec3 im, out vec3 t) {
    vec3 w = k * sqrt(abs(q2sq));
    vec3 s = x + w;
    vec3 d = x * x + w * w;
    vec3 tir = vec3(lessThan(q2sq, vec3(0.0)));
    re = sgn * mix((x - w) / s, (x * x - w * w) / d, tir);
    im = sgn * mix(vec3(0.0), -2.0 * x * w / d, tir);
    t = mix(4.0 * x * w / (s * s), vec3(0.0), tir);
}

// The series' coefficients for one polarisation: R = a0 + 2 Re sum_m g q^(m-1) e^(i m phi), with
// b = r12 (1 - r01^2), q = -r01 r12, a0 = r01^2 + |b|^2 / (1 - |q|^2),
// g = r01 b + |b|^2 q / (1 - |q|^2).
// Also bnd = |g| / (1 - |q|) (the sum of the terms' moduli) and mq = |q|.
void irid_coefficients(float r01, float t01, vec3 r12re, vec3 r12im, vec3 t12, out vec3 a0,
                       out vec3 gre, out vec3 gim, out vec3 qre, out vec3 qim,
                       out vec3 bnd, out vec3 mq) {
    qre = -r01 * r12re;
    qim = -r01 * r12im;
    vec3 omq = t01 + r01 * r01 * t12;
    vec3 e = (r12re * r12re + r12im * r12im) * t01 * min(t01 / max(omq, 1e-30), 1.0);
    a0 = r01 * r01 + e;
    gre = r01 * t01 * r12re + e * qre;
    gim = r01 * t01 * r12im + e * qim;
    mq = sqrt(qre * qre + qim * qim);
    bnd = sqrt(gre * gre + gim * gim) * (1.0 + mq) / max(omq, 1e-30);
}

vec2 irid_cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 irid_cdiv(vec2 a, vec2 b) { return irid_cmul(a, vec2(b.x, -b.y)) / max(dot(b, b), 1e-30); }
// N cos theta of a medium from its square, on the branch with Im >= 0.
vec2 irid_csqrt_q(float qsq) { return qsq >= 0.0 ? vec2(sqrt(qsq), 0.0) : vec2(0.0, sqrt(-qsq)); }

// The Airy reflectance at one wavenumber nu (unpolarised), any film: where the film is near or
// past its critical angle (q1 -> 0 or imaginary). q1sq is kept 1e-6 n1^2 from 0, where the
// formula is 0/0 (its limit is continuous there); d at most 1 mm, so that the phase stays finite.
float irid_airy_at(float n0, float n1, float q0, float q1sq, float n2, float q2sq, float d,
                   float nu) {
    d = min(d, 1e6);
    float eps = 1e-6 * n1 * n1;
    q1sq = abs(q1sq) < eps ? eps : q1sq;
    vec2 q1 = irid_csqrt_q(q1sq);
    vec2 q2 = irid_csqrt_q(q2sq);
    vec2 z = q1sq >= 0.0 ? vec2(cos(6.28318531 * fract(2.0 * d * q1.x * nu)),
                                sin(6.28318531 * fract(2.0 * d * q1.x * nu)))
                         : vec2(exp(-12.5663706 * d * q1.y * nu), 0.0);
    vec2 one = vec2(1.0, 0.0);
    vec2 r01s = irid_cdiv(vec2(q0, 0.0) - q1, vec2(q0, 0.0) + q1);
    vec2 r12s = irid_cdiv(q1 - q2, q1 + q2);
    vec2 r01p = irid_cdiv(n0 * n0 * q1 - vec2(n1 * n1 * q0, 0.0),
                          n0 * n0 * q1 + vec2(n1 * n1 * q0, 0.0));
    vec2 r12p = irid_cdiv(n1 * n1 * q2 - n2 * n2 * q1, n1 * n1 * q2 + n2 * n2 * q1);
    vec2 rs = irid_cdiv(r01s + irid_cmul(r12s, z), one + irid_cmul(r01s, irid_cmul(r12s, z)));
    vec2 rp = irid_cdiv(r01p + irid_cmul(r12p, z), one + irid_cmul(r01p, irid_cmul(r12p, z)));
    return 0.5 * (dot(rs, rs) + dot(rp, rp));
}

// The exact colour of a lossless film of index eta2 and thickness thinFilmThickness [nm] on a
// base of glTF F0 baseF0 (one index per channel), seen from a medium of index outsideIOR at an
// angle of cosine cosTheta1, in the working space's linear RGB (a perfect mirror is 1, 1, 1).
vec3 evalIridescence(float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0) {
    float n0 = max(outsideIOR, 1e-3);
    float n1 = max(eta2, 1e-3);
    float c0 = clamp(cosTheta1, 0.0, 1.0);
    float d = max(thinFilmThickness, 0.0);
    vec3 n2 = irid_base_index(baseF0);
    float q0 = n0 * c0;
    vec3 q2sq = (n2 - n0) * (n2 + n0) + q0 * q0;
    if (!(d > 0.0)) return irid_bare(n0, n2, q0, q2sq);
    float q1sq = (n1 - n0) * (n1 + n0) + q0 * q0;
    if (q1sq < IRID_MIN_FILM_COSINE_SQ * n1 * n1) {
        // A loop, not three calls: one copy of irid_airy_at, which costs a CPU rasteriser (that
        // runs both sides of a branch) a quarter less (docs/OPTICS.md, "In the browser").
        vec3 r;
        for (int c = 0; c < 3; ++c) r[c] = irid_airy_at(n0, n1, q0, q1sq, n2[c], q2sq[c], d, IRID_CENTRE[c]);
        return r;
    }
    float q1 = sqrt(q1sq);
    float t01s, t01p;
    float r01s = irid_face(q0, q1, t01s);
    float r01p = irid_face(n0 * n0 * q1, n1 * n1 * q0, t01p);
    vec3 r12re, r12im, t12;
    vec3 a0s, gsre, gsim, qsre, qsim, bs, mqs;
    irid_base_face(vec3(q1), vec3(1.0), q2sq, 1.0, r12re, r12im, t12);
    irid_coefficients(r01s, t01s, r12re, r12im, t12, a0s, gsre, gsim, qsre, qsim, bs, mqs);
    vec3 a0p, gpre, gpim, qpre, qpim, bp, mqp;
    irid_base_face(n2 * n2 * q1, vec3(n1 * n1), q2sq, -1.0, r12re, r12im, t12);
    irid_coefficients(r01p, t01p, r12re, r12im, t12, a0p, gpre, gpim, qpre, qpim, bp, mqp);
    vec3 colour = 0.5 * (a0s + a0p);
    float opd = 2.0 * d * q1;
    if (opd < IRID_TABLE_END) {
        // P = g e^(i theta_c) q_c^(m-1), theta_c = 2 pi opd nu_c: the m-th term is
        // Re(P V_c(m opd)).
        vec3 ph = 6.28318531 * fract(opd * IRID_CENTRE);
        vec3 er = cos(ph);
        vec3 ei = sin(ph);
        vec3 psre = gsre * er - gsim * ei;
        vec3 psim = gsre * ei + gsim * er;
        vec3 ppre = gpre * er - gpim * ei;
        vec3 ppim = gpre * ei + gpim * er;
        vec3 zsre = qsre * er - qsim * ei;
        vec3 zsim = qsre * ei + qsim * er;
        vec3 zpre = qpre * er - qpim * ei;
        vec3 zpim = qpre * ei + qpim * er;
        for (int m = 1; m <= IRID_MAX_TERMS; ++m) {
            float tau = float(m) * opd;
            if (tau >= IRID_TABLE_END) break;
            vec3 bound = bs + bp;
            float envelope = irid_envelope[min(int(tau * IRID_ENVELOPE_SCALE), IRID_ENVELOPE_LAST)];
            if (max(bound.r, max(bound.g, bound.b)) * envelope < IRID_TOLERANCE) break;
            vec3 vre, vim;
            irid_transform(tau, vre, vim);
            colour += (psre + ppre) * vre - (psim + ppim) * vim;
            vec3 t = psre * zsre - psim * zsim;
            psim = psre * zsim + psim * zsre;
            psre = t;
            t = ppre * zpre - ppim * zpim;
            ppim = ppre * zpim + ppim * zpre;
            ppre = t;
            bs *= mqs;
            bp *= mqp;
        }
    }
    return colour;
}
)glsl";

// ---------------------------------------------------------------------------------------------
// The mirror: GLSL's vec3, vec2 and built-ins in float, then the functions above in the same
// order and with the same names (irid_ dropped).

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
vec3 clamp(vec3 a, float lo, float hi) {
    return map(a, [lo, hi](float x) { return std::clamp(x, lo, hi); });
}
float fract(float x) {
    return x - std::floor(x);
}
vec3 fract(vec3 a) {
    return map(a, [](float x) { return fract(x); });
}
vec3 cos(vec3 a) {
    return map(a, [](float x) { return std::cos(x); });
}
vec3 sin(vec3 a) {
    return map(a, [](float x) { return std::sin(x); });
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

struct vec2 {
    float x = 0.0f, y = 0.0f;
};
vec2 operator+(vec2 a, vec2 b) {
    return {a.x + b.x, a.y + b.y};
}
vec2 operator-(vec2 a, vec2 b) {
    return {a.x - b.x, a.y - b.y};
}
vec2 operator*(float s, vec2 a) {
    return {s * a.x, s * a.y};
}
float dot(vec2 a, vec2 b) {
    return a.x * b.x + a.y * b.y;
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

vec2 cmul(vec2 a, vec2 b) {
    return {a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x};
}
vec2 cdiv(vec2 a, vec2 b) {
    const vec2 n = cmul(a, {b.x, -b.y});
    const float d = std::max(dot(b, b), 1e-30f);
    return {n.x / d, n.y / d};
}
vec2 csqrt_q(float qsq) {
    return qsq >= 0.0f ? vec2{std::sqrt(qsq), 0.0f} : vec2{0.0f, std::sqrt(-qsq)};
}

float airy_at(float n0, float n1, float q0, float q1sq, float n2, float q2sq, float d, float nu) {
    d = std::min(d, 1e6f);
    const float eps = 1e-6f * n1 * n1;
    q1sq = std::fabs(q1sq) < eps ? eps : q1sq;
    const vec2 q1 = csqrt_q(q1sq);
    const vec2 q2 = csqrt_q(q2sq);
    const vec2 z = q1sq >= 0.0f ? vec2{std::cos(6.28318531f * fract(2.0f * d * q1.x * nu)),
                                       std::sin(6.28318531f * fract(2.0f * d * q1.x * nu))}
                                : vec2{std::exp(-12.5663706f * d * q1.y * nu), 0.0f};
    const vec2 one{1.0f, 0.0f};
    const vec2 r01s = cdiv(vec2{q0, 0.0f} - q1, vec2{q0, 0.0f} + q1);
    const vec2 r12s = cdiv(q1 - q2, q1 + q2);
    const vec2 r01p =
        cdiv(n0 * n0 * q1 - vec2{n1 * n1 * q0, 0.0f}, n0 * n0 * q1 + vec2{n1 * n1 * q0, 0.0f});
    const vec2 r12p = cdiv(n1 * n1 * q2 - n2 * n2 * q1, n1 * n1 * q2 + n2 * n2 * q1);
    const vec2 rs = cdiv(r01s + cmul(r12s, z), one + cmul(r01s, cmul(r12s, z)));
    const vec2 rp = cdiv(r01p + cmul(r12p, z), one + cmul(r01p, cmul(r12p, z)));
    return 0.5f * (dot(rs, rs) + dot(rp, rp));
}

}  // namespace

FilmShader::FilmShader(const Colorimeter& colorimeter, std::string illuminant_name,
                       std::string space_name, int table_width)
    : m_width(table_width),
      m_illuminant(std::move(illuminant_name)),
      m_space(std::move(space_name)) {
    if (table_width < min_table_width || table_width > max_table_width) {
        throw Error(fmt::format("table width {} is out of range; valid: {} to {}", table_width,
                                min_table_width, max_table_width));
    }
    // The channels' weights on the 1 nm grid: the XYZ → RGB matrix (with the colorimeter's
    // adaptation) applied to the XYZ weights; its columns are the images of the unit vectors.
    const Rgb cx = colorimeter.linear_rgb(Xyz{1.0, 0.0, 0.0});
    const Rgb cy = colorimeter.linear_rgb(Xyz{0.0, 1.0, 0.0});
    const Rgb cz = colorimeter.linear_rgb(Xyz{0.0, 0.0, 1.0});
    const double rows[3][3] = {{cx.r, cy.r, cz.r}, {cx.g, cy.g, cz.g}, {cx.b, cy.b, cz.b}};
    m_wavenumber.resize(dense_sample_count);
    for (int c = 0; c < 3; ++c) m_weight[static_cast<std::size_t>(c)].resize(dense_sample_count);
    for (int i = 0; i < dense_sample_count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        m_wavenumber[k] = 1.0 / DenseSpectrum::wavelength_nm(i);
        const double x = colorimeter.weight_x()[i], y = colorimeter.weight_y()[i],
                     z = colorimeter.weight_z()[i];
        for (std::size_t c = 0; c < 3; ++c)
            m_weight[c][k] = rows[c][0] * x + rows[c][1] * y + rows[c][2] * z;
    }
    for (std::size_t c = 0; c < 3; ++c) {
        double sum = 0.0, moment = 0.0;
        for (int i = 0; i < dense_sample_count; ++i) {
            const auto k = static_cast<std::size_t>(i);
            sum += m_weight[c][k];
            moment += m_weight[c][k] * m_wavenumber[k];
        }
        m_white[c] = sum;
        m_centre[c] = moment / sum;
    }
    // The table: texel k at τ = (k − 1) step, Re in row 0, Im in row 1.
    m_table.assign(static_cast<std::size_t>(m_width * table_height * 4), 0.0f);
    for (int k = 0; k < m_width; ++k) {
        const Transform v = exact_transform(static_cast<double>(k - 1) * table_step_nm());
        for (std::size_t c = 0; c < 3; ++c) {
            m_table[static_cast<std::size_t>(4 * k) + c] = static_cast<float>(v.re[c]);
            m_table[static_cast<std::size_t>(4 * (m_width + k)) + c] = static_cast<float>(v.im[c]);
        }
    }
    // The envelope: max |V_c| over τ from each step on, sampled every eighth of the table's
    // step (where |V| varies by under 1 %: its fastest oscillation, the 380 nm edge against the
    // blue centre, has a period of about 2 000 nm), with 1 % to spare.
    const int fine = 8 * (default_table_width - 3);
    std::vector<double> largest(static_cast<std::size_t>(fine) + 1, 0.0);
    for (int i = fine; i >= 0; --i) {
        const Transform v = exact_transform(table_end_nm * i / fine);
        double m = 0.0;
        for (std::size_t c = 0; c < 3; ++c) m = std::max(m, std::hypot(v.re[c], v.im[c]));
        const auto k = static_cast<std::size_t>(i);
        largest[k] = i == fine ? m : std::max(m, largest[k + 1]);
    }
    for (int j = 0; j < envelope_count; ++j) {
        m_envelope[static_cast<std::size_t>(j)] =
            1.01 * largest[static_cast<std::size_t>(j * fine / envelope_count)];
    }
}

FilmShader::Transform FilmShader::exact_transform(double tau_nm) const noexcept {
    Transform v{};
    for (std::size_t c = 0; c < 3; ++c) {
        double re = 0.0, im = 0.0;
        for (std::size_t i = 0; i < m_wavenumber.size(); ++i) {
            const double phase = two_pi * tau_nm * (m_wavenumber[i] - m_centre[c]);
            re += m_weight[c][i] * std::cos(phase);
            im += m_weight[c][i] * std::sin(phase);
        }
        v.re[c] = re;
        v.im[c] = im;
    }
    return v;
}

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
    const float n0 = std::max(outside_ior, 1e-3f);
    const float n1 = std::max(eta2, 1e-3f);
    const float c0 = std::clamp(cos_theta1, 0.0f, 1.0f);
    const float d = std::max(thickness_nm, 0.0f);
    const vec3 n2 = base_index(vec3(base_f0[0], base_f0[1], base_f0[2]));
    const float q0 = n0 * c0;
    const vec3 q2sq = (n2 - n0) * (n2 + n0) + q0 * q0;
    if (!(d > 0.0f)) return {to_rgb(bare(n0, n2, q0, q2sq)), 0};
    const float q1sq = (n1 - n0) * (n1 + n0) + q0 * q0;
    constexpr auto min_cos_sq = static_cast<float>(min_film_cosine * min_film_cosine);
    if (q1sq < min_cos_sq * n1 * n1) {
        return {to_rgb(vec3(airy_at(n0, n1, q0, q1sq, n2.r, q2sq.r, d, centre.r),
                            airy_at(n0, n1, q0, q1sq, n2.g, q2sq.g, d, centre.g),
                            airy_at(n0, n1, q0, q1sq, n2.b, q2sq.b, d, centre.b))),
                0};
    }
    const float q1 = std::sqrt(q1sq);
    float t01s = 0.0f, t01p = 0.0f;
    const float r01s = face(q0, q1, t01s);
    const float r01p = face(n0 * n0 * q1, n1 * n1 * q0, t01p);
    vec3 r12re, r12im, t12;
    base_face(vec3(q1), vec3(1.0f), q2sq, 1.0f, r12re, r12im, t12);
    const Coefficients s = coefficients(r01s, t01s, r12re, r12im, t12);
    base_face(n2 * n2 * q1, vec3(n1 * n1), q2sq, -1.0f, r12re, r12im, t12);
    const Coefficients p = coefficients(r01p, t01p, r12re, r12im, t12);
    vec3 colour = 0.5f * (s.a0 + p.a0);
    const float opd = 2.0f * d * q1;
    const auto table_end = static_cast<float>(table_end_nm);
    int terms = 0;
    if (opd < table_end) {
        const vec3 ph = 6.28318531f * fract(opd * centre);
        const vec3 er = cos(ph);
        const vec3 ei = sin(ph);
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
            const vec3 bound = bs + bp;
            const auto e = static_cast<float>(m_envelope[std::min(
                static_cast<std::size_t>(tau * envelope_scale), m_envelope.size() - 1)]);
            if (std::max(bound.r, std::max(bound.g, bound.b)) * e <
                static_cast<float>(term_tolerance))
                break;
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
    }
    return {to_rgb(colour), terms};
}

std::string FilmShader::glsl() const {
    std::string out;
    out +=
        "// irid: the exact colour of a thin film, for KHR_materials_iridescence renderers "
        "(three.js\n";
    out += "// r187's evalIridescence signature), generated by irid shader --lang glsl for\n";
    out += "// illuminant " + m_illuminant + ", space " + m_space + ", CIE 1931 2 deg observer.\n";
    out +=
        "// GLSL ES 3.00: paste it into a fragment shader after three.js's own chunks, or after\n";
    out += "// the version line (300 es) and a highp float precision. Bind irid_film_table.f32\n";
    out += "// (described by irid_film_table.json) as an RGBA32F texture to iridFilmTable; it is\n";
    out += "// read with texelFetch, so NEAREST filtering suffices.\n";
    out += "// The algorithm: irid's docs/OPTICS.md, \"In a renderer\".\n";
    out += "uniform highp sampler2D iridFilmTable;\n\n";
    out += "// Each channel's centre wavenumber [1/nm], about which the table is demodulated.\n";
    out += "const vec3 IRID_CENTRE = " + glsl_vec3(m_centre) + ";\n";
    out +=
        "// 1 / the table's tau step [1/nm]; where its tau ends [nm] (terms past it are "
        "dropped).\n";
    out += "const float IRID_INV_STEP = " + glsl_float(1.0 / table_step_nm()) + ";\n";
    out += "const float IRID_TABLE_END = " + glsl_float(table_end_nm) + ";\n";
    out += "// The last texel at which the interpolant's four taps start (width - 4).\n";
    out += "const float IRID_LAST_TAP = " + glsl_float(m_width - 4) + ";\n";
    out += "// The term loop stops below this bound on the remaining terms (white = 1), or after\n";
    out += "// IRID_MAX_TERMS terms.\n";
    out += "const float IRID_TOLERANCE = " + glsl_float(term_tolerance) + ";\n";
    out += fmt::format("const int IRID_MAX_TERMS = {};\n", max_terms);
    out +=
        "// Under this cos^2 inside the film the Airy reflectance at the channels' centres is "
        "taken.\n";
    out +=
        "const float IRID_MIN_FILM_COSINE_SQ = " + glsl_float(min_film_cosine * min_film_cosine) +
        ";\n";
    out +=
        "// max |V_c| from tau = j IRID_TABLE_END / " + std::to_string(envelope_count) + " on.\n";
    out += "const float IRID_ENVELOPE_SCALE = " + glsl_float(envelope_count / table_end_nm) + ";\n";
    out += fmt::format("const int IRID_ENVELOPE_LAST = {};\n", envelope_count - 1);
    out +=
        fmt::format("const float irid_envelope[{}] = float[{}](", envelope_count, envelope_count);
    for (std::size_t j = 0; j < m_envelope.size(); ++j)
        out += (j == 0 ? "" : ", ") + glsl_float(m_envelope[j]);
    out += ");\n";
    out += glsl_body;
    return out;
}

std::string FilmShader::table_bytes() const {
    std::string out(m_table.size() * 4, '\0');
    for (std::size_t i = 0; i < m_table.size(); ++i) {
        const auto u = std::bit_cast<std::uint32_t>(m_table[i]);
        for (std::size_t b = 0; b < 4; ++b)
            out[4 * i + b] = static_cast<char>((u >> (8 * b)) & 0xffu);
    }
    return out;
}

std::string FilmShader::table_json() const {
    nlohmann::ordered_json j;
    j["width"] = m_width;
    j["height"] = table_height;
    j["uniform"] = uniform_name;
    j["illuminant"] = m_illuminant;
    j["space"] = m_space;
    j["filter"] = "nearest";
    return j.dump(2) + "\n";
}

std::vector<std::pair<std::string, std::string>> FilmShader::files(ShaderLanguage language) const {
    switch (language) {
        case ShaderLanguage::glsl: break;
    }
    return {{"irid_iridescence.glsl", glsl()},
            {"irid_film_table.f32", table_bytes()},
            {"irid_film_table.json", table_json()}};
}

}  // namespace irid
