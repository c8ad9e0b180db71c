// Fuzz harness: the clip kernels (include/irid/gamut/clip.h, batch.h) on any bit pattern of
// floats.
//
// Input: byte 0 picks the RGB space (builtin_rgb_spaces()), byte 1 the peak (1, 4, 0.5, 100,
// 1e6, 1e-3, 2, or the next 4 bytes as a float when it is a valid peak, 0 < max <= 1e6), byte 2
// the Highway target of the SIMD loop (one of those compiled and supported here: AVX3, AVX2,
// SSE4, ...); the rest are floats (little-endian bit patterns: NaN, ±Inf, subnormals, ±FLT_MAX),
// taken as RGB triples. For every method of clip_methods():
// - GamutClipper::clip on each colour: finite and inside [0, max]³ (only finite for aces-rgc
//   without clip, which leaves the cube by design); an in-gamut colour comes back unchanged
//   (except for the soft methods, moves_in_gamut_colours); clip_xyz on its XYZ is finite;
// - clip_batch with BatchOptions simd on and off (one thread): every output finite and inside
//   [0, max]³ (when confined); for smits and clamp the SIMD result has the same bits as the
//   scalar one (batch.h: "it computes, lane by lane, exactly the scalar float specification ...
//   the same bits"), for the other kernels it is within 1e-5 × max of it (kernels.h);
// - the other methods: each scalar batch output is float(GamutClipper::clip(input));
// - clip_batch in place gives the same bits as out of place.
#include "fuzz_support.h"

#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>

#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace {

using irid::fuzz::Bytes;

std::string colour_text(const float* c) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "(%a, %a, %a) = (%.9g, %.9g, %.9g)", c[0], c[1], c[2],
                  c[0], c[1], c[2]);
    return buffer;
}

std::string where(irid::ClipMethod m, const irid::Gamut& g, std::size_t colour, const float* in) {
    return std::string(irid::clip_method_name(m)) + " on " + g.space().name() + " max " +
           std::to_string(g.max()) + ", colour " + std::to_string(colour) + " " + colour_text(in);
}

void check_method(irid::ClipMethod method, const irid::Gamut& gamut, std::span<const float> in) {
    const irid::GamutClipper clipper(method, gamut);
    const double max = gamut.max();
    const auto max_f = static_cast<float>(max);
    const std::size_t colours = in.size() / 3;
    // aces-rgc without clip leaves the cube by design: only finiteness is asserted for it. The
    // kernels of smits and clamp are bit-exact; the others are within 1e-5 × max of the scalar
    // path (of max(max, |ach|, |value|) when not confined: float carries 6e-8 of magnitude).
    const bool confined = clipper.confines_to_cube();
    const bool bit_exact = method == irid::ClipMethod::smits || method == irid::ClipMethod::clamp;

    for (std::size_t i = 0; i < colours; ++i) {
        const float* c = &in[3 * i];
        const irid::Rgb rgb{c[0], c[1], c[2]};
        const irid::Rgb o = clipper.clip(rgb);
        IRID_FUZZ_REQUIRE(
            std::isfinite(o.r) && std::isfinite(o.g) && std::isfinite(o.b) &&
                (!confined || (o.r >= 0.0 && o.g >= 0.0 && o.b >= 0.0 && o.r <= max &&
                               o.g <= max && o.b <= max)),
            "clip() left the cube: " + where(method, gamut, i, c) + " -> (" + std::to_string(o.r) +
                ", " + std::to_string(o.g) + ", " + std::to_string(o.b) + ")");
        if (gamut.contains(rgb) && !irid::moves_in_gamut_colours(method)) {
            IRID_FUZZ_REQUIRE(o.r == rgb.r && o.g == rgb.g && o.b == rgb.b,
                              "an in-gamut colour changed: " + where(method, gamut, i, c));
        }
        const irid::Xyz xyz = clipper.clip_xyz(
            gamut.space().to_xyz({irid::finite_or_default(c[0]), irid::finite_or_default(c[1]),
                                  irid::finite_or_default(c[2])}));
        IRID_FUZZ_REQUIRE(std::isfinite(xyz.X) && std::isfinite(xyz.Y) && std::isfinite(xyz.Z),
                          "clip_xyz() not finite: " + where(method, gamut, i, c));
    }

    std::vector<float> simd(in.size()), scalar(in.size());
    irid::clip_batch(clipper, in, simd, {.threads = 1, .simd = true});
    irid::clip_batch(clipper, in, scalar, {.threads = 1, .simd = false});
    for (std::size_t i = 0; i < in.size(); ++i) {
        const float v = simd[i];
        IRID_FUZZ_REQUIRE(std::isfinite(v) && (!confined || (v >= 0.0f && v <= max_f)),
                          "clip_batch (SIMD " + std::string(irid::simd_target_name()) +
                              ") left the cube: " + where(method, gamut, i / 3, &in[i - i % 3]) +
                              ", channel " + std::to_string(i % 3) + " = " + std::to_string(v));
        IRID_FUZZ_REQUIRE(
            std::isfinite(scalar[i]) && (!confined || (scalar[i] >= 0.0f && scalar[i] <= max_f)),
            "clip_batch (scalar) left the cube: " + where(method, gamut, i / 3, &in[i - i % 3]));
        const float* c = &in[i - i % 3];
        const double ach = std::max({irid::finite_or_default(c[0]), irid::finite_or_default(c[1]),
                                     irid::finite_or_default(c[2])});
        const double scale = confined ? max : std::max({max, std::abs(ach), std::abs(double{scalar[i]})});
        IRID_FUZZ_REQUIRE(bit_exact ? std::memcmp(&simd[i], &scalar[i], sizeof(float)) == 0
                                    : std::abs(double{simd[i]} - double{scalar[i]}) <= 1e-5 * scale,
                          "SIMD (" + std::string(irid::simd_target_name()) + ") " +
                              colour_text(&simd[i - i % 3]) + " != scalar " +
                              colour_text(&scalar[i - i % 3]) + " for " +
                              where(method, gamut, i / 3, &in[i - i % 3]));
    }
    if (method != irid::ClipMethod::smits && method != irid::ClipMethod::clamp) {
        for (std::size_t i = 0; i < colours; ++i) {
            const irid::Rgb o = clipper.clip({in[3 * i], in[3 * i + 1], in[3 * i + 2]});
            IRID_FUZZ_REQUIRE(scalar[3 * i] == static_cast<float>(o.r) &&
                                  scalar[3 * i + 1] == static_cast<float>(o.g) &&
                                  scalar[3 * i + 2] == static_cast<float>(o.b),
                              "batch != float(clip()): " + where(method, gamut, i, &in[3 * i]));
        }
    }
    if (in.empty()) return;
    std::vector<float> in_place(in.begin(), in.end());
    irid::clip_batch(clipper, in_place, {.threads = 1, .simd = true});
    IRID_FUZZ_REQUIRE(std::memcmp(in_place.data(), simd.data(), simd.size() * sizeof(float)) == 0,
                      "in place != out of place: " + std::string(irid::clip_method_name(method)));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    Bytes bytes(data, size);
    const auto spaces = irid::builtin_rgb_spaces();
    const irid::RgbSpace& space = *spaces[bytes.pick(spaces.size())];
    constexpr double peaks[] = {1.0, 4.0, 0.5, 100.0, 1e6, 1e-3, 2.0};
    const std::size_t peak_choice = bytes.pick(std::size(peaks) + 1);
    double max = 1.0;
    if (peak_choice < std::size(peaks)) {
        max = peaks[peak_choice];
    } else {
        const float f = bytes.raw_float();
        if (std::isfinite(f) && f > 0.0f && f <= 1e6f) max = f;
    }
    const std::int64_t target = targets[bytes.pick(targets.size())];
    hwy::SetSupportedTargetsForTest(target);

    std::vector<float> in(bytes.size() / 12 * 3);
    if (!in.empty()) std::memcpy(in.data(), bytes.data(), in.size() * sizeof(float));
    const irid::Gamut gamut(space, max);
    for (const irid::ClipMethod method : irid::clip_methods()) check_method(method, gamut, in);
    hwy::SetSupportedTargetsForTest(0);
    return 0;
}
