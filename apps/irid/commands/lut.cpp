// irid lut: a clip method (or compression) baked as a 3D LUT for OpenColorIO, DaVinci Resolve,
// Nuke and ffmpeg.
//
//   irid lut --method M [--param k=v] --from SPACE --to SPACE [--size N] [--shaper log2] -o FILE
//   irid lut --view aces2 --display NAME [--from SPACE] [--to SPACE] [--size N] -o FILE.clf
//
// The pipeline is `irid clip`'s (irid/gamut/pipeline.h); the baking and the formats are the
// library's (irid/exchange/lut.h); this file parses.
#include "../cli_common.h"
#include "../pipeline_options.h"
#include "../spaces.h"

#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/exchange/display_lut.h>
#include <irid/exchange/lut.h>
#include <irid/io/output_file.h>
#include <irid/text_input.h>

#include <charconv>
#include <memory>
#include <optional>
#include <string>

namespace irid::cli {
namespace {

struct LutOptions : PipelineArgs {
    int size = 33;
    std::string shaper = "none";
    std::string domain;
    int stops = 14;
    std::string out;
    std::string view, display;
    const CLI::Option* stops_option = nullptr;
    const CLI::Option* shaper_option = nullptr;
    const CLI::Option* domain_option = nullptr;
    const CLI::Option* from_option = nullptr;
    const CLI::Option* to_option = nullptr;
    const CLI::Option* max_option = nullptr;
    const CLI::Option* white_option = nullptr;
    const CLI::Option* adaptation_option = nullptr;
};

LutDomain make_domain(const LutOptions& o) {
    LutDomain d;
    if (o.shaper == "log2") {
        d.shaper = LutShaper::log2;
    } else if (o.shaper != "none") {
        throw UsageError("--shaper '" + o.shaper + "': valid shapers: none, log2");
    }
    if (o.stops_option->count() > 0 && d.shaper != LutShaper::log2) {
        throw UsageError("--stops applies to --shaper log2");
    }
    d.stops = o.stops;
    d.max = o.max;
    if (!o.domain.empty()) {
        std::tie(d.min, d.max) = parse_number_pair("--domain", o.domain, "the inputs covered", "0,16");
    }
    try {
        check_lut_domain(d);
    } catch (const Error& e) {
        throw UsageError(std::string("--domain/--stops: ") + e.what());
    }
    return d;
}

LutFormat output_format(const LutOptions& o) {
    if (o.out.empty()) throw UsageError("-o FILE is required (.cube, .clf or .spi3d)");
    try {
        return lut_format_for(o.out);
    } catch (const Error& e) {
        throw UsageError(std::string("-o: ") + e.what());
    }
}

/// irid lut --view: the display transform baked; the defaults are the library's.
int run_display_lut(const LutOptions& o) {
    if (!o.method.empty() || !o.params.empty() || o.inverse) {
        throw UsageError("--view bakes a display transform; it takes no --method, --param or --inverse");
    }
    if (o.display.empty()) throw UsageError("--view " + o.view + " needs --display NAME (irid display --list)");
    if (o.max_option->count() > 0) throw UsageError("--max applies to --method; a display has its own peak");
    if (o.white_option->count() > 0 || o.adaptation_option->count() > 0) {
        throw UsageError(
            "--white and --adaptation apply to --method; a display transform goes through CIE XYZ relative to "
            "the display's white (D65)");
    }
    const LutFormat format = output_format(o);
    try {
        (void)aces2_display(o.display);
    } catch (const Error& e) {
        throw UsageError(std::string("--display: ") + e.what());
    }
    const std::string from = o.from_option->count() > 0 ? o.from : "aces2065-1";
    try {
        check_display_lut_source(from);
    } catch (const Error& e) {
        throw UsageError("--from " + from + ": " + e.what());
    }
    DisplayTransformOptions options;
    try {
        options = display_lut_options(o.view, o.display, from, o.to_option->count() > 0 ? o.to : "");
    } catch (const Error& e) {
        throw UsageError(std::string("--to: ") + e.what());
    }
    std::unique_ptr<DisplayTransform> transform;
    try {
        transform = std::make_unique<DisplayTransform>(options);
    } catch (const Error& e) {
        throw UsageError(std::string("--view/--from/--to: ") + e.what());
    }
    // The library's domain for the format, or for a .clf (the range, the stops) when --shaper
    // names one; --shaper, --domain and --stops override its parts.
    LutDomain domain;
    try {
        domain = display_lut_domain(*transform, o.shaper_option->count() > 0 ? LutFormat::clf : format);
    } catch (const Error& e) {
        throw UsageError(o.out + ": " + e.what());
    }
    if (o.shaper_option->count() > 0 || o.domain_option->count() > 0 || o.stops_option->count() > 0) {
        LutOptions given = o;
        if (o.shaper_option->count() == 0) given.shaper = domain.shaper == LutShaper::log2 ? "log2" : "none";
        if (o.stops_option->count() == 0) given.stops = domain.stops;
        if (o.domain_option->count() == 0) {
            given.domain = format_shortest(domain.min) + "," + format_shortest(domain.max);
        }
        const std::optional<Mat3> matrix = domain.matrix;
        const std::string matrix_space = domain.matrix_space;
        domain = make_domain(given);
        domain.matrix = matrix;  // the cube stays in the library's space (AP1 for light)
        domain.matrix_space = matrix_space;
    }
    try {
        check_lut_format(format, domain);
    } catch (const Error& e) {
        throw UsageError(o.out + ": " + e.what());
    }
    (void)io::check_output_path(o.out);  // refuse a directory before baking
    write_lut(o.out, bake_display_lut(*transform, o.size, domain, o.threads));
    return exit_success;
}

int run_lut(const LutOptions& o) {
    if (!o.view.empty()) return run_display_lut(o);
    if (!o.display.empty()) throw UsageError("--display applies to --view");
    const LutFormat format = output_format(o);
    LutDomain domain;
    domain = make_domain(o);
    try {
        check_lut_format(format, domain);
    } catch (const Error& e) {
        throw UsageError(o.out + ": " + e.what());
    }
    const ClipPipeline pipeline = make_clip_pipeline(o, false);
    const Space from = pipeline.from();
    if (!from.is_rgb() && from.family != Family::xyz) {
        throw UsageError("--from " + o.from +
                         ": a LUT's input must be an RGB space or xyz (one range on every axis)");
    }
    (void)io::check_output_path(o.out);  // refuse a directory before baking
    const Lut3D lut = bake_lut(pipeline, o.size, domain, o.threads);
    write_lut(o.out, lut);
    return exit_success;
}

}  // namespace

void add_lut_command(CLI::App& app, Runner& runner) {
    auto o = std::make_shared<LutOptions>();
    o->to = "srgb";
    CLI::App* cmd = app.add_subcommand(
        "lut",
        "Bake a clip method (or compression) as a 3D LUT for OpenColorIO, DaVinci Resolve, Nuke "
        "and ffmpeg; the format is FILE's extension");
    cmd->add_option("--method", o->method, "Clipping method: " + clip_method_names());
    cmd->add_option("--view", o->view,
                    "Bake a display transform instead of a method: " + join(display_views()) +
                        " (with --display; --from defaults to aces2065-1, --to to the display's "
                        "encoding, a .clf to the log2 shaper over AP1 [0, the forward limit])");
    cmd->add_option("--display", o->display, "The display of --view (irid display --list)");
    cmd->add_option("--param", o->params,
                    "A method's parameter, name=value (repeatable): " + clip_parameter_help())
        ->allow_extra_args(false);
    cmd->add_flag("--inverse", o->inverse,
                  "Bake the method's inverse (aces-rgc, smits-soft: undo a compression)");
    o->from_option = cmd->add_option("--from", o->from,
                    "The LUT's input space: an RGB space (" + join(rgb_space_names()) +
                        ") or xyz")
        ->capture_default_str();
    o->to_option = cmd->add_option("--to", o->to,
                    "The LUT's output space, whose linear cube [0, max]^3 is the gamut: values "
                    "encoded with its transfer function for an encoded name (srgb), linear for "
                    "a -linear name")
        ->capture_default_str();
    o->max_option = cmd->add_option("--max", o->max, "Peak of the destination gamut (HDR), > 0")->capture_default_str();
    cmd->add_option("--size", o->size,
                    "Nodes per axis, " + std::to_string(lut_min_size) + " to " +
                        std::to_string(lut_max_size) + " (17, 33 and 65 are usual)")
        ->transform(whole_number_in(lut_min_size, lut_max_size))
        ->capture_default_str();
    o->shaper_option = cmd->add_option("--shaper", o->shaper,
                    "none: nodes uniform over the domain; log2: nodes uniform in stops below the "
                    "domain's top (.clf only; for linear and HDR sources)")
        ->capture_default_str();
    o->domain_option = cmd->add_option("--domain", o->domain,
                    "The inputs covered on every axis, LO,HI (default 0,MAX); inputs beyond are "
                    "clamped. .spi3d covers 0,1 only");
    o->stops_option = cmd->add_option("--stops", o->stops,
                                      "Stops below the domain's top that the log2 shaper spans "
                                      "(1 to 40)")
                          ->capture_default_str();
    o->white_option = cmd->add_option(
           "--white", o->white,
           "Reference white of an xyz input: " + join(white_point_names()) + " or x,y")
        ->capture_default_str();
    o->adaptation_option = cmd->add_option("--adaptation", o->adaptation,
                    "Chromatic adaptation where whites differ: bradford, cat02, von-kries, none")
        ->capture_default_str();
    add_threads_option(cmd, o->threads, "Threads (0: all)");
    cmd->add_option("-o,--output", o->out,
                    "The LUT file: .cube (Resolve/Adobe; ffmpeg, OCIO), .clf (Academy/ASC CLF; "
                    "OCIO), .spi3d (Sony; OCIO)");
    cmd->footer(
        "\nFormats and the inputs they cover:\n"
        "  .cube   a uniform range: [0, 1], or another with LUT_3D_INPUT_RANGE (Resolve, OCIO;\n"
        "          ffmpeg ignores the range and takes [0, 1])\n"
        "  .clf    a uniform range or the log2 shaper, any range; tetrahedral interpolation\n"
        "  .spi3d  [0, 1] only\n"
        "Example: irid lut --method oklab-cusp --from acescg --to srgb --shaper log2 --domain "
        "0,16 -o look.clf");
    cmd->callback([o, &runner] { runner = [o] { return run_lut(*o); }; });
}

}  // namespace irid::cli
