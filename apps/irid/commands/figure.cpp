// irid figure NAME -o OUT [--width W] [--height H] [--set key=value ...] [--caption]
// irid figure --list
//
// Draws one of the thesis' figures (or tables) from the library's numbers: PNG or SVG for
// figures, Markdown or HTML for tables, chosen by OUT's extension. The catalog and the options
// of each figure are in include/irid/figures/figures.h (irid figure --list prints them).
#include "../cli_common.h"

#include <irid/error.h>
#include <irid/figures/figures.h>

#include <memory>
#include <string>
#include <vector>

namespace irid::cli {
namespace {

struct FigureCommand {
    std::string name;
    std::string output;
    int width = 960;
    int height = 600;
    std::vector<std::string> sets;
    bool list = false;
    bool caption = false;
};

std::vector<std::string> figure_names() {
    std::vector<std::string> names;
    for (const figures::FigureInfo& info : figures::figure_catalog()) names.push_back(info.name);
    return names;
}

std::string catalog_text() {
    std::string out;
    for (const figures::FigureInfo& info : figures::figure_catalog()) {
        std::string extensions;
        for (const std::string& e : info.extensions) extensions += (extensions.empty() ? "" : " ") + e;
        out += info.name + "  [" + (info.thesis_figure.empty() ? "irid" : info.thesis_figure) +
               "]  " + info.title + "  (" + extensions + ")\n";
        if (!info.options_help.empty()) out += "    options: " + info.options_help + "\n";
    }
    return out;
}

int run_figure(const FigureCommand& c) {
    if (c.list) {
        write_stdout(catalog_text());
        return exit_success;
    }
    if (c.name.empty()) {
        throw UsageError("give a figure NAME (or --list); valid names: " + join(figure_names()));
    }
    const figures::FigureInfo* info = figures::find_figure(c.name);
    if (info == nullptr) {
        throw UsageError("unknown figure '" + c.name + "'; valid names: " + join(figure_names()));
    }
    if (c.output.empty()) {
        throw UsageError("-o OUT is required; allowed extensions for " + c.name + ": " +
                         join(info->extensions));
    }
    figures::FigureRequest request;
    request.name = c.name;
    request.output = c.output;
    request.width_px = c.width;
    request.height_px = c.height;
    for (const std::string& s : c.sets) {
        const std::size_t eq = s.find('=');
        if (eq == std::string::npos || eq == 0) {
            throw UsageError("--set " + s + ": expected key=value; options of " + c.name + ": " +
                             info->options_help);
        }
        request.options.emplace_back(s.substr(0, eq), s.substr(eq + 1));
    }
    figures::FigureResult result;
    try {
        result = figures::draw_figure(request);
    } catch (const figures::FigureRequestError& e) {
        throw UsageError(e.what());
    }
    if (c.caption) {
        std::string out = result.caption + "\n";
        for (const auto& [label, value] : result.measurements) out += label + ": " + value + "\n";
        write_stdout(out);
    }
    return exit_success;
}

}  // namespace

void add_figure_command(CLI::App& app, Runner& runner) {
    auto command = std::make_shared<FigureCommand>();
    CLI::App* cmd = app.add_subcommand(
        "figure", "Draw a figure or table of the thesis (PNG/SVG, or Markdown/HTML for tables)");
    cmd->add_option("name", command->name, "The figure's name (see --list)");
    cmd->add_option("-o,--output", command->output,
                    "Output file; its extension picks the format (.svg .png, tables .md .html)");
    cmd->add_option("--width", command->width, "Image width in pixels (PNG) or points (SVG)")
        ->capture_default_str()
        ->transform(whole_number_in(figures::min_size_px, figures::max_size_px));
    cmd->add_option("--height", command->height, "Image height in pixels (PNG) or points (SVG)")
        ->capture_default_str()
        ->transform(whole_number_in(figures::min_size_px, figures::max_size_px));
    cmd->add_option("--set", command->sets, "A figure option key=value (repeatable)");
    cmd->add_flag("--list", command->list, "Print the catalog: name, thesis figure, title, options");
    cmd->add_flag("--caption", command->caption,
                  "Print the caption and the measured numbers after writing the file");
    cmd->callback([command, &runner] { runner = [command] { return run_figure(*command); }; });
}

}  // namespace irid::cli
