// irid ocio-config: an OpenColorIO config offering the clip methods as looks, LUTs beside it.
//
//   irid ocio-config -o DIR [--from SPACE] [--to SPACE] [--methods M,M...] [--size N]
//
// The config and its LUTs are the library's (irid/exchange/ocio_config.h); this file parses.
#include "../cli_common.h"
#include "../pipeline_options.h"
#include "../spaces.h"

#include <irid/color/adaptation.h>
#include <irid/color/convert.h>
#include <irid/error.h>
#include <irid/exchange/lut.h>
#include <irid/exchange/ocio_config.h>
#include <irid/gamut/clip.h>
#include <irid/text_input.h>

#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace irid::cli {
namespace {

struct OcioConfigArgs {
    std::string out;
    std::string from = "acescg-linear";
    std::string to = "srgb";
    std::string methods;
    int size = 33;
    std::string range;
    std::string adaptation = "bradford";
    std::string aces2 = "auto";
    int threads = 0;
};

ColorSpace rgb_space_option(const std::string& option, const std::string& name) {
    const std::optional<ColorSpace> s = find_color_space(name);
    if (!s || !s->is_rgb()) {
        throw UsageError(option + " " + quote_untrusted(name) + ": valid RGB spaces: " + join(rgb_space_names()));
    }
    return *s;
}

int run_ocio_config(const OcioConfigArgs& a) {
    if (a.out.empty()) throw UsageError("-o DIR is required (the folder of config.ocio and luts/)");
    OcioConfigOptions o;
    o.source = rgb_space_option("--from", a.from);
    o.display = rgb_space_option("--to", a.to);
    o.size = a.size;
    o.threads = a.threads;
    if (!a.range.empty()) o.source_range = parse_number_pair("--range", a.range, "the source values covered", "-1,16");
    try {
        o.adaptation = parse_chromatic_adaptation(a.adaptation);
        std::size_t start = 0;
        while (!a.methods.empty() && start <= a.methods.size()) {
            const std::size_t comma = std::min(a.methods.find(',', start), a.methods.size());
            o.methods.push_back(parse_clip_method(a.methods.substr(start, comma - start)));
            start = comma + 1;
        }
        if (a.aces2 == "none") {
            o.aces2_displays.emplace();
        } else if (a.aces2 != "auto") {
            o.aces2_displays.emplace();
            for (std::size_t at = 0; at <= a.aces2.size();) {
                const std::size_t end = std::min(a.aces2.find(',', at), a.aces2.size());
                o.aces2_displays->push_back(a.aces2.substr(at, end - at));
                at = end + 1;
            }
        }
        (void)ocio_aces2_displays(o);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    if (std::filesystem::exists(a.out) && !std::filesystem::is_directory(a.out)) {
        throw UsageError("-o " + quote_untrusted(a.out, 200) + " exists and is not a folder");
    }
    OcioConfig config;
    try {
        config = make_ocio_config(o);
    } catch (const UnknownNameError&) {
        throw;
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    const std::vector<std::filesystem::path> removed = write_ocio_config(a.out, config);
    // The folder as given, or quoted with escapes when it holds what a terminal would act on.
    const std::string quoted = quote_untrusted(a.out, 1000);
    const std::string shown = quoted == "'" + a.out + "'" ? a.out : quoted;
    const auto counted = [](std::size_t n, const char* one, const char* many) {
        return fmt::format("{} {}", n, n == 1 ? one : many);
    };
    fmt::print("{}/config.ocio: {} and {} on the display '{} display' ({} in {}/luts)\n", shown,
               counted(config.luts.size(), "look", "looks"),
               counted(config.display_luts.size(), "ACES 2.0 view", "ACES 2.0 views"), color_space_name(o.display),
               counted(config.luts.size() + config.display_luts.size(), "LUT", "LUTs"), shown);
    if (!removed.empty()) {
        fmt::print("{}/luts: removed {} of an earlier config\n", shown, counted(removed.size(), "LUT", "LUTs"));
    }
    return exit_success;
}

}  // namespace

void add_ocio_config_command(CLI::App& app, Runner& runner) {
    auto a = std::make_shared<OcioConfigArgs>();
    CLI::App* cmd = app.add_subcommand(
        "ocio-config",
        "Write an OpenColorIO config (DIR/config.ocio) that offers the clip methods as looks and "
        "views, their LUTs in DIR/luts");
    cmd->add_option("-o,--output", a->out, "The folder (created if missing)");
    cmd->add_option("--from", a->from, "The scene's space, the config's reference: " + join(rgb_space_names()))
        ->capture_default_str();
    cmd->add_option("--to", a->to, "The display's space, whose cube is the gamut")->capture_default_str();
    cmd->add_option("--methods", a->methods,
                    "The methods offered, comma-separated (default: all): " + clip_method_names());
    cmd->add_option("--size", a->size, "The LUTs' nodes per axis, in the display's linear space (0 and 1 "
                                       "among them; the range a source colour in [0, 16]³, or [0, 1]³ "
                                       "encoded, reaches there)")
        ->transform(whole_number_in(ocio_look_min_size, lut_max_size))
        ->capture_default_str();
    cmd->add_option("--range", a->range,
                    "The source values the looks cover, LO,HI (default -1,16 for a linear source, "
                    "0,1 for an encoded one); beyond them inputs clamp. LO < HI, HI > 0, both within "
                    "±1e5, and the colours of the range may reach an interval at most 4096 wide in the "
                    "display's linear space, where the LUT's nodes lie (ACEScg on sRGB: about ±849)");
    cmd->add_option("--adaptation", a->adaptation,
                    "Chromatic adaptation where whites differ: bradford, cat02, von-kries, none")
        ->capture_default_str();
    cmd->add_option("--aces2", a->aces2,
                    "ACES 2.0 views, each the display transform baked as a .clf: auto (every "
                    "built-in display whose default encoding is --to), none, or displays "
                    "comma-separated (irid display --list)")
        ->capture_default_str();
    add_threads_option(cmd, a->threads, "Threads (0: all)");
    cmd->footer("\nExample: irid ocio-config --from acescg-linear --to srgb -o irid-ocio\n"
                "  then: ociocheck --iconfig irid-ocio/config.ocio");
    cmd->callback([a, &runner] { runner = [a] { return run_ocio_config(*a); }; });
}

}  // namespace irid::cli
