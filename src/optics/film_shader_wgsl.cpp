// FilmShader::wgsl(): the chunk in WGSL (WebGPU, and the engines that write WGSL directly). It is
// the GLSL body (film_shader_glsl.cpp) function by function, with WGSL's forms: structures where
// GLSL has out parameters, select() where GLSL has mix() of a boolean or ?:, and the table passed
// as a texture_2d<f32> parameter, so that a node system (three.js's TSL) can bind it itself.

#include <irid/optics/film_shader.h>

#include "film_shader_text.h"

#include <fmt/core.h>

#include <string>
#include <string_view>

namespace irid {
namespace {

constexpr std::string_view wgsl_body = R"wgsl(
struct IridComplex3 {
    re: vec3f,
    im: vec3f,
}

struct IridFace {
    r: f32,
    t: f32,
}

struct IridBaseFace {
    re: vec3f,
    im: vec3f,
    t: vec3f,
}

struct IridCoefficients {
    a0: vec3f,
    gre: vec3f,
    gim: vec3f,
    qre: vec3f,
    qim: vec3f,
    bnd: vec3f,
    mq: vec3f,
}

// Catmull-Rom weights of the four taps around a fraction f in [0, 1).
fn irid_catmull_rom(f: f32) -> vec4f {
    let f2 = f * f;
    let f3 = f2 * f;
    return 0.5 * vec4f(-f3 + 2.0 * f2 - f, 3.0 * f3 - 5.0 * f2 + 2.0,
                       -3.0 * f3 + 4.0 * f2 + f, f3 - f2);
}

// V_c(tau), the demodulated transform of channel c's weights, interpolated through the table:
// texel k of row 0 (1) holds Re (Im) V at tau = (k - 1) * step. 0 <= tau < IRID_TABLE_END.
fn irid_transform(table: texture_2d<f32>, tau: f32) -> IridComplex3 {
    let x = tau * IRID_INV_STEP;
    let fx = min(floor(x), IRID_LAST_TAP);
    let w = irid_catmull_rom(x - fx);
    let j = i32(fx);
    let re = w.x * textureLoad(table, vec2i(j, 0), 0).rgb
           + w.y * textureLoad(table, vec2i(j + 1, 0), 0).rgb
           + w.z * textureLoad(table, vec2i(j + 2, 0), 0).rgb
           + w.w * textureLoad(table, vec2i(j + 3, 0), 0).rgb;
    let im = w.x * textureLoad(table, vec2i(j, 1), 0).rgb
           + w.y * textureLoad(table, vec2i(j + 1, 1), 0).rgb
           + w.z * textureLoad(table, vec2i(j + 2, 1), 0).rgb
           + w.w * textureLoad(table, vec2i(j + 3, 1), 0).rgb;
    return IridComplex3(re, im);
}

// The base's index per channel from glTF's F0 = ((n - 1) / (n + 1))^2.
fn irid_base_index(f0: vec3f) -> vec3f {
    let s = sqrt(clamp(f0, vec3f(0.0), vec3f(0.9999)));
    return (1.0 + s) / (1.0 - s);
}

// The bare interface, ambient to base (q = N cos theta; past the base's critical angle, 1).
fn irid_bare(n0: f32, n2: vec3f, q0: f32, q2sq: vec3f) -> vec3f {
    let q2 = sqrt(max(q2sq, vec3f(0.0)));
    let rs = (q0 - q2) / max(q0 + q2, vec3f(1e-30));
    let up = n0 * n0 * q2;
    let vp = n2 * n2 * q0;
    let rp = (up - vp) / max(up + vp, vec3f(1e-30));
    let r = 0.5 * (rs * rs + rp * rp);
    return select(r, vec3f(1.0), q2sq <= vec3f(0.0));
}

// The film's top face (u - v) / (u + v), u, v >= 0, u + v > 0; t = 1 - r^2 without cancellation.
fn irid_face(u: f32, v: f32) -> IridFace {
    let s = u + v;
    return IridFace((u - v) / s, 4.0 * u * v / (s * s));
}

// The base's face sgn (x - w) / (x + w) with w = k q2, q2 = sqrt(q2sq), x > 0; past the base's
// critical angle q2 = i sqrt(-q2sq) and the amplitude has modulus 1. t = 1 - |r|^2.
fn irid_base_face(x: vec3f, k: vec3f, q2sq: vec3f, sgn: f32) -> IridBaseFace {
    let w = k * sqrt(abs(q2sq));
    let s = x + w;
    let d = x * x + w * w;
    let tir = q2sq < vec3f(0.0);
    let re = sgn * select((x - w) / s, (x * x - w * w) / d, tir);
    let im = sgn * select(vec3f(0.0), -2.0 * x * w / d, tir);
    let t = select(4.0 * x * w / (s * s), vec3f(0.0), tir);
    return IridBaseFace(re, im, t);
}

// The series' coefficients for one polarisation: R = a0 + 2 Re sum_m g q^(m-1) e^(i m phi), with
// b = r12 (1 - r01^2), q = -r01 r12, a0 = r01^2 + |b|^2 / (1 - |q|^2),
// g = r01 b + |b|^2 q / (1 - |q|^2).
// Also bnd = |g| / (1 - |q|) (the sum of the terms' moduli) and mq = |q|.
fn irid_coefficients(r01: f32, t01: f32, r12: IridBaseFace) -> IridCoefficients {
    let qre = -r01 * r12.re;
    let qim = -r01 * r12.im;
    let omq = t01 + r01 * r01 * r12.t;
    let e = (r12.re * r12.re + r12.im * r12.im) * t01 * min(t01 / max(omq, vec3f(1e-30)), vec3f(1.0));
    let a0 = r01 * r01 + e;
    let gre = r01 * t01 * r12.re + e * qre;
    let gim = r01 * t01 * r12.im + e * qim;
    let mq = sqrt(qre * qre + qim * qim);
    let bnd = sqrt(gre * gre + gim * gim) * (1.0 + mq) / max(omq, vec3f(1e-30));
    return IridCoefficients(a0, gre, gim, qre, qim, bnd, mq);
}

// A = 1 + r01 r12 without cancellation, for a real top face r01 = (u - v) / (u + v) and the
// base's face r12 = sgn (x - w) / (x + w), w = k q2 (q2 = i sqrt(-q2sq) past the base's critical
// angle): 2 (u x + v w) / D for sgn = 1, 2 (u w + v x) / D for sgn = -1, D = (u + v)(x + w).
fn irid_resonance(u: f32, v: f32, x: vec3f, k: vec3f, q2sq: vec3f, sgn: f32) -> IridComplex3 {
    let w = k * sqrt(abs(q2sq));
    let tir = select(vec3f(0.0), vec3f(1.0), q2sq < vec3f(0.0));
    let wr = w * (1.0 - tir);
    let wi = w * tir;
    let a = select(v, u, sgn > 0.0) / (u + v);
    let b = select(u, v, sgn > 0.0) / (u + v);
    let nre = 2.0 * (a * x + b * wr);
    let nim = 2.0 * b * wi;
    let dre = x + wr;
    let m = max(dre * dre + wi * wi, vec3f(1e-30));
    return IridComplex3((nre * dre + nim * wi) / m, (nim * dre - nre * wi) / m);
}

// (a - b) / (a + b) for complex a, b per channel.
fn irid_ratio(ar: vec3f, ai: vec3f, br: vec3f, bi: vec3f) -> IridComplex3 {
    let nr = ar - br;
    let ni = ai - bi;
    let dr = ar + br;
    let di = ai + bi;
    let m = max(dr * dr + di * di, vec3f(1e-30));
    return IridComplex3((nr * dr + ni * di) / m, (ni * dr - nr * di) / m);
}

// a / (b c) for complex a, b, c per channel, b and c divided in turn (their product's modulus
// could pass a float's range).
fn irid_quotient(ar: vec3f, ai: vec3f, br: vec3f, bi: vec3f, cr: vec3f, ci: vec3f) -> IridComplex3 {
    var m = max(br * br + bi * bi, vec3f(1e-30));
    let xr = (ar * br + ai * bi) / m;
    let xi = (ai * br - ar * bi) / m;
    m = max(cr * cr + ci * ci, vec3f(1e-30));
    return IridComplex3((xr * cr + xi * ci) / m, (xi * cr - xr * ci) / m);
}

// The phase x [cycles] within half a cycle of 0, exactly (x - 0.5 would round a small x).
fn irid_centred(x: vec3f) -> vec3f {
    let f = fract(x);
    return f - select(vec3f(0.0), vec3f(1.0), f > vec3f(0.5));
}

// sin h for |h| <= pi / 2, by its Taylor series where |h| < 0.5 (error below 6e-9 of h): a GPU's
// sin may err by 1e-4 absolutely, which is all of a small phase's sine.
fn irid_sin(h: vec3f) -> vec3f {
    let h2 = h * h;
    let t = h * (1.0 - h2 / 6.0 * (1.0 - h2 / 20.0 * (1.0 - h2 / 42.0)));
    return select(sin(h), t, abs(h) < vec3f(0.5));
}

// e^(-x) - 1 for x >= 0, by its Taylor series below 0.1 (error below 1.4e-9 of x).
fn irid_expm1_neg(x: f32) -> f32 {
    return select(exp(-x) - 1.0,
                  -x * (1.0 - x / 2.0 * (1.0 - x / 3.0 * (1.0 - x / 4.0 * (1.0 - x / 5.0)))),
                  x < 0.1);
}

// One polarisation's Airy reflectance at a quadrature node: R = 1 + t / |A + B y|^2, with
// A = 1 + r01 r12, B = r01 r12 and y = z - 1 (z = e^(i phase), or e^(-4 pi d kappa nu) past the
// film's critical angle).
fn irid_node(a: IridComplex3, b: IridComplex3, t: vec3f, yre: f32, yim: f32) -> vec3f {
    let wre = a.re + b.re * yre - b.im * yim;
    let wim = a.im + b.re * yim + b.im * yre;
    return clamp(1.0 + t / max(wre * wre + wim * wim, vec3f(1e-30)), vec3f(0.0), vec3f(1.0));
}

// The exact colour of a lossless film of index eta2 and thickness thinFilmThickness [nm] on a
// base of glTF F0 baseF0 (one index per channel), seen from a medium of index outsideIOR at an
// angle of cosine cosTheta1, in the working space's linear RGB (a perfect mirror is 1, 1, 1),
// negative channels clamped to 0; `table` is irid_film_table.f32 as an rgba32float texture.
fn irid_eval(table: texture_2d<f32>, outsideIOR: f32, eta2: f32, cosTheta1: f32, thinFilmThickness: f32, baseF0: vec3f) -> vec3f {
    let n0 = clamp(outsideIOR, 1e-3, IRID_MAX_INDEX);
    let n1 = clamp(eta2, 1e-3, IRID_MAX_INDEX);
    let c0 = clamp(cosTheta1, 0.0, 1.0);
    let d = clamp(thinFilmThickness, 0.0, IRID_MAX_THICKNESS);
    let n2 = irid_base_index(baseF0);
    let q0 = n0 * c0;
    let q2sq = (n2 - n0) * (n2 + n0) + q0 * q0;
    if (!(d > 0.0)) {
        return irid_bare(n0, n2, q0, q2sq);
    }
    let q1sq = (n1 - n0) * (n1 + n0) + q0 * q0;
    let eps = IRID_MIN_FILM_Q_SQ * n1 * n1;
    var colour = vec3f(0.0);
    // The quadrature's amplitudes per polarisation (s, p): A = 1 + r01 r12, B = r01 r12, t.
    var as_ = IridComplex3(vec3f(0.0), vec3f(0.0));
    var ap = as_;
    var bs_ = as_;
    var bp_ = as_;
    var ts = vec3f(0.0);
    var tp = vec3f(0.0);
    var opd = 0.0;
    var kappa = 0.0;
    if (q1sq > -eps) {
        // The phase is real: the series, unless it needs more than IRID_MAX_TERMS terms.
        let q1 = sqrt(max(q1sq, eps));
        let fs = irid_face(q0, q1);
        let fp = irid_face(n0 * n0 * q1, n1 * n1 * q0);
        let r12s = irid_base_face(vec3f(q1), vec3f(1.0), q2sq, 1.0);
        let r12p = irid_base_face(n2 * n2 * q1, vec3f(n1 * n1), q2sq, -1.0);
        let s = irid_coefficients(fs.r, fs.t, r12s);
        let p = irid_coefficients(fp.r, fp.t, r12p);
        opd = max(2.0 * d * q1, 1e-30);
        // The terms the series needs: until the bound on the rest falls below the tolerance,
        // or the table ends.
        let b = s.bnd + p.bnd;
        let bound = max(max(b.r, max(b.g, b.b)) * irid_envelope[0], 1e-30);
        let mqv = max(s.mq, p.mq);
        let mq = clamp(max(mqv.r, max(mqv.g, mqv.b)), 1e-30, 0.99999994);
        let needed = min(log(IRID_TOLERANCE / bound) / log(mq), IRID_TABLE_END / opd);
        if (needed <= f32(IRID_MAX_TERMS)) {
            colour = 0.5 * (s.a0 + p.a0);
            // e^(2 pi i opd nu_c) = e^(2 i h), h = pi f, f the phase in cycles within half a
            // cycle of 0, from sin h and cos h.
            let h = 3.14159265 * irid_centred(opd * IRID_CENTRE);
            let sh = irid_sin(h);
            let er = 1.0 - 2.0 * sh * sh;
            let ei = 2.0 * sh * cos(h);
            var psre = s.gre * er - s.gim * ei;
            var psim = s.gre * ei + s.gim * er;
            var ppre = p.gre * er - p.gim * ei;
            var ppim = p.gre * ei + p.gim * er;
            let zsre = s.qre * er - s.qim * ei;
            let zsim = s.qre * ei + s.qim * er;
            let zpre = p.qre * er - p.qim * ei;
            let zpim = p.qre * ei + p.qim * er;
            var bs = s.bnd;
            var bp = p.bnd;
            for (var m = 1; m <= IRID_MAX_TERMS; m++) {
                let tau = f32(m) * opd;
                if (tau >= IRID_TABLE_END) {
                    break;
                }
                let bound_m = bs + bp;
                let envelope = irid_envelope[min(i32(tau * IRID_ENVELOPE_SCALE), IRID_ENVELOPE_LAST)];
                if (max(bound_m.r, max(bound_m.g, bound_m.b)) * envelope < IRID_TOLERANCE) {
                    break;
                }
                let v = irid_transform(table, tau);
                colour += (psre + ppre) * v.re - (psim + ppim) * v.im;
                var t = psre * zsre - psim * zsim;
                psim = psre * zsim + psim * zsre;
                psre = t;
                t = ppre * zpre - ppim * zpim;
                ppim = ppre * zpim + ppim * zpre;
                ppre = t;
                bs *= s.mq;
                bp *= p.mq;
            }
            return max(colour, vec3f(0.0));
        }
        // A film of short path whose faces both reflect almost all: its reflectance is smooth
        // across the spectrum, and the quadrature takes it.
        as_ = irid_resonance(q0, q1, vec3f(q1), vec3f(1.0), q2sq, 1.0);
        ap = irid_resonance(n0 * n0 * q1, n1 * n1 * q0, n2 * n2 * q1, vec3f(n1 * n1), q2sq, -1.0);
        bs_ = IridComplex3(fs.r * r12s.re, fs.r * r12s.im);
        bp_ = IridComplex3(fp.r * r12p.re, fp.r * r12p.im);
        ts = -fs.t * r12s.t;
        tp = -fp.t * r12p.t;
    } else {
        // Past the film's critical angle, N1 cos theta1 = i kappa: the light tunnels through
        // the film, whose reflectance is smooth in wavenumber.
        kappa = sqrt(-q1sq);
        let q2re = sqrt(max(q2sq, vec3f(0.0)));
        let q2im = sqrt(max(-q2sq, vec3f(0.0)));
        let k = vec3f(kappa);
        let zero = vec3f(0.0);
        let r01s = irid_ratio(vec3f(q0), zero, zero, k);
        let r01p = irid_ratio(zero, vec3f(n0 * n0 * kappa), vec3f(n1 * n1 * q0), zero);
        let r12s = irid_ratio(zero, k, q2re, q2im);
        let r12p = irid_ratio(n1 * n1 * q2re, n1 * n1 * q2im, zero, n2 * n2 * kappa);
        // A = 1 + r01 r12 = 2 (u x + v w) / ((u + v)(x + w)) (s) and 2 (u w + v x) / (...) (p),
        // each term a multiple of kappa.
        as_ = irid_quotient(-2.0 * k * q2im, 2.0 * k * (q0 + q2re), vec3f(q0), k, q2re, k + q2im);
        ap = irid_quotient(-2.0 * n1 * n1 * k * n0 * n0 * q2im,
                           2.0 * n1 * n1 * k * (n0 * n0 * q2re + n2 * n2 * q0),
                           vec3f(n1 * n1 * q0), vec3f(n0 * n0 * kappa),
                           n1 * n1 * q2re, n2 * n2 * kappa + n1 * n1 * q2im);
        bs_ = IridComplex3(r01s.re * r12s.re - r01s.im * r12s.im, r01s.re * r12s.im + r01s.im * r12s.re);
        bp_ = IridComplex3(r01p.re * r12p.re - r01p.im * r12p.im, r01p.re * r12p.im + r01p.im * r12p.re);
        ts = 4.0 * r01s.im * r12s.im;
        tp = 4.0 * r01p.im * r12p.im;
    }
    for (var j = 0; j < IRID_NODES; j++) {
        let nu = irid_node_nu[j];
        var r: vec3f;
        if (kappa > 0.0) {
            let yre = irid_expm1_neg(12.5663706 * d * kappa * nu);
            let z = 1.0 + yre;
            r = irid_node(as_, bs_, z * ts, yre, 0.0) + irid_node(ap, bp_, z * tp, yre, 0.0);
        } else {
            let h = 3.14159265 * irid_centred(vec3f(opd * nu)).x;
            let sh = irid_sin(vec3f(h)).x;
            let yre = -2.0 * sh * sh;
            let yim = 2.0 * sh * cos(h);
            r = irid_node(as_, bs_, ts, yre, yim) + irid_node(ap, bp_, tp, yre, yim);
        }
        colour += 0.5 * irid_node_weight[j] * r;
    }
    return max(colour, vec3f(0.0));
}
)wgsl";

/// The module-scope binding and evalIridescence of the GLSL signature; a node system that binds
/// the table itself takes the text before it (FilmShader::wgsl_binding_marker).
constexpr std::string_view wgsl_binding = R"wgsl(
// Bind irid_film_table.f32 here as an rgba32float texture (read with textureLoad: no sampler, no
// filtering); renumber the group and binding to the pipeline's layout.
@group(0) @binding(0) var iridFilmTable: texture_2d<f32>;

fn evalIridescence(outsideIOR: f32, eta2: f32, cosTheta1: f32, thinFilmThickness: f32, baseF0: vec3f) -> vec3f {
    return irid_eval(iridFilmTable, outsideIOR, eta2, cosTheta1, thinFilmThickness, baseF0);
}
)wgsl";


}  // namespace

std::string FilmShader::wgsl() const {
    using film_shader_text::float_literal;
    std::string out;
    out += "// irid: the exact colour of a thin film, for KHR_materials_iridescence renderers, in WGSL\n";
    out += "// (the signature of three.js r187's evalIridescence), generated by irid shader --lang wgsl\n";
    out += "// for illuminant " + m_illuminant + ", space " + m_space + ", CIE 1931 2 deg observer.\n";
    out += "// irid_eval takes the table as a texture_2d<f32> (irid_film_table.f32, described by\n";
    out += "// irid_film_table.json, as an rgba32float texture); evalIridescence, at the end, reads it\n";
    out += "// from a module-scope binding. The algorithm: irid's docs/OPTICS.md, \"In a renderer\".\n";
    out += "\n// Each channel's centre wavenumber [1/nm], about which the table is demodulated.\n";
    out += "const IRID_CENTRE = " + film_shader_text::vec3_literal(m_centre, "vec3f") + ";\n";
    out += "// 1 / the table's tau step [1/nm]; where its tau ends [nm] (terms past it are dropped).\n";
    out += "const IRID_INV_STEP: f32 = " + float_literal(1.0 / table_step_nm()) + ";\n";
    out += "const IRID_TABLE_END: f32 = " + float_literal(table_end_nm) + ";\n";
    out += "// The last texel at which the interpolant's four taps start (width - 4).\n";
    out += "const IRID_LAST_TAP: f32 = " + float_literal(m_width - 4) + ";\n";
    out += "// The term loop stops below this bound on the remaining terms (white = 1); a film\n";
    out += "// whose series needs more than IRID_MAX_TERMS terms is taken by the quadrature.\n";
    out += "const IRID_TOLERANCE: f32 = " + float_literal(term_tolerance) + ";\n";
    out += fmt::format("const IRID_MAX_TERMS: i32 = {};\n", max_terms);
    out += "// Indices are taken up to this, thicknesses up to this [nm].\n";
    out += "const IRID_MAX_INDEX: f32 = " + float_literal(max_index) + ";\n";
    out += "const IRID_MAX_THICKNESS: f32 = " + float_literal(max_thickness_nm) + ";\n";
    out += "// (N1 cos theta1)^2 is kept this many n1^2 from 0, where the faces are 0/0.\n";
    out += "const IRID_MIN_FILM_Q_SQ: f32 = " + float_literal(min_film_q_sq) + ";\n";
    out += "// max |V_c| from tau = j IRID_TABLE_END / " + std::to_string(envelope_count) + " on.\n";
    out += "const IRID_ENVELOPE_SCALE: f32 = " + float_literal(envelope_count / table_end_nm) + ";\n";
    out += fmt::format("const IRID_ENVELOPE_LAST: i32 = {};\n", envelope_count - 1);
    out += fmt::format("const irid_envelope = array<f32, {}>(", envelope_count);
    for (std::size_t j = 0; j < m_envelope.size(); ++j)
        out += (j == 0 ? "" : ", ") + float_literal(m_envelope[j]);
    out += ");\n";
    out += "// The quadrature: the colour is sum_j irid_node_weight[j] R(irid_node_nu[j]), the\n";
    out += "// 1 nm sum of the polynomial through the reflectance at these wavenumbers [1/nm].\n";
    out += fmt::format("const IRID_NODES: i32 = {};\n", quadrature_nodes);
    out += fmt::format("const irid_node_nu = array<f32, {}>(", quadrature_nodes);
    for (std::size_t j = 0; j < m_node_nu.size(); ++j)
        out += (j == 0 ? "" : ", ") + float_literal(m_node_nu[j]);
    out += ");\n";
    out += fmt::format("const irid_node_weight = array<vec3f, {}>(\n", quadrature_nodes);
    for (std::size_t j = 0; j < m_node_weight.size(); ++j)
        out += "    " + film_shader_text::vec3_literal(m_node_weight[j], "vec3f") + (j + 1 < m_node_weight.size() ? ",\n" : ");\n");
    out += wgsl_body;
    out += wgsl_binding_marker;
    out += wgsl_binding;
    return out;
}

}  // namespace irid
