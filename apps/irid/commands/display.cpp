// irid display --view aces2 --display NAME [--from SPACE] [--to xyz|SPACE] [--inverse] < CSV
// irid display --view aces2 --display NAME [--from SPACE] [--to SPACE] [--bits 8|16] IN OUT
// irid display --list
//
// Scene colours (CSV triples on stdin; ACES2065-1 by default) through a display transform to
// CIE XYZ of the display (1.0 = 100 cd/m²) or an RGB space's linear or encoded values; with
// --inverse, display values (XYZ by default) back to scene values (ACES2065-1 by default). An
// image goes forward to the display's signal in a display encoding, tagged. The transform, its
// displays and the image's plan are the library's (irid/gamut/display_transform.h,
// irid/exchange/image_display.h).
#include "../cli_common.h"
#include "../spaces.h"

#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/exchange/image_display.h>
#include <irid/gamut/aces2_display.h>
#include <irid/gamut/display_transform.h>
#include <irid/io/image.h>

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace irid::cli {
namespace {

struct DisplayOptions {
    std::string view = "aces2";
    std::string display;
    std::string from;
    std::string to;
    bool inverse = false;
    bool list = false;
    int threads = 0;
    int bits = 0;
    std::string in;
    std::string out;
};

std::string primaries_text(const RgbPrimaries& p) {
    return fmt::format("{} {} {} {} {} {}", format_shortest(p.red.x), format_shortest(p.red.y),
                       format_shortest(p.green.x), format_shortest(p.green.y), format_shortest(p.blue.x),
                       format_shortest(p.blue.y));
}

int run_list() {
    std::string out = "display,peak_nits,limiting_primaries,limiting_white,encoding_primaries,encoding_white,"
                      "linear_scale,file_encoding\n";
    for (const Aces2DisplaySpec& d : aces2_displays()) {
        // The nominal peak: the cinema presets render for 1/0.48 of it and scale back.
        const RgbSpace* file = default_display_encoding(d);
        out += fmt::format("{},{},{},{} {},{},{},{},{}\n", d.name, format_shortest(d.peak_nits * d.linear_scale),
                           primaries_text(d.limiting), format_shortest(d.limiting_white.x),
                           format_shortest(d.limiting_white.y),
                           d.encoding_xyz ? std::string("CIE XYZ") : primaries_text(d.encoding),
                           d.encoding_xyz ? std::string("E")
                                          : format_shortest(d.encoding_white.x) + " " +
                                                format_shortest(d.encoding_white.y),
                           format_shortest(d.linear_scale), file != nullptr ? file->name() : std::string("none"));
    }
    write_stdout(out);
    return exit_success;
}

int run_display_image(const DisplayOptions& o) {
    if (o.inverse) throw UsageError("--inverse takes CSV on stdin; an image goes forward, scene to display");
    io::ImageFormat format{};
    DisplayImagePlan plan;
    std::optional<ColorSpace> from;
    try {
        format = io::image_format_for(o.out);
        plan = plan_display_image(o.view, o.display, o.to.empty() ? std::nullopt : std::optional(o.to), format);
        if (!o.from.empty()) from = parse_space(o.from, "--from");
    } catch (const Error& e) {
        throw UsageError(e.what());  // an unknown name, an output format, a --to that is no RGB space or xyz
    }
    if (o.bits != 0) {
        if (!plan.encoded) throw UsageError("--bits applies to PNG and TIFF; " + o.out + " is written as 32-bit float (EXR)");
        if (o.bits != 8 && o.bits != 16)
            throw UsageError("--bits " + std::to_string(o.bits) + ": valid values are 8 and 16");
        if (format == io::ImageFormat::jpeg && o.bits != 8)
            throw UsageError("--bits 16: JPEG holds 8 bits per sample; write PNG or TIFF for 16");
        plan.bits = o.bits;
    }
    io::Image image = io::read_image(o.in);
    const bool alpha = image.channel_index("A") >= 0;
    DisplayImageReport report;
    try {
        report = display_image(image, plan,
                               DisplayImageOptions{.from = from,
                                                   .premultiplied_in = alpha && is_exr_path(o.in),
                                                   .premultiplied_out = alpha && !plan.encoded,
                                                   .threads = o.threads},
                               format, o.in);
    } catch (const ImageSourceConflict& e) {
        throw UsageError(e.what());
    }
    for (const std::string& note : report.notes) fmt::print(stderr, "irid display: note: {}\n", note);
    if (const std::string note = io::windows_dropped(image, format); !note.empty()) {
        fmt::print(stderr, "irid display: note: {}\n", note);
    }
    image.description = fmt::format("irid display --view {} --display {} --from {} --to {}; colour space {} ({})",
                                    plan.view, plan.display.name, report.source.described, plan.encoding_name(),
                                    image.color_space, plan.encoded ? "encoded" : "linear, 1.0 = 100 cd/m2");
    io::write_image(o.out, image, io::ImageEncoding{.bits = plan.bits, .compression = {}});
    return exit_success;
}

int run_display(const DisplayOptions& o) {
    if (o.list) return run_list();
    if (o.display.empty()) throw UsageError("--display is required (irid display --list names them)");
    if (!o.in.empty()) {
        if (o.out.empty()) throw UsageError("give both IN and OUT (images), or neither (CSV on stdin)");
        return run_display_image(o);
    }
    if (o.bits != 0) throw UsageError("--bits applies to PNG and TIFF images (IN OUT), not to CSV");
    DisplayTransformOptions t;
    t.view = o.view;
    t.display = o.display;
    t.inverse = o.inverse;
    t.source = !o.from.empty() ? o.from : (o.inverse ? "xyz" : "aces2065-1");
    t.target = !o.to.empty() ? o.to : (o.inverse ? "aces2065-1" : "xyz");
    const Space target = parse_space(t.target, "--to");
    (void)parse_space(t.source, "--from");
    std::unique_ptr<DisplayTransform> transform;
    try {
        transform = std::make_unique<DisplayTransform>(t);
    } catch (const Error& e) {
        throw UsageError(e.what());  // an unknown view or display, or a space on the wrong side
    }
    const NumericTable table = read_stdin_table(3);
    std::string out = std::string(header_of(target)) + "\n";
    std::vector<std::size_t> without;  // inverse: the lines without a scene value
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const std::span<const double> row = table.row(r);
        Vec3 result{};
        try {
            result = (*transform)({row[0], row[1], row[2]});
            if (o.inverse && !transform->has_scene_value({row[0], row[1], row[2]}))
                without.push_back(table.line_numbers[r]);
        } catch (const Error& e) {
            throw Error("<stdin>:" + std::to_string(table.line_numbers[r]) + ": " + e.what());
        }
        append_csv_line(out, result);
    }
    write_stdout(out);
    if (!without.empty())
        fmt::print(stderr, "irid display: note: {}\n", no_scene_value_note(without, table.rows(), "stdin line"));
    return exit_success;
}

}  // namespace

void add_display_command(CLI::App& app, Runner& runner) {
    auto options = std::make_shared<DisplayOptions>();
    CLI::App* cmd = app.add_subcommand(
        "display", "Scene colours (CSV on stdin) through a display transform (ACES 2.0), or back with --inverse");
    cmd->add_option("--view", options->view, "The view: " + join(display_views()))->capture_default_str();
    cmd->add_option("--display", options->display,
                    "The display: a name of irid display --list, or " + std::string(aces2_custom_form));
    cmd->add_option("--from", options->from,
                    "Input space (default aces2065-1; with --inverse xyz): " + join(space_names()));
    cmd->add_option("--to", options->to,
                    "Output space: xyz (1.0 = 100 cd/m²) or an RGB space (default xyz; with --inverse aces2065-1); "
                    "for an image a display encoding, or xyz (EXR only)");
    cmd->add_flag("--inverse", options->inverse, "Display values back to scene values");
    cmd->add_flag("--list", options->list,
                  "List the displays: peak, limiting and encoding primaries and whites, and the encoding of "
                  "their files");
    cmd->add_option("--bits", options->bits,
                    "Bits per sample of PNG and TIFF output: 8 or 16 (default 16 for PQ, else 8)");
    add_threads_option(cmd, options->threads, "Threads for images (0: all)");
    cmd->add_option("IN", options->in,
                    "Input image (EXR, or anything OpenImageIO reads) of scene colours: its EXR chromaticities' "
                    "or ICC profile's space, else ACES2065-1; --from overrides it");
    cmd->add_option("OUT", options->out,
                    "Output image of the display's signal: .png, .tif, .tiff (encoded, with the encoding's ICC "
                    "profile, none for PQ and HLG) or .exr (linear, 1.0 = 100 cd/m², with its chromaticities; CIE XYZ "
                    "for xyz), in --to or the display's own encoding (irid display --list)");
    cmd->callback([options, &runner] { runner = [options] { return run_display(*options); }; });
}

}  // namespace irid::cli
