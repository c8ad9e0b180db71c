// irid gallery: every scene, figure and table of irid on one HTML page, beside the thesis'
// figure numbers, with the numbers measured while making them.
//
//   irid gallery -o DIR [--width W] [--height H] [--spp N] [--figure-width W] [--threads N]
//                [--page FILE=TITLE ...] [--quiet]
//
// Writes DIR/index.html and the images it shows (PNG) into DIR. The page is plain HTML and CSS
// and references only files in DIR, so it opens from the file system without a network.
// --page links a page already in DIR (scripts/run writes iridescence.html first and links it).
#include "../cli_common.h"

#include <irid/gallery/gallery.h>

#include <fmt/core.h>

#include <filesystem>
#include <string>
#include <vector>

namespace irid::cli {
namespace {

struct GalleryCommand {
    std::string dir;
    std::vector<std::string> pages;
    gallery::GalleryOptions options;
    bool quiet = false;
};

int run_gallery(const GalleryCommand& c) {
    if (c.dir.empty()) throw UsageError("-o: an empty folder name; give the folder to write into");
    gallery::GalleryOptions options = c.options;
    options.dir = c.dir;
    for (const std::string& p : c.pages) {
        const auto eq = p.find('=');
        if (eq == std::string::npos || eq == 0)
            throw UsageError(fmt::format(
                "--page '{}': give FILE=TITLE (a file in the folder, the link's text)", p));
        options.pages.push_back({p.substr(0, eq), p.substr(eq + 1)});
    }
    if (!c.quiet) options.progress = [](const std::string& what) { fmt::print(stderr, "irid gallery: {}\n", what); };
    const gallery::GalleryResult r = gallery::make_gallery(options);
    fmt::print("{}\n", std::filesystem::absolute(r.index).lexically_normal().string());
    return exit_success;
}

}  // namespace

void add_gallery_command(CLI::App& app, Runner& runner) {
    auto o = std::make_shared<GalleryCommand>();
    CLI::App* cmd = app.add_subcommand(
        "gallery", "Render the scenes, figures and tables into DIR/index.html");
    cmd->add_option("-o,--output", o->dir, "Folder to write index.html and its images into")
        ->required();
    cmd->add_option("--width", o->options.width, "Scene width in pixels")->transform(whole_number_in(32, 4096));
    cmd->add_option("--height", o->options.height, "Scene height in pixels")->transform(whole_number_in(24, 4096));
    cmd->add_option("--spp", o->options.spp, "Samples per pixel of the scenes")->transform(whole_number_in(1, 256));
    cmd->add_option("--figure-width", o->options.figure_width, "Figure width in pixels (height 5/8 of it)")
        ->transform(whole_number_in(320, 4096));
    add_threads_option(cmd, o->options.threads, "Worker threads (0: all)");
    cmd->add_option("--page", o->pages, "Link a page already in the folder: FILE=TITLE (repeatable)");
    cmd->add_flag("-q,--quiet", o->quiet, "No progress messages on stderr");
    cmd->callback([o, &runner] { runner = [o] { return run_gallery(*o); }; });
}

}  // namespace irid::cli
