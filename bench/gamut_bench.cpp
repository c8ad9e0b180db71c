// Throughput of gamut clipping over batches of interleaved float RGB (irid::clip_batch), every
// method, beside memcpy of the same buffers.
//
// Input (gamut_bench_input.h): out-of-gamut colours of linear sRGB, uniform in [-0.5, 1.5]^3,
// each redrawn until a channel lies outside [0, 1]; the destination is the sRGB gamut [0, 1]^3.
// Two buffers: "cache" = 2^20 colours (12 MiB in, 12 MiB out: past the L2, inside a 32 MiB L3)
// and "dram" = 2^24 colours (192 MiB in and out: more than four times a 32 MiB L3). Both are
// allocated and written before the timed loops. One item is one colour (12 bytes read, 12
// written); bytes/s count the input bytes.
//
// Rows:
//   Memcpy/{cache,dram}                 memcpy of the same input into the same output buffer:
//                                       the floor of any clip, the baseline of every ratio
//   Clip/<method>/{cache,dram}/{1,2}t   clip_batch with the SIMD kernel (Highway, the widest
//                                       instruction set of this CPU, named in the label)
//   Clip/<method>/avx2/...              the same with Highway restricted to AVX2 at run time
//                                       (hwy::DisableTargets of the AVX-512 targets), smits and
//                                       aces-rgc
//   Reference/<method>                  clip_batch with simd = false: the scalar float
//                                       specification for smits and clamp, the double
//                                       GamutClipper::clip per colour for every other method;
//                                       on the first 2^14 colours (compute-bound, so its
//                                       items/s compare with the others all the same)
//   luv-hue has no kernel (a search over lightness per colour): its Reference row only.
//   OcioAcesGamutComp13/...             (gamut_ocio_bench.cpp, when OpenColorIO is found) OCIO
//                                       2.1's CPU processor on the same buffers
//
// Every row is timed in wall-clock time (UseRealTime), so that 1 and 2 threads and the ratios to
// memcpy compare like with like. clip_batch lives in another translation unit, so its calls
// cannot be folded away; the output is made observable with ClobberMemory. The memcpy is inline:
// its pointers are escaped with DoNotOptimize in the loop body itself (see the note on GCC 12 and
// Google Benchmark 1.7.1 in optics_bench.cpp).

#include "gamut_bench_input.h"

#include <irid/color/rgb.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>

#include <benchmark/benchmark.h>
#include <hwy/targets.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

namespace {

/// Colours per iteration of the reference rows (2^14 × 12 bytes = 192 KiB).
constexpr std::size_t reference_colours = std::size_t{1} << 14;

/// The AVX-512 targets of Highway 1.0.3 (hwy/detect_targets.h), disabled for the AVX2 rows.
constexpr std::int64_t avx512_targets = HWY_AVX3 | HWY_AVX3_DL;

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

void memcpy_row(benchmark::State& state, std::size_t colours) {
    const std::vector<float>& all = irid_bench::input();
    std::vector<float> out(3 * colours, 0.0f);
    const float* src = all.data();
    float* dst = out.data();
    const std::size_t bytes = 3 * colours * sizeof(float);
    for (auto _ : state) {
        benchmark::DoNotOptimize(src);
        benchmark::DoNotOptimize(dst);
        std::memcpy(dst, src, bytes);
        benchmark::ClobberMemory();
    }
    report(state, colours);
    state.SetLabel("memcpy");
}

/// clip_batch of the first `colours` colours with `method` on `threads` threads.
void clip_row(benchmark::State& state, irid::ClipMethod method, int threads, bool simd,
              std::size_t colours, bool avx2_only) {
    if (avx2_only) hwy::DisableTargets(avx512_targets);
    const std::vector<float>& all = irid_bench::input();
    const std::span<const float> in(all.data(), 3 * colours);
    std::vector<float> out(in.size(), 0.0f);
    const irid::GamutClipper clipper(method, srgb_gamut());
    const irid::BatchOptions options{threads, simd};
    for (auto _ : state) {
        irid::clip_batch(clipper, in, std::span<float>(out), options);
        benchmark::ClobberMemory();
    }
    report(state, colours);
    const bool float_spec = method == irid::ClipMethod::smits || method == irid::ClipMethod::clamp;
    state.SetLabel(simd ? "simd " + std::string(irid::simd_target_name())
                        : (float_spec ? "scalar float" : "double reference"));
    if (avx2_only) hwy::DisableTargets(0);
}

/// Registers every row (in the order of the header).
const bool registered = [] {
    struct Buffer {
        const char* name;
        std::size_t colours;
    };
    const Buffer buffers[] = {{"cache", irid_bench::cache_colours},
                              {"dram", irid_bench::dram_colours}};
    for (const Buffer& b : buffers) {
        benchmark::RegisterBenchmark((std::string("Memcpy/") + b.name).c_str(), memcpy_row,
                                     b.colours)
            ->UseRealTime();
    }
    for (const irid::ClipMethod m : irid::clip_methods()) {
        const std::string name(irid::clip_method_name(m));
        if (m != irid::ClipMethod::luv_hue) {
            for (const Buffer& b : buffers) {
                for (const int threads : {1, 2}) {
                    benchmark::RegisterBenchmark(
                        ("Clip/" + name + "/" + b.name + "/" + std::to_string(threads) + "t").c_str(),
                        clip_row, m, threads, true, b.colours, false)
                        ->UseRealTime();
                }
            }
            if (m == irid::ClipMethod::smits || m == irid::ClipMethod::aces_rgc) {
                for (const Buffer& b : buffers) {
                    benchmark::RegisterBenchmark(
                        ("Clip/" + name + "/avx2/" + b.name + "/1t").c_str(), clip_row, m, 1,
                        true, b.colours, true)
                        ->UseRealTime();
                }
            }
        }
        benchmark::RegisterBenchmark(("Reference/" + name).c_str(), clip_row, m, 1, false,
                                     reference_colours, false)
            ->UseRealTime();
    }
    return true;
}();

}  // namespace
