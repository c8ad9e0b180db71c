// Baking 3D LUTs (irid::bake_lut) beside what it is made of, in the same run: the clip
// pipeline's batch kernels on the same node colours (the work a bake cannot avoid), memcpy of
// the node buffer, and the formatting of the .cube text.
//
// A 65³ LUT is 274 625 nodes: 3.3 MB of float triples in, the same out, inside a 32 MiB L3 and
// past a 2 MiB L2. Items are nodes. Rows:
//   Memcpy/65                          memcpy of the 65³ node triples: the floor
//   PipelineClip/<method>/65           ClipPipeline::clip (float path, SIMD, all threads) on the
//                                      node inputs: the baseline of the bake
//   BakeLut/<method>/65                bake_lut: node inputs, checks, the same clip, the title
//   LutText/cube/65, LutText/clf/65    the file's text (shortest round-trip floats, fmt)
// Wall-clock time (UseRealTime), threads = all.

#include <irid/color/convert.h>
#include <irid/exchange/lut.h>
#include <irid/gamut/pipeline.h>

#include <benchmark/benchmark.h>

#include <cstring>
#include <string>
#include <vector>

namespace {

constexpr int size = 65;
constexpr std::size_t nodes = std::size_t{size} * size * size;

irid::ClipPipeline pipeline(irid::ClipMethod method) {
    return irid::ClipPipeline(method, irid::color_space("acescg-linear"), irid::color_space("srgb"));
}

constexpr irid::LutDomain domain{irid::LutShaper::log2, 0.0, 16.0, 14};

std::vector<float> node_inputs() {
    std::vector<float> v(3 * nodes);
    for (std::size_t i = 0; i < nodes; ++i) {
        const std::size_t idx[3] = {i % size, (i / size) % size, i / (std::size_t{size} * size)};
        for (int c = 0; c < 3; ++c) {
            v[3 * i + c] = static_cast<float>(irid::lut_unshape(domain, static_cast<double>(idx[c]) / (size - 1)));
        }
    }
    return v;
}

void BM_Memcpy(benchmark::State& state) {
    const std::vector<float> in = node_inputs();
    std::vector<float> out(in.size());
    for (auto _ : state) {
        std::memcpy(out.data(), in.data(), in.size() * sizeof(float));
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * nodes));
}
BENCHMARK(BM_Memcpy)->Name("Memcpy/65")->UseRealTime()->Unit(benchmark::kMillisecond);

void BM_PipelineClip(benchmark::State& state, irid::ClipMethod method) {
    const irid::ClipPipeline p = pipeline(method);
    const std::vector<float> in = node_inputs();
    std::vector<float> out(in.size());
    for (auto _ : state) {
        p.clip(std::span<const float>(in), std::span<float>(out), irid::BatchOptions{.threads = 0});
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * nodes));
}

void BM_BakeLut(benchmark::State& state, irid::ClipMethod method) {
    const irid::ClipPipeline p = pipeline(method);
    for (auto _ : state) {
        irid::Lut3D lut = irid::bake_lut(p, size, domain);
        benchmark::DoNotOptimize(lut.values.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * nodes));
}

void BM_LutText(benchmark::State& state, irid::LutFormat format) {
    irid::LutDomain uniform = domain;
    if (format == irid::LutFormat::cube) uniform.shaper = irid::LutShaper::none;
    const irid::Lut3D lut = irid::bake_lut(pipeline(irid::ClipMethod::smits), size, uniform);
    for (auto _ : state) {
        std::string text = irid::lut_text(lut, format);
        benchmark::DoNotOptimize(text.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * nodes));
}

const int registered = [] {
    for (const auto method : {irid::ClipMethod::smits, irid::ClipMethod::oklab_cusp,
                              irid::ClipMethod::css_raytrace, irid::ClipMethod::aces_rgc}) {
        const std::string name(irid::clip_method_name(method));
        benchmark::RegisterBenchmark(("PipelineClip/" + name + "/65").c_str(), BM_PipelineClip, method)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("BakeLut/" + name + "/65").c_str(), BM_BakeLut, method)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    }
    benchmark::RegisterBenchmark("LutText/cube/65", BM_LutText, irid::LutFormat::cube)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("LutText/clf/65", BM_LutText, irid::LutFormat::clf)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
    return 0;
}();

}  // namespace
