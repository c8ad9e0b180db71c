#pragma once

// Batches: clipping spans of interleaved float RGB (r, g, b, r, g, b, ...) at memory speed.
//
// The colours are linear RGB of the clipper's gamut space. For `ClipMethod::smits` and
// `ClipMethod::clamp` the inner loop is SIMD (Google Highway, the widest instruction set of the
// CPU chosen at run time: AVX-512, AVX2, SSE4, ...); it computes, lane by lane, exactly the
// scalar float specification:
//
//   c = non-finite rule (NaN → 0, ±Inf → ±1e30, as GamutClipper::clip)
//   smits: c = smits_clip_rgb<float>(c, lum, inv_lum_sum, max)       (clip.h)
//   clamp: nothing more
//   c = clamp to [0, max] (as GamutClipper::clip: the contract is outputs inside [0, max]³, and
//       rounding may leave a float result a few ulps outside a face)
//
// with the float parameters lum_i = float(A, B, C), inv_lum_sum = float(1/(A + B + C)) computed
// in double, max = float(gamut max). The SIMD path is compiled without floating-point
// contraction, so it gives the same bits as that scalar code. Every other method runs the double
// GamutClipper::clip per colour (float → double → float).
//
// Threads: the span is cut into fixed chunks of `batch_chunk_colours` colours (independent of the
// thread count) run by oneTBB in an arena of the requested concurrency. Each colour is computed
// independently by the same code, so the result does not depend on the thread count.

#include <irid/gamut/clip.h>

#include <cstddef>
#include <span>
#include <string_view>

namespace irid {

struct BatchOptions {
    /// Worker threads; 0 = all hardware threads available to the process (also the cap: more
    /// are not used). Must be >= 0.
    int threads = 0;
    /// false runs the scalar float specification instead of the SIMD loop (smits and clamp only;
    /// the other methods have no SIMD path).
    bool simd = true;
};

/// Colours per parallel task.
inline constexpr std::size_t batch_chunk_colours = 16384;

/// Clips `rgb` in place. Throws irid::Error when rgb.size() is not a multiple of 3 or
/// options.threads < 0; after that nothing is checked.
void clip_batch(const GamutClipper& clipper, std::span<float> rgb,
                const BatchOptions& options = {});

/// Clips `in` into `out`. Throws irid::Error unless in.size() == out.size(), the size is a
/// multiple of 3, options.threads >= 0 and the spans are either the same memory or disjoint.
void clip_batch(const GamutClipper& clipper, std::span<const float> in, std::span<float> out,
                const BatchOptions& options = {});

/// The Highway target the SIMD loop runs on this CPU ("AVX3" = AVX-512, "AVX2", "SSE4", ...).
[[nodiscard]] std::string_view simd_target_name();

namespace detail {

/// The float parameters of the SIMD kernels (see the top of this file).
struct BatchFloatParams {
    float lum0, lum1, lum2, inv_lum_sum, max;
};

/// SIMD kernels over `colours` interleaved colours; `in` may equal `out`. They process the
/// largest multiple of the vector length and return how many colours that is; the caller does
/// the rest with the scalar code.
std::size_t clip_smits_simd(const float* in, float* out, std::size_t colours,
                            const BatchFloatParams& p) noexcept;
std::size_t clip_clamp_simd(const float* in, float* out, std::size_t colours,
                            const BatchFloatParams& p) noexcept;

}  // namespace detail

}  // namespace irid
