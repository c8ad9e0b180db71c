// The reference of aces-rgc's speed: OpenColorIO 2.1's CPU processor on the same colours
// (compiled into irid_gamut_bench when OpenColorIO is found, so that its rows run in the same
// binary and the same run as irid's aces-rgc rows).
//
// BM_OcioAcesGamutComp13: OCIO's FixedFunctionTransform FIXED_FUNCTION_ACES_GAMUT_COMP_13 with
// the published parameters (1.147, 1.264, 1.312, 0.815, 0.803, 0.880, 1.2; ACES 1.3
// LMT.Academy.ReferenceGamutCompress.ctl), forward, through Config::CreateRaw()'s default CPU
// processor, applied out of place from one PackedImageDesc of packed float RGB (3 channels, one
// row) to another: OCIO's own batch path, on one thread (OCIO 2.1 does not thread apply()). The
// input is the shared one of gamut_bench_input.h, taken as ACEScg values as irid's aces-rgc
// rows take them: one row per buffer size (cache_colours: 12 MiB in and out; dram_colours:
// 192 MiB in and out). Items are colours; bytes count the input bytes; "per_item" is the time
// per colour. Timed in wall-clock time like the other rows.

#include "gamut_bench_input.h"

#include <OpenColorIO/OpenColorIO.h>
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

namespace OCIO = OCIO_NAMESPACE;

void BM_OcioAcesGamutComp13(benchmark::State& state) {
    const auto colours = static_cast<std::size_t>(state.range(0));
    const std::vector<float>& all = irid_bench::input();
    // OCIO's ImageDesc takes a non-const pointer also for the source; the copy keeps the shared
    // input untouched (it is only read).
    std::vector<float> in(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(3 * colours));
    std::vector<float> out(in.size(), 0.0f);
    const double params[7] = {1.147, 1.264, 1.312, 0.815, 0.803, 0.880, 1.2};
    const OCIO::FixedFunctionTransformRcPtr transform =
        OCIO::FixedFunctionTransform::Create(OCIO::FIXED_FUNCTION_ACES_GAMUT_COMP_13, params, 7);
    const OCIO::ConstCPUProcessorRcPtr cpu =
        OCIO::Config::CreateRaw()->getProcessor(transform)->getDefaultCPUProcessor();
    const auto width = static_cast<long>(colours);
    const OCIO::PackedImageDesc source(in.data(), width, 1, 3);
    OCIO::PackedImageDesc destination(out.data(), width, 1, 3);
    for (auto _ : state) {
        cpu->apply(source, destination);
        benchmark::ClobberMemory();
    }
    const auto iterations = static_cast<std::int64_t>(state.iterations());
    const auto items = static_cast<std::int64_t>(colours);
    state.SetItemsProcessed(iterations * items);
    state.SetBytesProcessed(iterations * items * static_cast<std::int64_t>(3 * sizeof(float)));
    state.counters["per_item"] = benchmark::Counter(
        static_cast<double>(colours),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.SetLabel(std::string("OCIO ") + OCIO::GetVersion());
}
BENCHMARK(BM_OcioAcesGamutComp13)
    ->Arg(static_cast<std::int64_t>(irid_bench::cache_colours))
    ->Arg(static_cast<std::int64_t>(irid_bench::dram_colours))
    ->UseRealTime();

}  // namespace
