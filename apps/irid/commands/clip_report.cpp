// irid clip-report [--set spectrum|interference|rec2020|ramps|all] [--to SPACE]
//
// Every clipping method on a set of colours: ΔE2000, hue shift (CIELAB and Oklab), |ΔY|, chroma
// kept and colours per second measured in this run, as Markdown tables (one per set, and for
// --set all one more over the union); under each, a second table of what the methods do to
// gradients and to colours already in the gamut (in-gamut ΔE2000, banding and collapse on the
// set's ramps). The definitions are in docs/GAMUT.md. SPACE is
// an RGB space, encoded or linear (the gamut is its linear cube [0, 1]³); aces-rgc is measured
// with clip = true, as a display gets it. The sets are built here and given to the report: the
// interference set needs the film optics, which the gamut library does not know, so they come
// from irid_figures (clip_sets.h).
#include "../cli_common.h"

#include <irid/color/convert.h>
#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/figures/clip_sets.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/report.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace irid::cli {
namespace {

struct ClipReportCommand {
    std::string set = "all";
    std::string to = "srgb";
};

/// An RGB space by its name as `irid convert` writes it: NAME (encoded) or NAME-linear; both
/// give the same gamut.
const RgbSpace& parse_destination(const std::string& name) {
    if (const std::optional<ColorSpace> s = find_color_space(name); s && s->is_rgb()) return *s->rgb;
    std::vector<std::string> names;
    for (const RgbSpace* s : builtin_rgb_spaces()) {
        names.push_back(s->name());
        names.push_back(s->name() + "-linear");
    }
    throw UsageError("unknown space '" + name + "' for --to (an RGB space); valid names: " + join(names));
}

int run_clip_report(const ClipReportCommand& c) {
    std::vector<figures::ClipReportSet> kinds;
    try {
        kinds = figures::parse_clip_report_sets(c.set);
    } catch (const Error& e) {
        throw UsageError(std::string("--set: ") + e.what());
    }
    const RgbSpace& destination = parse_destination(c.to);
    const Gamut gamut(destination);

    std::vector<ColorSet> sets;
    for (const figures::ClipReportSet k : kinds) {
        sets.push_back(figures::clip_report_color_set(k, destination));
    }
    if (sets.size() > 1) sets.push_back(union_color_set(sets, c.set));

    std::string out;
    for (const ColorSet& set : sets) {
        if (!out.empty()) out += "\n";
        out += clip_report_markdown(measure_clip_report(set, gamut));
    }
    write_stdout(out);
    return exit_success;
}

}  // namespace

void add_clip_report_command(CLI::App& app, Runner& runner) {
    auto command = std::make_shared<ClipReportCommand>();
    CLI::App* cmd = app.add_subcommand(
        "clip-report",
        "Every gamut-clipping method measured on a set of colours (Markdown tables). Per set, a "
        "first table: ΔE00 mean, p95, max; hue change in CIELAB and Oklab; |ΔY|; chroma kept; "
        "colours per second. A second table: in-gamut ΔE00 mean / max (how far colours already "
        "inside the gamut moved), banding mean / max over the set's ramps (per ramp the largest "
        "ΔE00 between neighbouring outputs over their mean; 1 = even) and collapse (the share of "
        "a ramp's out-of-gamut steps whose output is within ΔE00 0.5 of the next step's, mean "
        "over ramps); \"–\" where the set has no such colours or ramps. aces-rgc is measured "
        "with clip=true.");
    cmd->add_option("--set", command->set,
                    "spectrum, interference, rec2020, ramps (144 gradients from a grey to the "
                    "Rec.2020 boundary and to the spectral locus) or all")
        ->capture_default_str();
    cmd->add_option("--to", command->to, "Destination RGB space (encoded or -linear): the gamut")
        ->capture_default_str();
    cmd->callback([command, &runner] { runner = [command] { return run_clip_report(*command); }; });
}

}  // namespace irid::cli
