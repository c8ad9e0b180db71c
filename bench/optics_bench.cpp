// Throughput of irid's interference optics.
//
// Items are named in each benchmark: one wavelength sample (one reflectance at one wavelength),
// one colour (a full 1 nm spectrum, 360-830 nm, 471 samples, turned into XYZ), or one table
// lookup. Everything a benchmark needs (materials, stacks, prepared films, tables, thicknesses)
// is built before its timed loop. The thickness changes from one evaluation to the next, taken
// from a precomputed array of pseudo-random thicknesses (std::mt19937, fixed seed), so no result
// can be hoisted or folded; the library functions live in other translation units, and every
// result is passed through DoNotOptimize.
//
// The film of the single-film benchmarks is a soap film, air | water t | air, lit unpolarised
// at 30° in air. The 5-layer stack is air | H L H L H | fused silica, H = Material::constant
// ("high", 2.35) (TiO2-like), L = fused silica, each layer a quarter wave at 550 nm scaled by a
// pseudo-random factor in [0.8, 1.2].
//
// Baselines in the same binary, so that the ratios hold on a noisy machine:
//   BM_MemcpyFilmColor  memcpy of a batch of FilmColor (XYZ + linear RGB, 48 bytes): the cost of
//                       merely reading and writing a colour, the floor of a table lookup.
//   BM_WaterIndex       Material::index of the water Sellmeier model: the dispersion every
//                       unprepared evaluation pays per material and wavelength.
//   BM_ExactFilmColor / BM_PreparedFilmColor: the colour computed from the spectrum, against
//                       which the table lookups and the renderers' closed-form film colours
//                       (BM_RendererFilmRgb) are compared.

#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/color/spectrum.h>
#include <irid/color/types.h>
#include <irid/optics/film_color.h>
#include <irid/optics/fourier_film.h>
#include <irid/optics/material.h>
#include <irid/optics/multilayer.h>
#include <irid/optics/renderer_films.h>
#include <irid/optics/thesis_models.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr std::uint32_t seed = 20240612;
/// Thicknesses cycled through, one per evaluation (a power of two: index & mask).
constexpr std::size_t thickness_count = 256;
constexpr std::size_t thickness_mask = thickness_count - 1;
/// Stacks built in advance for the benchmarks whose thickness lives in a FilmStack.
constexpr std::size_t stack_count = 64;
constexpr std::size_t stack_mask = stack_count - 1;
/// Lookups per batch: 4096 × 48 bytes = 192 KiB out, resident in L2.
constexpr std::size_t lookup_batch_size = 4096;
/// Angle of incidence in air [rad]: 30°.
constexpr double angle_rad = std::numbers::pi / 6.0;
/// Largest thickness of the tables and of the random thicknesses [nm].
constexpr double max_thickness_nm = 1500.0;
constexpr double table_step_nm = 4.0;
/// The 2-D table: cos θ from cos 80° to 1 in 32 steps.
constexpr double table_2d_max_angle_rad = 80.0 * std::numbers::pi / 180.0;
constexpr int table_2d_cos_steps = 32;

const irid::Material& material(const char* name) {
    const irid::Material* m = irid::find_material(name);
    if (m == nullptr) throw std::runtime_error(std::string("no material ") + name);
    return *m;
}

irid::SingleFilm soap_film() {
    return {material("air"), material("water"), material("air")};
}

/// Pseudo-random thicknesses uniform in [lo, hi] nm.
std::vector<double> random_thicknesses(std::size_t n, double lo, double hi,
                                       std::uint32_t s = seed) {
    std::mt19937 rng(s);
    std::uniform_real_distribution<double> d(lo, hi);
    std::vector<double> out(n);
    for (double& t : out) t = d(rng);
    return out;
}

/// One soap-film stack per thickness.
std::vector<irid::FilmStack> soap_stacks(const std::vector<double>& thicknesses) {
    const irid::SingleFilm f = soap_film();
    std::vector<irid::FilmStack> out;
    out.reserve(thicknesses.size());
    for (const double t : thicknesses) {
        out.emplace_back(f.ambient, std::vector{irid::Layer{f.film, t}}, f.substrate);
    }
    return out;
}

/// air | H L H L H | fused silica, quarter waves at 550 nm scaled by a factor in [0.8, 1.2].
std::vector<irid::FilmStack> five_layer_stacks(std::size_t n) {
    const irid::Material high = irid::Material::constant("high", 2.35);
    const irid::Material& low = material("fused-silica");
    const double quarter_high = 550.0 / (4.0 * 2.35);
    const double quarter_low = 550.0 / (4.0 * low.index(550.0).real());
    const std::vector<double> scale = random_thicknesses(n, 0.8, 1.2, seed + 3);
    std::vector<irid::FilmStack> out;
    out.reserve(n);
    for (const double f : scale) {
        std::vector<irid::Layer> layers;
        for (int j = 0; j < 5; ++j) {
            const bool is_high = j % 2 == 0;
            layers.push_back({is_high ? high : low, f * (is_high ? quarter_high : quarter_low)});
        }
        out.emplace_back(material("air"), std::move(layers), low);
    }
    return out;
}

const irid::Colorimeter& colorimeter() {
    static const irid::Colorimeter c(irid::illuminant_d65(), irid::Observer::cie1931_2deg);
    return c;
}

/// Reports items per second and, as "per_item", the time per item (seconds, SI-prefixed).
void report(benchmark::State& state, std::int64_t items_per_iteration) {
    state.SetItemsProcessed(state.iterations() * items_per_iteration);
    state.counters["per_item"] = benchmark::Counter(
        static_cast<double>(items_per_iteration),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

/// Runs f(i, t) for every wavelength index i of the 1 nm grid per iteration, the thickness t
/// taken from the array, and reports one item per wavelength sample.
template <class F>
void run_samples(benchmark::State& state, F f) {
    const std::vector<double> thickness =
        random_thicknesses(thickness_count, 0.0, max_thickness_nm);
    std::array<double, irid::dense_sample_count> out{};
    std::size_t k = 0;
    for (auto _ : state) {
        const std::size_t which = k++ & thickness_mask;
        const double t = thickness[which];
        for (int i = 0; i < irid::dense_sample_count; ++i) {
            out[static_cast<std::size_t>(i)] = f(i, which, t);
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    report(state, irid::dense_sample_count);
}

// --- baselines ----------------------------------------------------------------------------------

void BM_MemcpyFilmColor(benchmark::State& state) {
    std::vector<irid::FilmColor> in(lookup_batch_size);
    for (std::size_t i = 0; i < in.size(); ++i) {
        const auto v = static_cast<double>(i);
        in[i] = {{v, v + 1.0, v + 2.0}, {v, v, v}};
    }
    std::vector<irid::FilmColor> out(lookup_batch_size);
    const irid::FilmColor* src = in.data();
    irid::FilmColor* dst = out.data();
    const std::size_t bytes = lookup_batch_size * sizeof(irid::FilmColor);
    for (auto _ : state) {
        benchmark::DoNotOptimize(src);
        benchmark::DoNotOptimize(dst);
        std::memcpy(dst, src, bytes);
        benchmark::ClobberMemory();
    }
    report(state, static_cast<std::int64_t>(lookup_batch_size));
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_MemcpyFilmColor);

void BM_WaterIndex(benchmark::State& state) {
    const irid::Material& water = material("water");
    run_samples(state, [&](int i, std::size_t, double) {
        return water.index(irid::DenseSpectrum::wavelength_nm(i)).real();
    });
}
BENCHMARK(BM_WaterIndex);

// --- 1. one film, per wavelength sample ----------------------------------------------------------

void BM_SoapFilmStackEvaluate(benchmark::State& state) {
    const std::vector<double> thickness =
        random_thicknesses(thickness_count, 0.0, max_thickness_nm);
    const std::vector<irid::FilmStack> stacks = soap_stacks(thickness);
    run_samples(state, [&](int i, std::size_t which, double) {
        return stacks[which]
            .evaluate(irid::DenseSpectrum::wavelength_nm(i), angle_rad,
                      irid::Polarization::unpolarized)
            .R;
    });
}
BENCHMARK(BM_SoapFilmStackEvaluate);

void BM_SoapFilmAiry(benchmark::State& state) {
    // The indices at each wavelength, as a caller of airy_film would have them.
    const irid::SingleFilm f = soap_film();
    std::vector<double> n0(irid::dense_sample_count);
    std::vector<irid::Complex> n1(irid::dense_sample_count), n2(irid::dense_sample_count);
    for (int i = 0; i < irid::dense_sample_count; ++i) {
        const double lambda = irid::DenseSpectrum::wavelength_nm(i);
        const auto u = static_cast<std::size_t>(i);
        n0[u] = f.ambient.index(lambda).real();
        n1[u] = f.film.index(lambda);
        n2[u] = f.substrate.index(lambda);
    }
    run_samples(state, [&](int i, std::size_t, double t) {
        const auto u = static_cast<std::size_t>(i);
        return irid::airy_film(n0[u], n1[u], n2[u], t, irid::DenseSpectrum::wavelength_nm(i),
                               angle_rad, irid::Polarization::unpolarized)
            .R;
    });
}
BENCHMARK(BM_SoapFilmAiry);

void BM_SoapFilmPreparedReflectance(benchmark::State& state) {
    const irid::PreparedFilm prepared(soap_film(), angle_rad);
    run_samples(state, [&](int i, std::size_t, double t) { return prepared.reflectance(i, t); });
}
BENCHMARK(BM_SoapFilmPreparedReflectance);

// --- 2. a 5-layer stack, per wavelength sample ---------------------------------------------------

void BM_FiveLayerStackEvaluate(benchmark::State& state) {
    const std::vector<irid::FilmStack> stacks = five_layer_stacks(stack_count);
    run_samples(state, [&](int i, std::size_t which, double) {
        return stacks[which & stack_mask]
            .evaluate(irid::DenseSpectrum::wavelength_nm(i), angle_rad,
                      irid::Polarization::unpolarized)
            .R;
    });
}
BENCHMARK(BM_FiveLayerStackEvaluate);

// --- 3. one film, full 1 nm spectrum -> XYZ, per colour ------------------------------------------

/// Runs f(which, t) once per iteration, t from the array; one item per colour.
template <class F>
void run_colors(benchmark::State& state, F f) {
    const std::vector<double> thickness =
        random_thicknesses(thickness_count, 0.0, max_thickness_nm);
    std::size_t k = 0;
    for (auto _ : state) {
        const std::size_t which = k++ & thickness_mask;
        auto c = f(which, thickness[which]);
        benchmark::DoNotOptimize(c);
    }
    report(state, 1);
}

// (a) From scratch: prepares the film at the angle, then integrates 471 samples.
void BM_ExactFilmColor(benchmark::State& state) {
    const irid::SingleFilm f = soap_film();
    const irid::Colorimeter& cm = colorimeter();
    run_colors(state,
               [&](std::size_t, double t) { return irid::exact_film_color(f, t, angle_rad, cm); });
}
BENCHMARK(BM_ExactFilmColor);

// (a') The preparation alone, the part of (a) that (b) does not repeat: indices, Fresnel
// amplitudes and phase per nanometre at 471 wavelengths, stored in a new 41 KiB array.
void BM_PrepareFilm(benchmark::State& state) {
    const irid::SingleFilm f = soap_film();
    for (auto _ : state) {
        const irid::PreparedFilm prepared(f, angle_rad);
        benchmark::DoNotOptimize(&prepared);
        benchmark::ClobberMemory();
    }
    report(state, 1);
}
BENCHMARK(BM_PrepareFilm);

// (b) Prepared once; per colour only the Airy sums and the integration. Arg 0: soap film (real
// fast path), 1: mineral oil on water (real fast path), 2: fused silica on silver (complex path).
void BM_PreparedFilmColor(benchmark::State& state) {
    irid::SingleFilm f = soap_film();
    if (state.range(0) == 1) f = {material("air"), material("mineral-oil"), material("water")};
    if (state.range(0) == 2) f = {material("air"), material("fused-silica"), material("silver")};
    const irid::PreparedFilm prepared(f, angle_rad);
    const irid::Colorimeter& cm = colorimeter();
    run_colors(state, [&](std::size_t, double t) { return prepared.color(t, cm); });
}
BENCHMARK(BM_PreparedFilmColor)->ArgName("film")->Arg(0)->Arg(1)->Arg(2);

// (d) The Fourier series (irid/optics/fourier_film.h): any thickness and any angle per colour,
// nothing prepared per angle, so its peer is (a), from scratch, not (b), prepared at one angle.
// The cosine of the angle cycles through 256 pseudo-random values in [cos 80°, 1]. Arg 0: a
// constant-index soap film (n 1.333 in vacuum, one band); 1: the soap film of water (Sellmeier,
// one band with slopes); 2: mineral oil on water (slopes); 3: a 1.5 film on a constant metal
// index 0.12 + 3.34i (silver near 550 nm, Johnson & Christy 1972; complex r12, one band).
irid::SingleFilm fourier_case(std::int64_t which) {
    switch (which) {
        case 1: return soap_film();
        case 2: return {material("air"), material("mineral-oil"), material("water")};
        case 3:
            return {irid::Material::constant("vacuum", 1.0), irid::Material::constant("film", 1.5),
                    irid::Material::constant("metal", 0.12, 3.34)};
        default:
            return {irid::Material::constant("vacuum", 1.0), irid::Material::constant("soap", 1.333),
                    irid::Material::constant("vacuum", 1.0)};
    }
}

void BM_FourierFilmColor(benchmark::State& state) {
    const irid::SingleFilm f = fourier_case(state.range(0));
    const irid::FourierFilm fourier(f, irid::fourier_colorimeter_for(f, colorimeter()));
    std::mt19937 rng(seed + 1);
    std::uniform_real_distribution<double> cos_theta(std::cos(80.0 * std::numbers::pi / 180.0), 1.0);
    std::vector<double> cosines(thickness_count);
    for (double& c : cosines) c = cos_theta(rng);
    run_colors(state, [&](std::size_t which, double t) { return fourier.xyz(t, cosines[which]); });
}
BENCHMARK(BM_FourierFilmColor)->ArgName("film")->Arg(0)->Arg(1)->Arg(2)->Arg(3);

// (d'') Over the whole grid, thickness 0–5000 nm every 10 nm × angle 0–89° every 1°, in a
// fixed pseudo-random order: the mean cost per colour including the colours left to the 1 nm sum,
// and `fallback` the share of the grid that is. Arg 0: a constant 2.4 film on glass; 1: the soap
// film of water; 2: mineral oil on water; 3: a film of 1.2 under water on 1.6 (past 64° the film
// totally reflects); 4: 1.5 on gold (a metal's table: always summed).
void BM_FourierFilmGrid(benchmark::State& state) {
    const auto film = [](std::int64_t which) -> irid::SingleFilm {
        switch (which) {
            case 0:
                return {irid::Material::constant("vacuum", 1.0), irid::Material::constant("film", 2.4),
                        irid::Material::constant("glass", 1.5)};
            case 1: return soap_film();
            case 2: return {material("air"), material("mineral-oil"), material("water")};
            case 3:
                return {material("water"), irid::Material::constant("film", 1.2),
                        irid::Material::constant("glass", 1.6)};
            default: return {material("air"), irid::Material::constant("film", 1.5), material("gold")};
        }
    };
    const irid::SingleFilm f = film(state.range(0));
    const irid::FourierFilm fourier(f, irid::fourier_colorimeter_for(f, colorimeter()));
    std::vector<std::pair<double, double>> grid;
    for (int a = 0; a <= 89; ++a) {
        for (int t = 0; t <= 5000; t += 10) grid.emplace_back(t, std::cos(a * std::numbers::pi / 180.0));
    }
    std::shuffle(grid.begin(), grid.end(), std::mt19937(seed + 2));
    std::size_t summed = 0;
    for (const auto& [t, c] : grid) summed += fourier.summed_at(t, c) ? 1 : 0;
    std::size_t k = 0;
    for (auto _ : state) {
        const auto& [t, c] = grid[k++ % grid.size()];
        auto x = fourier.xyz(t, c);
        benchmark::DoNotOptimize(x);
    }
    report(state, 1);
    state.counters["fallback"] = static_cast<double>(summed) / static_cast<double>(grid.size());
}
BENCHMARK(BM_FourierFilmGrid)->ArgName("film")->DenseRange(0, 4);

// (d') Building the transforms for a colorimeter (once per illuminant and observer): one band,
// and one band with its slope table.
void BM_FourierColorimeterBuild(benchmark::State& state) {
    const bool slopes = state.range(0) != 0;
    for (auto _ : state) {
        const irid::FourierColorimeter table(colorimeter(), 1, slopes);
        benchmark::DoNotOptimize(&table);
        benchmark::ClobberMemory();
    }
    report(state, 1);
}
BENCHMARK(BM_FourierColorimeterBuild)->ArgName("slopes")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// (b') The renderers' closed-form film colours (renderer_films.h), one RGB per item, the same
// pseudo-random thicknesses and angle, beside (b) as their baseline. Arg model: 0 glTF, 1 Belcour
// & Barla, 2 Cycles; film: 0 soap film (one base index), 1 a film of 1.5 on gold (three).
void BM_RendererFilmRgb(benchmark::State& state) {
    const auto model = static_cast<irid::RendererFilmModel>(state.range(0));
    irid::SingleFilm f = soap_film();
    if (state.range(1) == 1) f = {material("air"), irid::Material::constant("film", 1.5), material("gold")};
    const irid::RendererFilmInputs inputs = irid::renderer_film_inputs(f);
    (void)irid::cycles_sensitivity_table();  // built once, outside the timed loop
    run_colors(state, [&](std::size_t, double t) { return irid::renderer_film_rgb(model, inputs, t, angle_rad); });
}
BENCHMARK(BM_RendererFilmRgb)->ArgNames({"model", "film"})->ArgsProduct({{0, 1, 2}, {0, 1}});

// (c) The generic path: transfer-matrix spectrum of the one-layer stack, then XYZ.
void BM_StackSpectrumXyz(benchmark::State& state) {
    const std::vector<double> thickness =
        random_thicknesses(thickness_count, 0.0, max_thickness_nm);
    const std::vector<irid::FilmStack> stacks = soap_stacks(thickness);
    const irid::Colorimeter& cm = colorimeter();
    run_colors(state, [&](std::size_t which, double) {
        return cm.xyz(irid::exact_reflectance_spectrum(stacks[which], angle_rad));
    });
}
BENCHMARK(BM_StackSpectrumXyz);

// (c') The same for the 5-layer stack.
void BM_FiveLayerSpectrumXyz(benchmark::State& state) {
    const std::vector<irid::FilmStack> stacks = five_layer_stacks(stack_count);
    const irid::Colorimeter& cm = colorimeter();
    run_colors(state, [&](std::size_t which, double) {
        return cm.xyz(irid::exact_reflectance_spectrum(stacks[which & stack_mask], angle_rad));
    });
}
BENCHMARK(BM_FiveLayerSpectrumXyz);

// (d) The thesis' single-film model (eq. 21/22 with eq. 24) on the real materials, then XYZ.
void BM_ThesisSpectrumXyz(benchmark::State& state) {
    const irid::SingleFilm f = soap_film();
    const irid::Colorimeter& cm = colorimeter();
    run_colors(state, [&](std::size_t, double t) {
        return cm.xyz(irid::thesis_single_film_spectrum(f, t, angle_rad));
    });
}
BENCHMARK(BM_ThesisSpectrumXyz);

// --- 4. table lookups, per lookup ----------------------------------------------------------------

/// Runs out[i] = f(i) over a batch of lookup_batch_size lookups per iteration. The inputs are
/// pseudo-random and the lookups out of line, so nothing needs escaping but the output. (An
/// input pointer passed through DoNotOptimize and then captured by reference here crashed: GCC
/// 12 compiled Google Benchmark 1.7.1's "+m,r" asm constraint without ever storing the pointer
/// to the stack slot it then read; "+m" or "+r" alone were correct.)
template <class F>
void run_lookups(benchmark::State& state, F f) {
    std::vector<irid::FilmColor> out(lookup_batch_size);
    irid::FilmColor* dst = out.data();
    for (auto _ : state) {
        benchmark::DoNotOptimize(dst);
        for (std::size_t i = 0; i < lookup_batch_size; ++i) dst[i] = f(i);
        benchmark::ClobberMemory();
    }
    report(state, static_cast<std::int64_t>(lookup_batch_size));
}

void BM_TableLookup(benchmark::State& state) {
    const irid::FilmColorTable table = irid::exact_film_color_table(
        soap_film(), angle_rad, max_thickness_nm, table_step_nm, colorimeter());
    const std::vector<double> thickness =
        random_thicknesses(lookup_batch_size, 0.0, max_thickness_nm);
    run_lookups(state, [&](std::size_t i) { return table.at(thickness[i]); });
}
BENCHMARK(BM_TableLookup);

void BM_Table2DLookup(benchmark::State& state) {
    const irid::FilmColorTable2D table =
        irid::exact_film_color_table_2d(soap_film(), max_thickness_nm, table_step_nm,
                                        table_2d_max_angle_rad, table_2d_cos_steps, colorimeter());
    const std::vector<double> thickness =
        random_thicknesses(lookup_batch_size, 0.0, max_thickness_nm);
    const std::vector<double> cosine =
        random_thicknesses(lookup_batch_size, std::cos(table_2d_max_angle_rad), 1.0, seed + 1);
    run_lookups(state, [&](std::size_t i) { return table.at(thickness[i], cosine[i]); });
}
BENCHMARK(BM_Table2DLookup);

}  // namespace
