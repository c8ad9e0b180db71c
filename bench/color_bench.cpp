// Throughput of irid's colour core.
//
// Every benchmark converts a fixed batch of pseudo-random inputs (std::mt19937, fixed seed,
// prepared outside the timed loop) into a preallocated output array and reports items per
// second, one item being one colour (one pair for CIEDE2000, one spectrum for spectrum -> XYZ).
// The library functions live in another translation unit, so their calls cannot be folded
// away; the inputs and outputs are escaped with DoNotOptimize and the stores made observable
// with ClobberMemory so the baselines, which are inline, cannot be elided or hoisted either.
//
// Baselines, built into the same binary so that ratios stay meaningful on a noisy machine:
//   BM_MemcpyXyz       memcpy of the same batch of XYZ triples: the cost of merely reading
//                      and writing 24 bytes per colour, the floor of any conversion.
//   BM_LinearSrgbToXyz irid::srgb().to_xyz, a 3x3 matrix product: the cheapest real
//                      conversion (no transcendental functions, no branches).
//   BM_MemcpyDram      memcpy of 8 M colours (192 MB), beside the batch converter on them.
//   BM_SpectrumDotFloor three dot products of a 471-sample reflectance with weight vectors
//                      S(λ)·x̄(λ)/k, S(λ)·ȳ(λ)/k, S(λ)·z̄(λ)/k precomputed once: the arithmetic
//                      floor of spectrum -> XYZ (3 × 471 multiply-adds, no normalisation).

#include <irid/color/convert.h>
#include <irid/color/difference.h>
#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/color/spectrum.h>
#include <irid/color/types.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

namespace {

/// Colours per batch: 4096 × 24 bytes = 96 KiB in and out, resident in L2.
constexpr std::size_t batch_size = 4096;
/// Spectra per batch: 256 × 471 × 8 bytes ≈ 0.94 MiB, also resident in L2.
constexpr std::size_t spectrum_batch_size = 256;
constexpr std::uint32_t seed = 20240611;

// --- inputs -------------------------------------------------------------------------------------

/// Linear sRGB uniform in the unit cube: in-gamut colours, a few of them dark enough to take
/// the linear segment of L*.
std::vector<irid::Rgb> random_linear_rgb(std::size_t n, std::uint32_t s = seed) {
    std::mt19937 rng(s);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<irid::Rgb> out(n);
    for (irid::Rgb& c : out) c = {unit(rng), unit(rng), unit(rng)};
    return out;
}

/// XYZ (D65, Y = 1 white) of those colours.
std::vector<irid::Xyz> random_xyz(std::size_t n) {
    const std::vector<irid::Rgb> rgb = random_linear_rgb(n);
    std::vector<irid::Xyz> out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = irid::srgb().to_xyz(rgb[i]);
    return out;
}

/// Pairs of CIELAB colours a small distance apart (|Δ| up to 5 per coordinate), the regime
/// CIEDE2000 is meant for.
struct LabPair {
    irid::Lab a, b;
};
std::vector<LabPair> random_lab_pairs(std::size_t n) {
    const std::vector<irid::Xyz> xyz = random_xyz(n);
    const irid::Xyz& white = irid::srgb().white_xyz();
    std::mt19937 rng(seed + 1);
    std::uniform_real_distribution<double> delta(-5.0, 5.0);
    std::vector<LabPair> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        const irid::Lab a = irid::xyz_to_lab(xyz[i], white);
        out[i] = {a, {a.L + delta(rng), a.a + delta(rng), a.b + delta(rng)}};
    }
    return out;
}

/// Smooth reflectances in [0.1, 0.9]: a sinusoid of random period and phase over 360-830 nm.
std::vector<irid::DenseSpectrum> random_reflectances(std::size_t n) {
    std::mt19937 rng(seed + 2);
    std::uniform_real_distribution<double> period(100.0, 600.0);
    std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
    std::vector<irid::DenseSpectrum> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double p = period(rng);
        const double ph = phase(rng);
        out.push_back(irid::DenseSpectrum::from_function([&](double lambda) {
            return 0.5 + 0.4 * std::sin(2.0 * std::numbers::pi * lambda / p + ph);
        }));
    }
    return out;
}

// --- harness ------------------------------------------------------------------------------------

/// Runs out[i] = f(in[i]) over the whole batch per iteration and reports items per second.
template <class In, class Out, class F>
void run_batch(benchmark::State& state, const std::vector<In>& in, std::vector<Out>& out, F f) {
    const In* src = in.data();
    Out* dst = out.data();
    const std::size_t n = in.size();
    for (auto _ : state) {
        benchmark::DoNotOptimize(src);
        benchmark::DoNotOptimize(dst);
        for (std::size_t i = 0; i < n; ++i) dst[i] = f(src[i]);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

// --- baselines ----------------------------------------------------------------------------------

void BM_MemcpyXyz(benchmark::State& state) {
    const std::vector<irid::Xyz> in = random_xyz(batch_size);
    std::vector<irid::Xyz> out(batch_size);
    const irid::Xyz* src = in.data();
    irid::Xyz* dst = out.data();
    const std::size_t bytes = batch_size * sizeof(irid::Xyz);
    for (auto _ : state) {
        benchmark::DoNotOptimize(src);
        benchmark::DoNotOptimize(dst);
        std::memcpy(dst, src, bytes);
        benchmark::ClobberMemory();
    }
    const auto iterations = static_cast<std::int64_t>(state.iterations());
    state.SetItemsProcessed(iterations * static_cast<std::int64_t>(batch_size));
    state.SetBytesProcessed(iterations * static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_MemcpyXyz);

void BM_LinearSrgbToXyz(benchmark::State& state) {
    const std::vector<irid::Rgb> in = random_linear_rgb(batch_size);
    std::vector<irid::Xyz> out(batch_size);
    const irid::RgbSpace& space = irid::srgb();
    run_batch(state, in, out, [&](const irid::Rgb& c) { return space.to_xyz(c); });
}
BENCHMARK(BM_LinearSrgbToXyz);

// --- conversions --------------------------------------------------------------------------------

void BM_XyzToLab(benchmark::State& state) {
    const std::vector<irid::Xyz> in = random_xyz(batch_size);
    std::vector<irid::Lab> out(batch_size);
    const irid::Xyz white = irid::srgb().white_xyz();
    run_batch(state, in, out, [&](const irid::Xyz& c) { return irid::xyz_to_lab(c, white); });
}
BENCHMARK(BM_XyzToLab);

void BM_XyzToLuv(benchmark::State& state) {
    const std::vector<irid::Xyz> in = random_xyz(batch_size);
    std::vector<irid::Luv> out(batch_size);
    const irid::Xyz white = irid::srgb().white_xyz();
    run_batch(state, in, out, [&](const irid::Xyz& c) { return irid::xyz_to_luv(c, white); });
}
BENCHMARK(BM_XyzToLuv);

void BM_XyzToOklab(benchmark::State& state) {
    const std::vector<irid::Xyz> in = random_xyz(batch_size);
    std::vector<irid::Oklab> out(batch_size);
    run_batch(state, in, out, [](const irid::Xyz& c) { return irid::xyz_to_oklab(c); });
}
BENCHMARK(BM_XyzToOklab);

// The batch converter (irid/color/convert.h): linear sRGB → Oklab on every SIMD lane
// (src/color/convert_simd.cpp), on the L2-resident batch and on 8 M colours (192 MB of float64,
// six times a 32 MiB L3), beside memcpy of the same bytes: BM_XyzToOklab above is the scalar
// path (std::cbrt) on the same kind of input.
void converter_batch(benchmark::State& state, std::size_t colours, bool copy) {
    const std::vector<irid::Rgb> rgb = random_linear_rgb(colours);
    std::vector<double> in(3 * colours), out(3 * colours);
    for (std::size_t i = 0; i < colours; ++i) {
        in[3 * i] = rgb[i].r, in[3 * i + 1] = rgb[i].g, in[3 * i + 2] = rgb[i].b;
    }
    const irid::Converter c(irid::color_space("srgb-linear"), irid::color_space("oklab"));
    for (auto _ : state) {
        benchmark::DoNotOptimize(in.data());
        if (copy) std::memcpy(out.data(), in.data(), in.size() * sizeof(double));
        else c.convert(in, out);
        benchmark::ClobberMemory();
    }
    const auto iterations = static_cast<std::int64_t>(state.iterations());
    state.SetItemsProcessed(iterations * static_cast<std::int64_t>(colours));
    state.SetBytesProcessed(iterations * static_cast<std::int64_t>(in.size() * sizeof(double)));
}
void BM_ConverterOklabBatch(benchmark::State& state) { converter_batch(state, batch_size, false); }
BENCHMARK(BM_ConverterOklabBatch);
void BM_ConverterOklabBatchDram(benchmark::State& state) { converter_batch(state, std::size_t{1} << 23, false); }
BENCHMARK(BM_ConverterOklabBatchDram)->Unit(benchmark::kMillisecond);
void BM_MemcpyDram(benchmark::State& state) { converter_batch(state, std::size_t{1} << 23, true); }
BENCHMARK(BM_MemcpyDram)->Unit(benchmark::kMillisecond);

void BM_DeltaE2000(benchmark::State& state) {
    const std::vector<LabPair> in = random_lab_pairs(batch_size);
    std::vector<double> out(batch_size);
    run_batch(state, in, out, [](const LabPair& p) { return irid::delta_e_2000(p.a, p.b); });
}
BENCHMARK(BM_DeltaE2000);

// --- spectra ------------------------------------------------------------------------------------

void BM_ReflectanceToXyz(benchmark::State& state) {
    const std::vector<irid::DenseSpectrum> in = random_reflectances(spectrum_batch_size);
    std::vector<irid::Xyz> out(spectrum_batch_size);
    const irid::DenseSpectrum d65 = irid::illuminant_d65();
    run_batch(state, in, out, [&](const irid::DenseSpectrum& r) {
        return irid::reflectance_to_xyz(r, d65, irid::Observer::cie1931_2deg);
    });
}
BENCHMARK(BM_ReflectanceToXyz);

void BM_SpectrumDotFloor(benchmark::State& state) {
    const std::vector<irid::DenseSpectrum> in = random_reflectances(spectrum_batch_size);
    std::vector<irid::Xyz> out(spectrum_batch_size);
    // The weights reflectance_to_xyz applies, folded into three vectors once.
    const irid::DenseSpectrum d65 = irid::illuminant_d65();
    const irid::ColorMatchingFunctions& cmf =
        irid::color_matching_functions(irid::Observer::cie1931_2deg);
    const double k = 1.0 / d65.dot(cmf.y);
    const irid::DenseSpectrum wx = d65 * cmf.x * k;
    const irid::DenseSpectrum wy = d65 * cmf.y * k;
    const irid::DenseSpectrum wz = d65 * cmf.z * k;
    const double* px = wx.values().data();
    const double* py = wy.values().data();
    const double* pz = wz.values().data();
    benchmark::DoNotOptimize(px);
    benchmark::DoNotOptimize(py);
    benchmark::DoNotOptimize(pz);
    run_batch(state, in, out, [&](const irid::DenseSpectrum& r) {
        const double* pr = r.values().data();
        double x = 0.0, y = 0.0, z = 0.0;
        for (int i = 0; i < irid::dense_sample_count; ++i) {
            x += pr[i] * px[i];
            y += pr[i] * py[i];
            z += pr[i] * pz[i];
        }
        return irid::Xyz{x, y, z};
    });
}
BENCHMARK(BM_SpectrumDotFloor);

}  // namespace
