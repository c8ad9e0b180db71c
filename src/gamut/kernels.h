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

/// A method's SIMD kernel, and the rule of which clippers it may take, beyond batch.cpp's rules
/// for every kernel (a peak of at least 1e-6, primaries of positive luminance). The rule is
/// written beside the kernel, in its file; nullptr takes every clipper.
struct Kernel {
    ClipKernel run = nullptr;
    bool (*takes)(const GamutClipper& clipper) noexcept = nullptr;
};

/// The kernel of a method, or {} for one without (luv-hue). smits and clamp keep their
/// bit-exact kernels of batch.h (clip_smits_simd, clip_clamp_simd) and are not listed here.
[[nodiscard]] Kernel simd_kernel(ClipMethod method) noexcept;

// Each kernel file's methods ({} for any other method).
[[nodiscard]] Kernel smits_family_kernel(ClipMethod method) noexcept;  // batch_simd_smits.cpp
[[nodiscard]] Kernel aces_rgc_kernel(ClipMethod method) noexcept;      // batch_simd_aces.cpp
[[nodiscard]] Kernel css_kernel(ClipMethod method) noexcept;           // batch_simd_css.cpp
[[nodiscard]] Kernel oklab_kernel(ClipMethod method) noexcept;         // batch_simd_oklab.cpp

}  // namespace irid::detail

/// In a kernel file's HWY_ONCE part, inside namespace irid: exports HWY_NAMESPACE::Name (a
/// ClipKernel without noexcept, compiled once per target by foreach_target.h) and defines
/// Name##Dispatch, the ClipKernel that runs the best target the CPU has.
#define IRID_EXPORT_KERNEL(Name)                                                                \
    HWY_EXPORT(Name);                                                                           \
    std::size_t Name##Dispatch(const GamutClipper& clipper, const float* in, float* out,        \
                               std::size_t colours) noexcept {                                  \
        return HWY_DYNAMIC_DISPATCH(Name)(clipper, in, out, colours);                           \
    }
