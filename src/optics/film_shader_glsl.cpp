// FilmShader::glsl(): the GLSL ES 3.00 chunk. Its body follows the single-precision mirror
// (film_shader_mirror.cpp) function by function and line by line, so that a reviewer can check
// them side by side; docs/OPTICS.md ("In a renderer") derives the algorithm.

#include <irid/optics/film_shader.h>

#include "film_shader_text.h"

#include <fmt/core.h>

#include <string>
#include <string_view>

namespace irid {
namespace {

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

// A = 1 + r01 r12 without cancellation, for a real top face r01 = (u - v) / (u + v) and the
// base's face r12 = sgn (x - w) / (x + w), w = k q2 (q2 = i sqrt(-q2sq) past the base's critical
// angle): 2 (u x + v w) / D for sgn = 1, 2 (u w + v x) / D for sgn = -1, D = (u + v)(x + w).
void irid_resonance(float u, float v, vec3 x, vec3 k, vec3 q2sq, float sgn, out vec3 re, out vec3 im) {
    vec3 w = k * sqrt(abs(q2sq));
    vec3 tir = vec3(lessThan(q2sq, vec3(0.0)));
    vec3 wr = w * (1.0 - tir);
    vec3 wi = w * tir;
    float a = (sgn > 0.0 ? u : v) / (u + v);
    float b = (sgn > 0.0 ? v : u) / (u + v);
    vec3 nre = 2.0 * (a * x + b * wr);
    vec3 nim = 2.0 * b * wi;
    vec3 dre = x + wr;
    vec3 m = max(dre * dre + wi * wi, 1e-30);
    re = (nre * dre + nim * wi) / m;
    im = (nim * dre - nre * wi) / m;
}

// (a - b) / (a + b) for complex a, b per channel.
void irid_ratio(vec3 ar, vec3 ai, vec3 br, vec3 bi, out vec3 re, out vec3 im) {
    vec3 nr = ar - br;
    vec3 ni = ai - bi;
    vec3 dr = ar + br;
    vec3 di = ai + bi;
    vec3 m = max(dr * dr + di * di, 1e-30);
    re = (nr * dr + ni * di) / m;
    im = (ni * dr - nr * di) / m;
}

// a / (b c) for complex a, b, c per channel, b and c divided in turn (their product's modulus
// could pass a float's range).
void irid_quotient(vec3 ar, vec3 ai, vec3 br, vec3 bi, vec3 cr, vec3 ci, out vec3 re, out vec3 im) {
    vec3 m = max(br * br + bi * bi, 1e-30);
    vec3 xr = (ar * br + ai * bi) / m;
    vec3 xi = (ai * br - ar * bi) / m;
    m = max(cr * cr + ci * ci, 1e-30);
    re = (xr * cr + xi * ci) / m;
    im = (xi * cr - xr * ci) / m;
}

// sin h for |h| <= pi / 2, by its Taylor series where |h| < 0.5 (error below 6e-9 of h): a GPU's
// sin may err by 1e-4 absolutely (SwiftShader's does), which is all of a small phase's sine, at
// a thin film or one near its critical angle.
// The phase x [cycles] within half a cycle of 0, exactly (x - 0.5 would round a small x).
vec3 irid_centred(vec3 x) {
    vec3 f = fract(x);
    return f - vec3(greaterThan(f, vec3(0.5)));
}

vec3 irid_sin(vec3 h) {
    vec3 h2 = h * h;
    vec3 t = h * (1.0 - h2 / 6.0 * (1.0 - h2 / 20.0 * (1.0 - h2 / 42.0)));
    return mix(sin(h), t, vec3(lessThan(abs(h), vec3(0.5))));
}

// e^(-x) - 1 for x >= 0, by its Taylor series below 0.1 (error below 1.4e-9 of x).
float irid_expm1_neg(float x) {
    return x < 0.1 ? -x * (1.0 - x / 2.0 * (1.0 - x / 3.0 * (1.0 - x / 4.0 * (1.0 - x / 5.0))))
                   : exp(-x) - 1.0;
}

// One polarisation's Airy reflectance at a quadrature node: R = 1 + t / |A + B y|^2, with
// A = 1 + r01 r12, B = r01 r12 and y = z - 1 (z = e^(i phase), or e^(-4 pi d kappa nu) past the
// film's critical angle). For a film whose phase is real t = -(1 - r01^2)(1 - |r12|^2); past its
// critical angle t = 4 z Im r01 Im r12 (|r01| = 1). No digit is lost where both faces reflect
// almost all.
vec3 irid_node(vec3 are, vec3 aim, vec3 bre, vec3 bim, vec3 t, float yre, float yim) {
    vec3 wre = are + bre * yre - bim * yim;
    vec3 wim = aim + bre * yim + bim * yre;
    return clamp(1.0 + t / max(wre * wre + wim * wim, 1e-30), 0.0, 1.0);
}

// The exact colour of a lossless film of index eta2 and thickness thinFilmThickness [nm] on a
// base of glTF F0 baseF0 (one index per channel), seen from a medium of index outsideIOR at an
// angle of cosine cosTheta1, in the working space's linear RGB (a perfect mirror is 1, 1, 1),
// negative channels (a saturated colour outside the space) clamped to 0.
vec3 evalIridescence(float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0) {
    float n0 = clamp(outsideIOR, 1e-3, IRID_MAX_INDEX);
    float n1 = clamp(eta2, 1e-3, IRID_MAX_INDEX);
    float c0 = clamp(cosTheta1, 0.0, 1.0);
    float d = clamp(thinFilmThickness, 0.0, IRID_MAX_THICKNESS);
    vec3 n2 = irid_base_index(baseF0);
    float q0 = n0 * c0;
    vec3 q2sq = (n2 - n0) * (n2 + n0) + q0 * q0;
    if (!(d > 0.0)) return irid_bare(n0, n2, q0, q2sq);
    float q1sq = (n1 - n0) * (n1 + n0) + q0 * q0;
    float eps = IRID_MIN_FILM_Q_SQ * n1 * n1;
    vec3 colour = vec3(0.0);
    // The quadrature's amplitudes per polarisation (s, p): A = 1 + r01 r12, B = r01 r12, t.
    vec3 asre, asim, bsre, bsim, ts, apre, apim, bpre, bpim, tp;
    float opd = 0.0;
    float kappa = 0.0;
    if (q1sq > -eps) {
        // The phase is real: the series, unless it needs more than IRID_MAX_TERMS terms.
        float q1 = sqrt(max(q1sq, eps));
        float t01s, t01p;
        float r01s = irid_face(q0, q1, t01s);
        float r01p = irid_face(n0 * n0 * q1, n1 * n1 * q0, t01p);
        vec3 r12sre, r12sim, t12s, r12pre, r12pim, t12p;
        irid_base_face(vec3(q1), vec3(1.0), q2sq, 1.0, r12sre, r12sim, t12s);
        irid_base_face(n2 * n2 * q1, vec3(n1 * n1), q2sq, -1.0, r12pre, r12pim, t12p);
        vec3 a0s, gsre, gsim, qsre, qsim, bs, mqs;
        irid_coefficients(r01s, t01s, r12sre, r12sim, t12s, a0s, gsre, gsim, qsre, qsim, bs, mqs);
        vec3 a0p, gpre, gpim, qpre, qpim, bp, mqp;
        irid_coefficients(r01p, t01p, r12pre, r12pim, t12p, a0p, gpre, gpim, qpre, qpim, bp, mqp);
        opd = max(2.0 * d * q1, 1e-30);
        // The terms the series needs: until the bound on the rest falls below the tolerance,
        // or the table ends.
        vec3 b = bs + bp;
        float bound = max(max(b.r, max(b.g, b.b)) * irid_envelope[0], 1e-30);
        vec3 mqv = max(mqs, mqp);
        float mq = clamp(max(mqv.r, max(mqv.g, mqv.b)), 1e-30, 0.99999994);
        float needed = min(log(IRID_TOLERANCE / bound) / log(mq), IRID_TABLE_END / opd);
        if (needed <= float(IRID_MAX_TERMS)) {
            colour = 0.5 * (a0s + a0p);
            // P = g e^(i theta_c) q_c^(m-1), theta_c = 2 pi opd nu_c: the m-th term is
            // Re(P V_c(m opd)).
            // e^(2 pi i opd nu_c) = e^(2 i h), h = pi f, f the phase in cycles within half a cycle of
            // 0, from sin h and cos h.
            vec3 h = 3.14159265 * irid_centred(opd * IRID_CENTRE);
            vec3 sh = irid_sin(h);
            vec3 er = 1.0 - 2.0 * sh * sh;
            vec3 ei = 2.0 * sh * cos(h);
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
            return max(colour, vec3(0.0));
        }
        // A film of short path whose faces both reflect almost all: its reflectance is smooth
        // across the spectrum, and the quadrature takes it.
        irid_resonance(q0, q1, vec3(q1), vec3(1.0), q2sq, 1.0, asre, asim);
        irid_resonance(n0 * n0 * q1, n1 * n1 * q0, n2 * n2 * q1, vec3(n1 * n1), q2sq, -1.0, apre, apim);
        bsre = r01s * r12sre;
        bsim = r01s * r12sim;
        bpre = r01p * r12pre;
        bpim = r01p * r12pim;
        ts = -t01s * t12s;
        tp = -t01p * t12p;
    } else {
        // Past the film's critical angle, N1 cos theta1 = i kappa: the light tunnels through
        // the film, whose reflectance is smooth in wavenumber.
        kappa = sqrt(-q1sq);
        vec3 q2re = sqrt(max(q2sq, 0.0));
        vec3 q2im = sqrt(max(-q2sq, 0.0));
        vec3 k = vec3(kappa);
        vec3 r01sre, r01sim, r01pre, r01pim, r12sre, r12sim, r12pre, r12pim;
        irid_ratio(vec3(q0), vec3(0.0), vec3(0.0), k, r01sre, r01sim);
        irid_ratio(vec3(0.0), vec3(n0 * n0 * kappa), vec3(n1 * n1 * q0), vec3(0.0), r01pre, r01pim);
        irid_ratio(vec3(0.0), k, q2re, q2im, r12sre, r12sim);
        irid_ratio(n1 * n1 * q2re, n1 * n1 * q2im, vec3(0.0), n2 * n2 * kappa, r12pre, r12pim);
        // A = 1 + r01 r12 = 2 (u x + v w) / ((u + v)(x + w)) (s) and 2 (u w + v x) / (...) (p),
        // each term a multiple of kappa.
        irid_quotient(-2.0 * k * q2im, 2.0 * k * (q0 + q2re), vec3(q0), k, q2re, k + q2im, asre, asim);
        irid_quotient(-2.0 * n1 * n1 * k * n0 * n0 * q2im,
                      2.0 * n1 * n1 * k * (n0 * n0 * q2re + n2 * n2 * q0),
                      vec3(n1 * n1 * q0), vec3(n0 * n0 * kappa),
                      n1 * n1 * q2re, n2 * n2 * kappa + n1 * n1 * q2im, apre, apim);
        bsre = r01sre * r12sre - r01sim * r12sim;
        bsim = r01sre * r12sim + r01sim * r12sre;
        bpre = r01pre * r12pre - r01pim * r12pim;
        bpim = r01pre * r12pim + r01pim * r12pre;
        ts = 4.0 * r01sim * r12sim;
        tp = 4.0 * r01pim * r12pim;
    }
    for (int j = 0; j < IRID_NODES; ++j) {
        float nu = irid_node_nu[j];
        vec3 r;
        if (kappa > 0.0) {
            float yre = irid_expm1_neg(12.5663706 * d * kappa * nu);
            float z = 1.0 + yre;
            r = irid_node(asre, asim, bsre, bsim, z * ts, yre, 0.0)
              + irid_node(apre, apim, bpre, bpim, z * tp, yre, 0.0);
        } else {
            // y = e^(2i h) - 1 = (-2 sin^2 h, 2 sin h cos h).
            float h = 3.14159265 * irid_centred(vec3(opd * nu)).x;
            float sh = irid_sin(vec3(h)).x;
            float yre = -2.0 * sh * sh;
            float yim = 2.0 * sh * cos(h);
            r = irid_node(asre, asim, bsre, bsim, ts, yre, yim)
              + irid_node(apre, apim, bpre, bpim, tp, yre, yim);
        }
        colour += 0.5 * irid_node_weight[j] * r;
    }
    return max(colour, vec3(0.0));
}
)glsl";

}  // namespace

std::string FilmShader::glsl() const {
    using film_shader_text::float_literal;
    using film_shader_text::vec3_literal;
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
    out += "const vec3 IRID_CENTRE = " + vec3_literal(m_centre) + ";\n";
    out +=
        "// 1 / the table's tau step [1/nm]; where its tau ends [nm] (terms past it are "
        "dropped).\n";
    out += "const float IRID_INV_STEP = " + float_literal(1.0 / table_step_nm()) + ";\n";
    out += "const float IRID_TABLE_END = " + float_literal(table_end_nm) + ";\n";
    out += "// The last texel at which the interpolant's four taps start (width - 4).\n";
    out += "const float IRID_LAST_TAP = " + float_literal(m_width - 4) + ";\n";
    out += "// The term loop stops below this bound on the remaining terms (white = 1); a film\n";
    out += "// whose series needs more than IRID_MAX_TERMS terms is taken by the quadrature.\n";
    out += "const float IRID_TOLERANCE = " + float_literal(term_tolerance) + ";\n";
    out += fmt::format("const int IRID_MAX_TERMS = {};\n", max_terms);
    out += "// Indices are taken up to this, thicknesses up to this [nm].\n";
    out += "const float IRID_MAX_INDEX = " + float_literal(max_index) + ";\n";
    out += "const float IRID_MAX_THICKNESS = " + float_literal(max_thickness_nm) + ";\n";
    out += "// (N1 cos theta1)^2 is kept this many n1^2 from 0, where the faces are 0/0.\n";
    out += "const float IRID_MIN_FILM_Q_SQ = " + float_literal(min_film_q_sq) + ";\n";
    out +=
        "// max |V_c| from tau = j IRID_TABLE_END / " + std::to_string(envelope_count) + " on.\n";
    out += "const float IRID_ENVELOPE_SCALE = " + float_literal(envelope_count / table_end_nm) +
           ";\n";
    out += fmt::format("const int IRID_ENVELOPE_LAST = {};\n", envelope_count - 1);
    out +=
        fmt::format("const float irid_envelope[{}] = float[{}](", envelope_count, envelope_count);
    for (std::size_t j = 0; j < m_envelope.size(); ++j)
        out += (j == 0 ? "" : ", ") + float_literal(m_envelope[j]);
    out += ");\n";
    out += "// The quadrature: the colour is sum_j irid_node_weight[j] R(irid_node_nu[j]), the\n";
    out += "// 1 nm sum of the polynomial through the reflectance at these wavenumbers [1/nm].\n";
    out += fmt::format("const int IRID_NODES = {};\n", quadrature_nodes);
    out += fmt::format("const float irid_node_nu[{}] = float[{}](", quadrature_nodes,
                       quadrature_nodes);
    for (std::size_t j = 0; j < m_node_nu.size(); ++j)
        out += (j == 0 ? "" : ", ") + float_literal(m_node_nu[j]);
    out += ");\n";
    out += fmt::format("const vec3 irid_node_weight[{}] = vec3[{}](\n", quadrature_nodes,
                       quadrature_nodes);
    for (std::size_t j = 0; j < m_node_weight.size(); ++j)
        out += "    " + vec3_literal(m_node_weight[j]) + (j + 1 < m_node_weight.size() ? ",\n" : ");\n");
    out += glsl_body;
    return out;
}

}  // namespace irid
