// irid render: the thesis' scenes (Smits 1990 Figures 7, 8 and 9) as images.
//
//   irid render SCENE [-o OUT] [--width W] [--height H] [--spp N] [--threads N] [--seed S]
//                     [--clip METHOD] [--set key=value ...] [--linear FILE.exr] [--quiet]
//
// SCENE is a built-in name (oil-slick, soap-bubbles, morpho) or a JSON file (scenes/*.json show
// every key). OUT's extension picks PNG, TIFF or EXR (default: SCENE's name + .png); an EXR OUT
// holds the displayed values decoded to linear (after the view transform and the clip),
// --linear the scene-referred ones (before both). The files appear only when
// complete, both or neither; a failed run leaves existing files as they were. Exit 0 on success,
// 1 for a bad scene file or failed I/O, 2 for bad options (including --set values the scene
// refuses).
#include "../cli_common.h"

#include <irid/error.h>
#include <irid/exchange/icc.h>
#include <irid/gamut/clip.h>
#include <irid/io/image.h>
#include <irid/io/output_file.h>
#include <irid/render/render.h>
#include <irid/render/scene.h>

#include <fmt/core.h>

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace irid::cli {
namespace {

struct RenderCliOptions {
    std::string scene;
    std::optional<std::string> out;     // given but empty is an error, not the default name
    std::optional<std::string> linear;
    std::optional<int> width, height, spp;
    int threads = 0;
    std::optional<std::uint64_t> seed;
    std::string clip;
    std::vector<std::string> assignments;
    bool quiet = false;
};

std::string default_output(const std::string& scene) {
    return std::filesystem::path(scene).stem().string() + ".png";
}

/// A progress bar on stderr: "render [#####.....] 52%".
class ProgressBar {
public:
    void operator()(int done, int total) {
        std::lock_guard lock(m_mutex);
        const int percent = static_cast<int>(100.0 * done / total);
        if (percent <= m_last) return;  // a slower thread may report an older count
        m_last = percent;
        constexpr int width = 40;
        const int filled = width * done / total;
        fmt::print(stderr, "\rrender [{}{}] {:3d}%", std::string(filled, '#'),
                   std::string(width - filled, '.'), percent);
        if (done == total) fmt::print(stderr, "\n");
        std::fflush(stderr);
    }

private:
    std::mutex m_mutex;
    int m_last = -1;
};

int run_render(const RenderCliOptions& o) {
    // The file (or built-in scene) alone first: its errors are bad data (exit 1).
    (void)render::load_scene(o.scene);

    std::vector<std::string> overrides = o.assignments;
    // --width or --height alone keeps the scene's aspect ratio (after its --set values).
    render::Scene shape;  // read only when one side alone is given
    if (o.width.has_value() != o.height.has_value()) {
        try {
            shape = render::load_scene(o.scene, overrides);
        } catch (const Error& e) {
            throw UsageError(fmt::format("{} (from the command line's options)", e.what()));
        }
    }
    for (std::string& size : render::image_size_overrides(shape, o.width, o.height))
        overrides.push_back(std::move(size));
    if (o.spp) overrides.push_back(fmt::format("image.spp={}", *o.spp));
    if (o.seed) overrides.push_back(fmt::format("render.seed={}", *o.seed));
    if (!o.clip.empty()) {
        try {
            (void)parse_clip_method(o.clip);
        } catch (const Error& e) {
            throw UsageError(fmt::format("--clip: {}", e.what()));
        }
        overrides.push_back("render.clip=\"" + o.clip + "\"");
    }
    render::Scene scene;
    try {
        scene = render::load_scene(o.scene, overrides);
    } catch (const Error& e) {
        throw UsageError(fmt::format("{} (from the command line's options)", e.what()));
    }

    namespace fs = std::filesystem;
    const std::string out = o.out ? *o.out : default_output(o.scene);
    io::ImageFormat format;
    try {
        format = io::image_format_for(out);
        check_file_holds(*find_rgb_space(scene.render.space), format);
    } catch (const Error& e) {
        throw UsageError(fmt::format("-o: {}", e.what()));
    }
    if (o.linear) {
        bool exr = false;
        try {
            exr = io::image_format_for(*o.linear) == io::ImageFormat::exr;
        } catch (const Error&) {  // any other extension: the same message
        }
        if (!exr) throw UsageError(fmt::format("--linear: '{}' must end in .exr", *o.linear));
        if (fs::absolute(*o.linear).lexically_normal() == fs::absolute(out).lexically_normal())
            throw UsageError(fmt::format("--linear: '{}' is also the output image (-o)", *o.linear));
    }
    // A missing folder (or a folder named as the file) fails now, not after the render; the
    // check creates nothing.
    (void)io::check_output_path(out);
    if (o.linear) (void)io::check_output_path(*o.linear);

    render::RenderOptions options;
    options.threads = o.threads;
    ProgressBar bar;
    if (!o.quiet && isatty(STDERR_FILENO)) options.progress = [&](int d, int t) { bar(d, t); };
    const render::RenderResult result = render::render(scene, options);

    io::Image image = result.display;
    const RgbSpace& space = *find_rgb_space(scene.render.space);
    if (format == io::ImageFormat::exr) {  // the clipped values, linear (whole colours: HLG's curve needs them)
        for (std::size_t i = 0; i + 2 < image.pixels.size(); i += 3) {
            const Rgb v = space.decode({image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]});
            image.pixels[i] = static_cast<float>(v.r);
            image.pixels[i + 1] = static_cast<float>(v.g);
            image.pixels[i + 2] = static_cast<float>(v.b);
        }
    }
    // Every output says its space to other programs: an ICC profile or EXR chromaticities.
    tag_image(image, space, format);
    image.description = fmt::format("irid render {} ({}×{}, {} spp, {} path, {} optics, view {}, clip {})",
                                     scene.source, scene.image.width, scene.image.height,
                                     scene.image.spp,
                                     render::color_path_name(scene.render.path),
                                     scene.render.optics == render::OpticsModel::exact ? "exact" : "thesis",
                                     scene.render.view == render::ViewTransform::aces2
                                         ? "aces2 " + scene.render.display
                                         : std::string(render::view_transform_name(scene.render.view)),
                                     clip_method_name(scene.render.clip));
    // Both files or neither: each is written whole under a temporary name beside its target,
    // and both are renamed into place only when both are complete.
    io::OutputFile main_file(out);
    // PQ's and HLG's 8-bit steps are visible: such a display image is written with 16 bits.
    const bool pq = space.transfer().kind() == TransferFunction::Kind::pq ||
                    space.transfer().kind() == TransferFunction::Kind::hlg;
    io::write_image(main_file, image, io::ImageEncoding{.bits = pq ? 16 : 8, .compression = {}});
    if (o.linear) {
        io::Image linear = result.linear;
        tag_image(linear, space, io::image_format_for(*o.linear));
        linear.description = image.description + ", unclipped";
        io::OutputFile linear_file(*o.linear);
        io::write_image(linear_file, linear);
        linear_file.commit();
    }
    main_file.commit();
    if (!o.quiet) {
        const auto& s = result.stats;
        // Rays per second of the tracing alone: building the colour tables (the exact Morpho's
        // takes most of its run) is counted apart.
        const double tracing = std::max(s.seconds - s.table_seconds, 1e-9);
        fmt::print(stderr,
                   "irid render: wrote {} ({}×{}, {} spp) in {:.2f} s ({:.2f} s building colour "
                   "tables, {:.2f} s tracing {:.3g} M rays/s), {:.1f} % of pixels out of gamut "
                   "before the clip\n",
                   out, scene.image.width, scene.image.height, scene.image.spp, s.seconds,
                   s.table_seconds, tracing, static_cast<double>(s.rays) / tracing * 1e-6,
                   100.0 * static_cast<double>(s.out_of_gamut_pixels) /
                       (static_cast<double>(scene.image.width) * scene.image.height));
    }
    return exit_success;
}

}  // namespace

void add_render_command(CLI::App& app, Runner& runner) {
    auto o = std::make_shared<RenderCliOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Render one of the thesis' scenes (oil-slick, soap-bubbles, morpho) or a JSON scene");
    cmd->add_option("scene", o->scene,
                    "oil-slick, soap-bubbles, morpho, or a JSON scene file (see scenes/)")
        ->required();
    cmd->add_option("-o,--output", o->out, "Output image: .png, .tif/.tiff or .exr (default: SCENE.png)");
    cmd->add_option("--width", o->width, "Image width in pixels")
        ->transform(whole_number_in(1, render::max_image_side));
    cmd->add_option("--height", o->height, "Image height in pixels")
        ->transform(whole_number_in(1, render::max_image_side));
    cmd->add_option("--spp", o->spp, "Samples per pixel")->transform(whole_number_in(1, render::max_spp));
    add_threads_option(cmd, o->threads, "Worker threads (0: all)");
    // CLI11 2.1 reads "-1" as 2^64 - 1 and saturates numbers beyond 2^64 - 1: check the text.
    cmd->add_option("--seed", o->seed, "Seed of the sampling and of the noise textures")
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                std::uint64_t value = 0;
                const char* end = text.data() + text.size();
                const auto [p, ec] = std::from_chars(text.data(), end, value);
                if (text.empty() || ec != std::errc{} || p != end)
                    return fmt::format("'{}' is not an integer in [0, {}]", text,
                                       std::numeric_limits<std::uint64_t>::max());
                return {};
            },
            "UINT64"));
    cmd->add_option("--clip", o->clip, "Gamut clip method (default: the scene's, smits)");
    cmd->add_option("--set", o->assignments,
                    "Override a scene value: key.path=value, e.g. render.path=spectral, "
                    "oil.k1=1.5, soap.bubbles.0.radius=0.7 (repeatable)");
    cmd->add_option("--linear", o->linear, "Also write the unclipped linear image (.exr)");
    cmd->add_flag("-q,--quiet", o->quiet, "No progress bar and no summary on stderr");
    cmd->callback([o, &runner] { runner = [o] { return run_render(*o); }; });
}

}  // namespace irid::cli
