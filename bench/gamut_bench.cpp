// Throughput of gamut clipping over batches of interleaved float RGB (irid::clip_batch).
//
// The input is 2^20 fully out-of-gamut colours of linear sRGB: uniform in [-0.5, 1.5]^3
// (std::mt19937, fixed seed), each colour redrawn until at least one channel lies outside [0, 1].
// That is 12 MiB of floats in and 12 MiB out, six times the L2, so the fast paths stream from
// beyond it (the shared L3 or main memory). Both buffers are allocated and written once before
// the timed loop. One item is one colour (12 bytes read, 12 bytes written); bytes/s count the
// input bytes.
//
// Baseline in the same binary, so that the ratios hold on a noisy machine:
//   BM_Memcpy  memcpy of the same 12 MiB buffer into the same output buffer: the cost of merely
//              reading and writing every colour once, the floor of any clip.
//
// Then clip_batch(clipper, in, out, {threads, simd}) for:
//   smits on 1 and 2 threads (SIMD), smits on 1 thread with the scalar float loop (simd=false),
//   clamp on 1 thread (SIMD), and every other method on 1 thread. The methods without a SIMD path
//   (smits-xyz, luv-lightness-hue, luv-hue, css, oklab, smits-corrected) run the double
//   GamutClipper::clip per colour and cost tens to thousands of nanoseconds per colour, so they
//   clip the first 2^14 colours of the same input (192 KiB) per iteration instead of all of them;
//   being compute-bound, their items/s compare with the others all the same.
//
// Every benchmark is timed in wall-clock time (UseRealTime): the 2-thread one must be, and the
// 1-thread ones are timed the same way so that "2 threads faster than 1" and the ratios to
// memcpy compare like with like. The label names the path: the Highway target the SIMD loop
// runs on ("simd AVX2", "simd SSE4", ...) or "scalar".
//
// clip_batch lives in another translation unit, so its calls cannot be folded away; the output
// is made observable with ClobberMemory. The memcpy is inline: its pointers are escaped with
// DoNotOptimize in the loop body itself (not captured by a lambda; see the note on GCC 12 and
// Google Benchmark 1.7.1 in optics_bench.cpp).

#include <irid/color/rgb.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace {

constexpr std::uint32_t seed = 20240613;
/// Colours of the full batch: 2^20 × 12 bytes = 12 MiB in and 12 MiB out.
constexpr std::size_t full_colours = std::size_t{1} << 20;
/// Colours per iteration for the methods without a SIMD path (2^14 × 12 bytes = 192 KiB).
constexpr std::size_t small_colours = std::size_t{1} << 14;

/// The shared input: full_colours interleaved float triples, each with a channel outside [0, 1].
const std::vector<float>& input() {
    static const std::vector<float> in = [] {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> d(-0.5f, 1.5f);
        const auto outside = [](float v) { return v < 0.0f || v > 1.0f; };
        std::vector<float> v(3 * full_colours);
        for (std::size_t i = 0; i < full_colours; ++i) {
            float r = 0.0f, g = 0.0f, b = 0.0f;
            do {
                r = d(rng);
                g = d(rng);
                b = d(rng);
            } while (!(outside(r) || outside(g) || outside(b)));
            v[3 * i] = r;
            v[3 * i + 1] = g;
            v[3 * i + 2] = b;
        }
        return v;
    }();
    return in;
}

const irid::Gamut& srgb_gamut() {
    static const irid::Gamut g(irid::srgb());
    return g;
}

/// Items (colours) and bytes (input bytes) per second, and "per_item", the time per colour.
void report(benchmark::State& state, std::size_t colours) {
    const auto iterations = static_cast<std::int64_t>(state.iterations());
    const auto items = static_cast<std::int64_t>(colours);
    state.SetItemsProcessed(iterations * items);
    state.SetBytesProcessed(iterations * items * static_cast<std::int64_t>(3 * sizeof(float)));
    state.counters["per_item"] = benchmark::Counter(
        static_cast<double>(colours),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// --- baseline -----------------------------------------------------------------------------------

void BM_Memcpy(benchmark::State& state) {
    const std::vector<float>& in = input();
    std::vector<float> out(in.size(), 0.0f);
    const float* src = in.data();
    float* dst = out.data();
    const std::size_t bytes = in.size() * sizeof(float);
    for (auto _ : state) {
        benchmark::DoNotOptimize(src);
        benchmark::DoNotOptimize(dst);
        std::memcpy(dst, src, bytes);
        benchmark::ClobberMemory();
    }
    report(state, full_colours);
    state.SetLabel("memcpy");
}
BENCHMARK(BM_Memcpy)->UseRealTime();

// --- clip_batch ---------------------------------------------------------------------------------

/// clip_batch of the first `colours` colours of the input with `method` on `threads` threads.
void BM_ClipBatch(benchmark::State& state, irid::ClipMethod method, int threads, bool simd,
                  std::size_t colours) {
    const std::vector<float>& all = input();
    const std::span<const float> in(all.data(), 3 * colours);
    std::vector<float> out(in.size(), 0.0f);
    const irid::GamutClipper clipper(method, srgb_gamut());
    const irid::BatchOptions options{threads, simd};
    for (auto _ : state) {
        irid::clip_batch(clipper, in, std::span<float>(out), options);
        benchmark::ClobberMemory();
    }
    report(state, colours);
    const bool has_simd = method == irid::ClipMethod::smits || method == irid::ClipMethod::clamp;
    state.SetLabel(simd && has_simd ? "simd " + std::string(irid::simd_target_name())
                                    : std::string("scalar"));
}

using irid::ClipMethod;
BENCHMARK_CAPTURE(BM_ClipBatch, smits_1t_simd, ClipMethod::smits, 1, true, full_colours)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ClipBatch, smits_2t_simd, ClipMethod::smits, 2, true, full_colours)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ClipBatch, smits_1t_scalar, ClipMethod::smits, 1, false, full_colours)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ClipBatch, clamp_1t_simd, ClipMethod::clamp, 1, true, full_colours)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ClipBatch, smits_xyz_1t, ClipMethod::smits_xyz, 1, true, small_colours)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ClipBatch, luv_lightness_hue_1t, ClipMethod::luv_lightness_hue, 1, true,
                  small_colours)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ClipBatch, luv_hue_1t, ClipMethod::luv_hue, 1, true, small_colours)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ClipBatch, css_1t, ClipMethod::css, 1, true, small_colours)->UseRealTime();
BENCHMARK_CAPTURE(BM_ClipBatch, oklab_1t, ClipMethod::oklab, 1, true, small_colours)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ClipBatch, smits_corrected_1t, ClipMethod::smits_corrected, 1, true,
                  small_colours)
    ->UseRealTime();

}  // namespace
