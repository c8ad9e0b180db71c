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
//
// Reading an image's colours through its ICC profile (irid/exchange/icc.h), one thread, 2^20
// encoded Adobe RGB triples (12 MiB in, 12 MiB out; items are colours):
//   Memcpy/icc                         memcpy of the triples
//   ExactProfile/adobe-rgb             a matrix/TRC profile as irid takes it: the exact RgbSpace's
//                                      Converter (decode, matrix, adapt) to XYZ D65
//   LittleCms/adobe-rgb                the same profile through lcms2's float transform to XYZ
//                                      and irid's Bradford adaptation (the path of LUT profiles)
//   ReadProfile, MakeProfile           parsing a profile (lcms2, transform built); building one

#include <irid/color/convert.h>
#include <irid/exchange/icc.h>
#include <irid/exchange/lut.h>
#include <irid/gamut/pipeline.h>

#include <benchmark/benchmark.h>

#include <cstdint>
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

/// memcpy of a buffer of float triples: the floor of every row beside it. Items are triples.
void memcpy_of(benchmark::State& state, const std::vector<float>& in) {
    std::vector<float> out(in.size());
    for (auto _ : state) {
        std::memcpy(out.data(), in.data(), in.size() * sizeof(float));
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * (in.size() / 3)));
}

void BM_Memcpy(benchmark::State& state) { memcpy_of(state, node_inputs()); }
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

constexpr std::size_t icc_colours = std::size_t{1} << 20;

std::vector<float> encoded_colours() {
    std::vector<float> v(3 * icc_colours);
    std::uint32_t x = 12345;
    for (float& f : v) {
        x = x * 1664525u + 1013904223u;  // Numerical Recipes' LCG: reproducible, cheap
        f = static_cast<float>(x >> 8) / 16777216.0f;
    }
    return v;
}

void BM_IccMemcpy(benchmark::State& state) { memcpy_of(state, encoded_colours()); }
BENCHMARK(BM_IccMemcpy)->Name("Memcpy/icc")->UseRealTime()->Unit(benchmark::kMillisecond);

void BM_ExactProfile(benchmark::State& state) {
    const irid::IccProfile p = irid::IccProfile::parse(irid::make_icc_profile(irid::adobe_rgb()), "bench");
    const irid::ColorSpace from{irid::SpaceFamily::rgb_encoded, &*p.rgb_space()};
    const irid::Converter convert(from, irid::color_space("xyz"));
    const std::vector<float> in = encoded_colours();
    std::vector<float> out(in.size());
    for (auto _ : state) {
        convert.convert(in, out);
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * icc_colours));
}
BENCHMARK(BM_ExactProfile)->Name("ExactProfile/adobe-rgb")->UseRealTime()->Unit(benchmark::kMillisecond);

void BM_LittleCms(benchmark::State& state) {
    const irid::IccProfile p = irid::IccProfile::parse(irid::make_icc_profile(irid::adobe_rgb()), "bench");
    const std::vector<float> in = encoded_colours();
    std::vector<float> out(in.size());
    for (auto _ : state) {
        p.to_xyz(in, out, {0.3127, 0.3290}, 1);
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * icc_colours));
}
BENCHMARK(BM_LittleCms)->Name("LittleCms/adobe-rgb")->UseRealTime()->Unit(benchmark::kMillisecond);

void BM_ReadProfile(benchmark::State& state) {
    const std::vector<unsigned char> bytes = irid::make_icc_profile(irid::display_p3());
    for (auto _ : state) {
        irid::IccProfile p = irid::IccProfile::parse(bytes, "bench");
        benchmark::DoNotOptimize(&p);
    }
}
BENCHMARK(BM_ReadProfile)->Name("ReadProfile/display-p3")->Unit(benchmark::kMicrosecond);

void BM_MakeProfile(benchmark::State& state) {
    for (auto _ : state) {
        std::vector<unsigned char> bytes = irid::make_icc_profile(irid::display_p3());
        benchmark::DoNotOptimize(bytes.data());
    }
}
BENCHMARK(BM_MakeProfile)->Name("MakeProfile/display-p3")->Unit(benchmark::kMicrosecond);

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
