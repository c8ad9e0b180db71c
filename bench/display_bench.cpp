// Throughput of the ACES 2.0 display chain (issue 27) on one thread: the float SIMD kernel
// (Aces2Kernel) and the double reference (Aces2Output, colour by colour), forward and inverse,
// for sdr-100nit-rec709 and hdr-1000nit-p3-d65, beside memcpy of the same buffer.
//
// Input: 2^20 ACES2065-1 colours uniform in [-0.5, 64]^3 (std::mt19937, fixed seed; the range of
// the continuity walk), 12 MiB in and 12 MiB out. The inverse rows take the display's
// forward output of those colours (CIE XYZ, 1.0 = 100 cd/m²), computed before the timed loop.
// One item is one colour; "per_item" is the time per colour; "flagged" is the fraction of
// colours the kernel handed to the double chain.
//
// Rows:
//   Memcpy                             memcpy of the input into the output buffer
//   Kernel/<display>/<direction>       Aces2Kernel::run, the widest instruction set of this CPU
//   Kernel/<display>/forward/avx2      the same with Highway restricted to AVX2 at run time
//   Double/<display>/<direction>       Aces2Output::forward or ::inverse per colour
//
// Every row is timed in wall-clock time (UseRealTime). The kernel and the chain live in another
// translation unit; the output is made observable with ClobberMemory.

#include <irid/gamut/aces2_display.h>
#include <irid/gamut/aces2_kernel.h>
#include <irid/gamut/batch.h>

#include <benchmark/benchmark.h>
#include <hwy/targets.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr std::size_t colours = std::size_t{1} << 20;
constexpr std::uint32_t input_seed = 20261206;

/// The AVX-512 targets of Highway 1.0.3 (hwy/detect_targets.h), disabled for the AVX2 rows.
constexpr std::int64_t avx512_targets = HWY_AVX3 | HWY_AVX3_DL;

const std::vector<float>& scene_input() {
    static const std::vector<float> in = [] {
        std::mt19937 rng(input_seed);
        std::uniform_real_distribution<float> u(-0.5f, 64.0f);
        std::vector<float> v(3 * colours);
        for (float& x : v) x = u(rng);
        return v;
    }();
    return in;
}

const irid::Aces2Output& output(const std::string& name) {
    static std::map<std::string, std::unique_ptr<const irid::Aces2Output>> built;
    auto& o = built[name];
    if (!o) o = std::make_unique<const irid::Aces2Output>(irid::aces2_display(name));
    return *o;
}

/// The display's forward output of the scene input: the inverse rows' input.
const std::vector<float>& display_input(const std::string& name) {
    static std::map<std::string, std::vector<float>> built;
    std::vector<float>& v = built[name];
    if (v.empty()) {
        v.resize(scene_input().size());
        (void)irid::Aces2Kernel(output(name), false).run(scene_input(), v);
    }
    return v;
}

void report(benchmark::State& state) {
    const auto iterations = static_cast<std::int64_t>(state.iterations());
    state.SetItemsProcessed(iterations * static_cast<std::int64_t>(colours));
    state.SetBytesProcessed(iterations * static_cast<std::int64_t>(3 * sizeof(float) * colours));
    state.counters["per_item"] = benchmark::Counter(
        static_cast<double>(colours),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void memcpy_row(benchmark::State& state) {
    const std::vector<float>& in = scene_input();
    std::vector<float> out(in.size(), 0.0f);
    const float* src = in.data();
    float* dst = out.data();
    for (auto _ : state) {
        benchmark::DoNotOptimize(src);
        benchmark::DoNotOptimize(dst);
        std::memcpy(dst, src, in.size() * sizeof(float));
        benchmark::ClobberMemory();
    }
    report(state);
    state.SetLabel("memcpy");
}

void kernel_row(benchmark::State& state, const std::string& name, bool inverse, bool avx2_only) {
    const std::vector<float>& in = inverse ? display_input(name) : scene_input();
    if (avx2_only) hwy::DisableTargets(avx512_targets);
    const irid::Aces2Kernel kernel(output(name), inverse);
    std::vector<float> out(in.size(), 0.0f);
    std::size_t flagged = 0;
    for (auto _ : state) {
        flagged = kernel.run(in, out);
        benchmark::ClobberMemory();
    }
    report(state);
    state.counters["flagged"] = static_cast<double>(flagged) / static_cast<double>(colours);
    state.SetLabel("simd " + std::string(irid::simd_target_name()));
    if (avx2_only) hwy::DisableTargets(0);
}

void double_row(benchmark::State& state, const std::string& name, bool inverse) {
    const std::vector<float>& in = inverse ? display_input(name) : scene_input();
    const irid::Aces2Output& o = output(name);
    std::vector<float> out(in.size(), 0.0f);
    for (auto _ : state) {
        for (std::size_t i = 0; i < in.size(); i += 3) {
            irid::Vec3 r;
            if (!inverse) {
                const irid::Xyz x = o.forward({in[i], in[i + 1], in[i + 2]});
                r = {x.X, x.Y, x.Z};
            } else {
                r = o.inverse({in[i], in[i + 1], in[i + 2]});
            }
            for (std::size_t c = 0; c < 3; ++c) out[i + c] = static_cast<float>(r[c]);
        }
        benchmark::ClobberMemory();
    }
    report(state);
    state.SetLabel("double reference");
}

const bool registered = [] {
    benchmark::RegisterBenchmark("Memcpy", memcpy_row)->UseRealTime();
    for (const std::string name : {"sdr-100nit-rec709", "hdr-1000nit-p3-d65"}) {
        for (const bool inverse : {false, true}) {
            const std::string direction = inverse ? "inverse" : "forward";
            benchmark::RegisterBenchmark(("Kernel/" + name + "/" + direction).c_str(), kernel_row,
                                         name, inverse, false)
                ->UseRealTime();
            if (!inverse)
                benchmark::RegisterBenchmark(("Kernel/" + name + "/forward/avx2").c_str(),
                                             kernel_row, name, false, true)
                    ->UseRealTime();
            benchmark::RegisterBenchmark(("Double/" + name + "/" + direction).c_str(), double_row,
                                         name, inverse)
                ->UseRealTime();
        }
    }
    return true;
}();

}  // namespace
