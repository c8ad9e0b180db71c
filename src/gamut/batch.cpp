// No floating-point contraction: the scalar specification must perform the same IEEE operations
// as the SIMD kernels (batch_simd.cpp), also when built with -march and FMA available.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <irid/error.h>
#include <irid/gamut/batch.h>

#include "kernels.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>

namespace irid {
namespace {

/// std::clamp(v, 0, max), written as the SIMD kernel does.
float clamp_to_cube(float v, float max) noexcept {
    if (v < 0.0f) v = 0.0f;
    if (v > max) v = max;
    return v;
}

detail::BatchFloatParams float_params(const Gamut& gamut) noexcept {
    const Vec3& lum = gamut.luminance_row();
    return {static_cast<float>(lum[0]), static_cast<float>(lum[1]), static_cast<float>(lum[2]),
            static_cast<float>(1.0 / (lum[0] + lum[1] + lum[2])), static_cast<float>(gamut.max())};
}

/// The scalar float specification of the SIMD kernels (batch.h), colour by colour.
void smits_scalar(const float* in, float* out, std::size_t colours,
                  const detail::BatchFloatParams& p) noexcept {
    const std::array<float, 3> lum{p.lum0, p.lum1, p.lum2};
    for (std::size_t i = 0; i < colours; ++i) {
        const std::array<float, 3> c{finite_or_default<float>(in[3 * i]),
                                     finite_or_default<float>(in[3 * i + 1]),
                                     finite_or_default<float>(in[3 * i + 2])};
        const std::array<float, 3> o = smits_clip_rgb<float>(c, lum, p.inv_lum_sum, p.max);
        for (std::size_t k = 0; k < 3; ++k) out[3 * i + k] = clamp_to_cube(o[k], p.max);
    }
}

void clamp_scalar(const float* in, float* out, std::size_t colours,
                  const detail::BatchFloatParams& p) noexcept {
    for (std::size_t i = 0; i < 3 * colours; ++i)
        out[i] = clamp_to_cube(finite_or_default<float>(in[i]), p.max);
}

/// Any other method: the double GamutClipper::clip per colour.
void clipper_scalar(const GamutClipper& clipper, const float* in, float* out,
                    std::size_t colours) noexcept {
    for (std::size_t i = 0; i < colours; ++i) {
        const Rgb o = clipper.clip({in[3 * i], in[3 * i + 1], in[3 * i + 2]});
        out[3 * i] = static_cast<float>(o.r);
        out[3 * i + 1] = static_cast<float>(o.g);
        out[3 * i + 2] = static_cast<float>(o.b);
    }
}

/// The rules for every float kernel (a method's own rules are beside its kernel, kernels.h).
bool any_kernel_takes(const GamutClipper& clipper) noexcept {
    // A peak below 1e-6 puts the float kernels' values near float's subnormals, where they lose
    // the relative precision the 1e-5 × max contract needs (fuzz finding clip-4: smits-soft at a
    // peak of 2e-41): the double reference runs instead.
    if (!(clipper.gamut().max() >= 1e-6)) return false;
    // A primary of zero or negative luminance (ACES2065-1's blue, Y = -0.072) makes the geometry
    // of the hue- and lightness-keeping methods ill-conditioned in float in places no hard-lane
    // test foresees (fuzz findings clip-6, smits-xyz black instead of the colour, and clip-7,
    // luv-lightness-hue 3e-5 × max off, both on aces2065-1): such a gamut runs the double
    // reference. Nobody displays ACES2065-1's cube; its colours are clipped in AP1.
    const Vec3& lum = clipper.gamut().luminance_row();
    return lum[0] > 0.0 && lum[1] > 0.0 && lum[2] > 0.0;
}

/// Clips colours [0, colours) of in into out: the kernel of one chunk.
void clip_range(const GamutClipper& clipper, const detail::BatchFloatParams& p, bool simd,
                const float* in, float* out, std::size_t colours) noexcept {
    switch (clipper.method()) {
        case ClipMethod::smits: {
            const std::size_t done = simd ? detail::clip_smits_simd(in, out, colours, p) : 0;
            smits_scalar(in + 3 * done, out + 3 * done, colours - done, p);
            return;
        }
        case ClipMethod::clamp: {
            const std::size_t done = simd ? detail::clip_clamp_simd(in, out, colours, p) : 0;
            clamp_scalar(in + 3 * done, out + 3 * done, colours - done, p);
            return;
        }
        default: {
            const detail::Kernel kernel = simd ? detail::simd_kernel(clipper.method()) : detail::Kernel{};
            const std::size_t done =
                kernel.run != nullptr && any_kernel_takes(clipper) && (kernel.takes == nullptr || kernel.takes(clipper))
                    ? kernel.run(clipper, in, out, colours)
                    : 0;
            clipper_scalar(clipper, in + 3 * done, out + 3 * done, colours - done);
            return;
        }
    }
}

}  // namespace

namespace detail {

Kernel simd_kernel(ClipMethod method) noexcept {
    for (const auto lookup : {smits_family_kernel, aces_rgc_kernel, css_kernel, oklab_kernel}) {
        const Kernel k = lookup(method);
        if (k.run != nullptr) return k;
    }
    return {};
}

}  // namespace detail

void clip_batch(const GamutClipper& clipper, std::span<float> rgb, const BatchOptions& options) {
    clip_batch(clipper, std::span<const float>(rgb), rgb, options);
}

void clip_batch(const GamutClipper& clipper, std::span<const float> in, std::span<float> out,
                const BatchOptions& options) {
    if (in.size() != out.size()) {
        throw Error("clip_batch: input has " + std::to_string(in.size()) + " floats and output " +
                    std::to_string(out.size()) + "; they must be equal");
    }
    if (in.size() % 3 != 0) {
        throw Error("clip_batch: " + std::to_string(in.size()) +
                    " floats is not a whole number of RGB colours (must be a multiple of 3)");
    }
    if (options.threads < 0) {
        throw Error("clip_batch: threads " + std::to_string(options.threads) +
                    " must be >= 0 (0 = all hardware threads)");
    }
    const std::size_t colours = in.size() / 3;
    if (colours == 0) return;
    const float* src = in.data();
    float* dst = out.data();
    if (static_cast<const float*>(dst) != src) {
        const std::less<const float*> less;
        const bool disjoint = !less(src, dst + in.size()) || !less(dst, src + in.size());
        if (!disjoint) {
            throw Error(
                "clip_batch: input and output overlap; they must be the same span or disjoint");
        }
    }

    const detail::BatchFloatParams params = float_params(clipper.gamut());
    const bool simd = options.simd;
    const std::size_t chunks = (colours + batch_chunk_colours - 1) / batch_chunk_colours;
    // More threads than the hardware has would only be refused by TBB (with a warning).
    const int hardware = tbb::info::default_concurrency();
    const int threads = options.threads == 0 ? hardware : std::min(options.threads, hardware);
    const auto run_chunks = [&](std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) {
            const std::size_t begin = k * batch_chunk_colours;
            const std::size_t count = std::min(batch_chunk_colours, colours - begin);
            clip_range(clipper, params, simd, src + 3 * begin, dst + 3 * begin, count);
        }
    };
    if (threads == 1 || chunks == 1) {
        run_chunks(0, chunks);
        return;
    }
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, chunks, 1),
            [&](const tbb::blocked_range<std::size_t>& r) { run_chunks(r.begin(), r.end()); },
            tbb::simple_partitioner());
    });
}

}  // namespace irid
