// Writes colorjs_gamut.csv: colorjs.io 0.7.1's CSS Color 4 gamut mapping ("css", the binary
// search with local MINDE, and "raytrace") of colours at the edges of the domain, in linear
// sRGB, Display P3 and Rec.2020, for tests/gamut/colorjs_reference_test.cpp.
//
//   cd tests/gamut/references && npm ci && node make_colorjs_references.mjs > colorjs_gamut.csv
//
// The colours: near the white's Oklab lightness (1 − δ, δ from 1e-2 down to 1e-9, at 36 hues and
// three chromas), near black (L from 1e-2 down to 1e-6, and tiny RGB of either sign), bright
// colours of linear RGB in [−1, 4.5]³, saturated HDR colours up to 100, and the examples of
// issue 23. Inputs and outputs are linear RGB of the destination, written with 17 significant
// digits. Deterministic: a fixed linear congruential generator, no clock.

import Color from "colorjs.io";

const spaces = [
    ["srgb-linear", "srgb-linear"],
    ["display-p3-linear", "p3-linear"],
    ["rec2020-linear", "rec2020-linear"],
];
const methods = [
    ["css", "css"],
    ["css-raytrace", "raytrace"],
];

let state = 20261205n;
function random() {
    // 64-bit LCG (Knuth's MMIX constants), top 53 bits.
    state = (state * 6364136223846793005n + 1442695040888963407n) & ((1n << 64n) - 1n);
    return Number(state >> 11n) / 2 ** 53;
}
const uniform = (lo, hi) => lo + (hi - lo) * random();

function colours(space) {
    const out = [];
    const fromOklch = (l, c, h) => new Color("oklch", [l, c, h]).to(space).coords.map(Number);
    for (let k = 0; k < 36; ++k) {
        const h = k * 10 + 3;
        for (const delta of [1e-2, 1e-3, 1.4e-4, 1e-5, 1e-7, 1e-9]) {
            for (const c of [0.02, 0.15, 0.4]) out.push(fromOklch(1 - delta, c, h));
        }
        for (const l of [1e-2, 1e-3, 1e-4, 1e-6]) {
            for (const c of [0.01, 0.1, 0.3]) out.push(fromOklch(l, c * l * 10, h));
        }
    }
    for (let i = 0; i < 120; ++i) out.push([uniform(-0.002, 0.004), uniform(-0.002, 0.004), uniform(-0.002, 0.004)]);
    for (let i = 0; i < 240; ++i) out.push([uniform(-1, 4.5), uniform(-1, 4.5), uniform(-1, 4.5)]);
    for (let i = 0; i < 120; ++i) {
        // Saturated and bright: one channel large, the others small or negative.
        const big = uniform(1, 100);
        const c = [uniform(-1, 0.3) * big * 0.05, uniform(-1, 0.3) * big * 0.05, uniform(-1, 0.3) * big * 0.05];
        c[i % 3] = big;
        out.push(c);
    }
    out.push([4.037, 0, 0], [4.0379, 0, 0], [4.03, 0, 0], [0.00129, -0.00065, 0.00154]);
    return out;
}

const fmt = (x) => (Object.is(x, -0) ? 0 : x).toPrecision(17);
console.log("space,method,r,g,b,out_r,out_g,out_b");
for (const [name, id] of spaces) {
    for (const c of colours(id)) {
        for (const [method, option] of methods) {
            const mapped = new Color(id, c).toGamut({ space: id, method: option }).coords.map(Number);
            console.log([name, method, ...c.map(fmt), ...mapped.map(fmt)].join(","));
        }
    }
}
