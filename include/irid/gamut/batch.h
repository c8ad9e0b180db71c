#pragma once

// Batches: clipping spans of interleaved float RGB (r, g, b, r, g, b, ...) at memory speed.
//
// The colours are linear RGB of the clipper's gamut space. Every method but luv-hue has a SIMD
// kernel (Google Highway, the widest instruction set of the CPU chosen at run time: AVX-512,
// AVX2, SSE4, ...; src/gamut/kernels.h lists them). For `ClipMethod::smits` and
// `ClipMethod::clamp` it computes, lane by lane, exactly the scalar float specification:
//
//   c = non-finite rule (NaN → 0, ±Inf → ±1e30, as GamutClipper::clip)
//   smits: c = smits_clip_rgb<float>(c, lum, inv_lum_sum, max)       (clip.h)
//   clamp: nothing more
//   c = clamp to [0, max] (as GamutClipper::clip: the contract is outputs inside [0, max]³, and
//       rounding may leave a float result a few ulps outside a face)
//
// with the float parameters lum_i = float(A, B, C), inv_lum_sum = float(1/(A + B + C)) computed
// in double, max = float(gamut max). That path is compiled without floating-point contraction,
// so it gives the same bits as that scalar code. The other kernels compute their method in float
// and are within 1e-5 × max of the double GamutClipper::clip (for aces-rgc without clip, whose
// output is not bounded by the cube, within 1e-5 of the colour's own size); lanes where float
// could take another branch of the method (listed in each kernel's file) are recomputed with
// the double GamutClipper::clip. With `BatchOptions::simd == false`, smits and clamp run the
// scalar float specification and every other method the double GamutClipper::clip per colour
// (float → double → float); luv-hue always does, and so does every method but smits and clamp
// when the peak is below 1e-6 (float's subnormals are near) or when a primary of the gamut has
// a luminance of 0 or below (ACES2065-1), where float is ill-conditioned; css does above a peak
// of 16.
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
    /// false runs the scalar reference instead of the SIMD kernels (the float specification for
    /// smits and clamp, the double GamutClipper::clip for the others).
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
