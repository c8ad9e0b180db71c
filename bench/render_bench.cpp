// Throughput of the renderer: each of the thesis' scenes rendered with the thesis' table path
// and with a spectrum per ray (the spectral path), on one thread (rays per second per core)
// and on all threads, at 1024×768 and 4 samples per pixel unless IRID_BENCH_SIZE says
// otherwise ("WIDTHxHEIGHT", e.g. 256x192 for a quick run).
//
// The table path is the spectral path's baseline, in the same binary and the same run: the
// spectral benchmarks report speed_up (spectral time / table time) and the CIEDE2000 between
// the two images per pixel (mean and 99th percentile), which must stay below 1 on average for
// the tables to be a fair shortcut.
//
// Counters: rays/s (all rays: camera, reflected, transmitted), rays/s/core (divided by the
// threads used), seconds (wall time of one render, the tables included), table_s (building the
// colour tables).

#include <irid/render/render.h>
#include <irid/render/scene.h>

#include <benchmark/benchmark.h>
#include <tbb/info.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace irid::render;

std::pair<int, int> bench_size() {
    int w = 1024, h = 768;
    if (const char* s = std::getenv("IRID_BENCH_SIZE")) {
        if (std::sscanf(s, "%dx%d", &w, &h) != 2 || w < 8 || h < 8) {
            std::fprintf(stderr, "IRID_BENCH_SIZE must be WIDTHxHEIGHT, e.g. 256x192\n");
            std::exit(2);
        }
    }
    return {w, h};
}

/// The table path's XYZ image per scene and thread count, for the spectral path's ΔE.
std::map<std::string, irid::io::Image>& table_images() {
    static std::map<std::string, irid::io::Image> images;
    return images;
}
std::map<std::string, double>& table_seconds() {
    static std::map<std::string, double> seconds;
    return seconds;
}

void BM_Render(benchmark::State& state, const std::string& scene_name, ColorPath path, int threads) {
    const auto [w, h] = bench_size();
    std::vector<std::string> set = {"image.width=" + std::to_string(w),
                                    "image.height=" + std::to_string(h), "image.spp=4"};
    if (path == ColorPath::spectral) set.push_back("render.path=spectral");
    const Scene scene = load_scene(scene_name, set);
    RenderOptions options;
    options.threads = threads;
    RenderResult result;
    for (auto _ : state) {
        result = render(scene, options);
        benchmark::DoNotOptimize(result.xyz.pixels.data());
    }
    const int used = threads == 0 ? tbb::info::default_concurrency() : threads;
    const double s = result.stats.seconds;
    const auto rays = static_cast<double>(result.stats.rays);
    state.counters["rays/s"] = rays / s;
    state.counters["rays/s/core"] = rays / s / used;
    state.counters["seconds"] = s;
    state.counters["table_s"] = result.stats.table_seconds;
    state.SetItemsProcessed(static_cast<std::int64_t>(result.stats.rays));
    const std::string key = scene_name + "/" + std::to_string(threads);
    if (path == ColorPath::table) {
        table_images()[key] = result.xyz;
        table_seconds()[key] = s;
    } else if (const auto it = table_images().find(key); it != table_images().end()) {
        const ImageDifference d = delta_e_2000_images(it->second, result.xyz);
        state.counters["dE2000_mean"] = d.mean;
        state.counters["dE2000_p99"] = d.p99;
        state.counters["speed_up"] = s / table_seconds()[key];
    }
}

void register_all() {
    for (const int threads : {1, 0}) {
        for (const std::string scene : {"oil-slick", "soap-bubbles", "morpho"}) {
            for (const ColorPath path : {ColorPath::table, ColorPath::spectral}) {
                const std::string name = "BM_Render/" + scene + "/" +
                                         (path == ColorPath::table ? "table" : "spectral") +
                                         "/threads:" + (threads == 0 ? "all" : "1");
                benchmark::RegisterBenchmark(name.c_str(), BM_Render, scene, path, threads)
                    ->Iterations(1)
                    ->Unit(benchmark::kSecond)
                    ->UseRealTime();
            }
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    register_all();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
