#pragma once

// The ACES 2.0 display chain (aces2_display.h) on batches of interleaved float triples: a
// Highway SIMD kernel (dynamic dispatch) that follows Aces2Output in float, and hands the colours
// float cannot follow to the double path. docs/KERNELS.md describes its arithmetic and the
// colours it hands back; tests/gamut/aces2_kernel_test.cpp holds it to the double path.

#include <irid/color/matrix.h>
#include <irid/gamut/aces2_display.h>

#include <cstddef>
#include <memory>
#include <span>

namespace irid {

namespace detail {
struct Aces2KernelData;
}

/// One direction of one display, with a linear map on either side folded in. Its tables and
/// parameters are converted once, at construction; run() allocates nothing.
class Aces2Kernel {
public:
    /// Forward: `in` takes the input triples to ACES2065-1, `out` takes CIE XYZ of the display
    /// (1.0 = 100 cd/m²) to the output. Inverse: `in` takes the input to that XYZ, `out` takes
    /// ACES2065-1 to the output. `output` must outlive the kernel.
    Aces2Kernel(const Aces2Output& output, bool inverse, const Mat3& in = Mat3::identity(),
                const Mat3& out = Mat3::identity());
    ~Aces2Kernel();
    Aces2Kernel(const Aces2Kernel&) = delete;
    Aces2Kernel& operator=(const Aces2Kernel&) = delete;

    /// The chain on whole triples of `in` into `out` (equal sizes, a multiple of 3; they may be
    /// the same array), within 1e-5 × max(|result|, 1) of reference(). Each triple's result
    /// depends on that triple alone, whatever the length and the split into calls. Returns how
    /// many triples were handed to reference().
    std::size_t run(std::span<const float> in, std::span<float> out) const noexcept;

    /// The forward's stages one at a time, as run() computes them, for OpenColorIO's published
    /// stage vectors (data/ocio-aces2): ACES2065-1 (no clamp) to the input model's (J, M, h);
    /// the tonescale with chroma compression of (J, M, h); the gamut compression of (J, M, h),
    /// h in degrees. `in_float` computes in float what run() takes in double (docs/KERNELS.md),
    /// to measure what that buys. rgb_to_jmh's input goes through the kernel's `in` map first;
    /// the `out` map is not applied. Whole triples, as run(). Throws irid::Error for an inverse
    /// kernel.
    enum class Stage { rgb_to_jmh, tonescale_and_chroma, gamut_compression };
    void run_stage(Stage stage, std::span<const float> in, std::span<float> out,
                   bool in_float = false) const;

    /// The double path: non-finite input channels taken as 0, `in`, Aces2Output::forward or
    /// inverse, `out`.
    [[nodiscard]] Vec3 reference(const Vec3& in) const noexcept;

    [[nodiscard]] bool inverse() const noexcept { return m_inverse; }

    /// For a forward kernel, a bound on |run() − reference()| of any channel relative to the
    /// largest |channel| of reference()'s result, dark colours included: 1e-4 where the forward
    /// runs in float (peaks of 100 cd/m²), 3e-6 where its back end runs in double, 1e-7 where
    /// every colour goes to the double chain (a limiting gamut beyond AP1); 2.6 and
    /// 3.3 times the largest measured (docs/KERNELS.md). What a caller that must round the result
    /// as the double path would (display_image's encoded files) checks against.
    [[nodiscard]] double error_of_largest() const noexcept;

private:
    struct Builder;  // aces2_kernel.cpp

    const Aces2Output& m_output;
    bool m_inverse;
    Mat3 m_in, m_out;
    std::unique_ptr<const detail::Aces2KernelData> m_data;
};

}  // namespace irid
