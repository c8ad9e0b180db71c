#pragma once

// The SIMD batch kernels of the clip methods (internal to irid_gamut; batch.cpp dispatches).
//
// Every kernel clips the largest multiple of its vector length of `colours` interleaved float RGB
// colours from `in` to `out` (`in` may equal `out`) and returns how many it did; batch.cpp does
// the rest with the method's scalar reference (GamutClipper::clip in double). Each kernel reads
// what it needs from the clipper (its matrices, parameters and derived values) once per call; a
// call covers one chunk of batch_chunk_colours colours. The result is within 1e-5 × max of the
// double reference (tests/gamut/*_test.cpp) and does not depend on the thread count (each colour
// is computed alone).
//
// Files: batch_simd_smits.cpp (smits-xyz, luv-lightness-hue, smits-soft), batch_simd_aces.cpp (aces-rgc), batch_simd_css.cpp (css, css-raytrace),
// batch_simd_oklab.cpp (oklab, oklab-adaptive, oklab-cusp).

#include <irid/color/matrix.h>
#include <irid/gamut/clip.h>

#include <array>
#include <cstddef>

namespace irid::detail {

/// A 3×3 matrix in float, row-major, for the kernels.
struct Mat3f {
    std::array<float, 9> m;
};
[[nodiscard]] inline Mat3f to_float(const Mat3& a) noexcept {
    Mat3f f{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) f.m[static_cast<std::size_t>(3 * i + j)] = static_cast<float>(a[i][j]);
    }
    return f;
}

using ClipKernel = std::size_t (*)(const GamutClipper& clipper, const float* in, float* out,
                                   std::size_t colours) noexcept;

/// The kernel of a method, or nullptr for one without (luv-hue). smits and clamp keep their
/// bit-exact kernels of batch.h (clip_smits_simd, clip_clamp_simd) and are not listed here.
[[nodiscard]] ClipKernel simd_kernel(ClipMethod method) noexcept;

std::size_t clip_smits_xyz_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept;
std::size_t clip_luv_lightness_hue_simd(const GamutClipper&, const float*, float*,
                                        std::size_t) noexcept;
std::size_t clip_smits_soft_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept;
std::size_t clip_aces_rgc_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept;
std::size_t clip_css_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept;
std::size_t clip_css_raytrace_simd(const GamutClipper&, const float*, float*,
                                   std::size_t) noexcept;
std::size_t clip_oklab_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept;
std::size_t clip_oklab_adaptive_simd(const GamutClipper&, const float*, float*,
                                     std::size_t) noexcept;
std::size_t clip_oklab_cusp_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept;

}  // namespace irid::detail
