// irid clip: bring out-of-gamut colours into a display's gamut (Smits 1990, §4.3, and the
// methods it is compared with).
//
//   irid clip --method M [--from SPACE] [--to SPACE] [--max PEAK]        CSV on stdin → stdout
//   irid clip --method M [--from SPACE] [--to SPACE] [--bits 8|16] IN OUT         an image
//   irid clip --count-ops                                   Table 1, ours beside the thesis'
//
// The pipeline is the library's (irid/gamut/pipeline.h: --from → the --to space's linear RGB →
// the clip → encoded when --to is encoded, for CSV, or when OUT is PNG or TIFF), the image's
// channels and alpha too (irid/exchange/image_clip.h); this file parses and prints.
#include "../cli_common.h"
#include "../pipeline_options.h"
#include "../spaces.h"

#include <irid/color.h>
#include <irid/exchange/icc.h>
#include <irid/exchange/image_clip.h>
#include <irid/exchange/image_source.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/pipeline.h>
#include <irid/io/image.h>
#include <irid/text_input.h>

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace irid::cli {
namespace {

struct ClipOptions : PipelineArgs {
    int bits = 8;
    bool count_ops = false;
    std::string in;
    std::string out;
    const CLI::Option* bits_option = nullptr;
    const CLI::Option* from_option = nullptr;
};

// --- Table 1 ---------------------------------------------------------------------------------

/// "ours (thesis)".
std::string cell(long ours, const char* thesis) {
    return fmt::format("{} ({})", ours, thesis);
}

int run_count_ops() {
    const Table1 t = count_smits_operations();
    struct Row {
        const char* name;
        const OperationCounts* ours;
        // Smits 1990, Table 1: 5-7 comparisons, 9-11 additions, 7 multiplications and 1-3
        // divisions per clipped colour, the ranges running with the planes crossed; an in-gamut
        // colour costs only comparisons (their number is not given).
        std::array<const char*, 4> thesis;
    };
    const Row rows[] = {
        {"in gamut", &t.in_gamut, {"—", "0", "0", "0"}},
        {"1 plane", &t.one_plane, {"5", "9", "7", "1"}},
        {"2 planes", &t.two_planes, {"6", "10", "7", "2"}},
        {"3 planes", &t.three_planes, {"7", "11", "7", "3"}},
    };
    std::string out =
        "| colour | comparisons | additions | multiplications | divisions |\n"
        "|:--|--:|--:|--:|--:|\n";
    for (const Row& r : rows) {
        out += fmt::format(
            "| {} | {} | {} | {} | {} |\n", r.name, cell(r.ours->comparisons, r.thesis[0]),
            cell(r.ours->additions, r.thesis[1]), cell(r.ours->multiplications, r.thesis[2]),
            cell(r.ours->divisions, r.thesis[3]));
    }
    out +=
        "\nOperations per colour of the thesis' RGB clip, ours (thesis). Ours: counted by running "
        "the clip's code on a number type that counts its operations, for sRGB colours inside the "
        "gamut and crossing one, two and three planes (red above 1, then green and blue below 0); "
        "additions include subtractions. Ours compares the crossed planes' parameters by "
        "cross-multiplication and divides once: 2 multiplications and 1 comparison per plane "
        "after the first instead of a division per plane. Our comparisons are the 6 outcode "
        "tests, 2 luminance tests (Y <= 0 gives black, a grey above the maximum gives white) and "
        "one per plane after the first. Thesis: Smits 1990, Table 1: 5-7 comparisons, 9-11 "
        "additions, 7 multiplications, 1-3 divisions per clipped colour, shown here against one, "
        "two and three crossed planes; an in-gamut colour costs only comparisons.\n";
    write_stdout(out);
    return exit_success;
}

// --- the pipeline ----------------------------------------------------------------------------

/// The pipeline of the options; an image gets aces-rgc's final clip unless --param clip= says
/// otherwise: a file cannot hold what a display cannot show.
ClipPipeline make_pipeline(const ClipOptions& o, bool image) {
    if (o.method.empty()) {
        throw UsageError("--method is required (or --count-ops); valid methods: " + clip_method_names());
    }
    return make_clip_pipeline(o, image);
}

// --- CSV -------------------------------------------------------------------------------------

int run_clip_csv(const ClipOptions& o, const ClipPipeline& p) {
    if (o.bits_option->count() > 0) {
        throw UsageError("--bits applies to PNG and TIFF images (IN OUT), not to CSV");
    }
    const NumericTable table = read_stdin_table(3);
    std::string out = "R,G,B\n";
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const std::span<const double> row = table.row(r);
        Rgb c{};
        try {
            c = p.clip(Vec3{row[0], row[1], row[2]});
        } catch (const Error& e) {
            throw Error("<stdin>:" + std::to_string(table.line_numbers[r]) + ": " + e.what());
        }
        append_csv_line(out, std::array{c.r, c.g, c.b});
    }
    write_stdout(out);
    return exit_success;
}

// --- images ----------------------------------------------------------------------------------

int run_clip_image(const ClipOptions& o, const ClipPipeline& p) {
    io::ImageFormat format{};
    try {
        format = io::image_format_for(o.out);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    const bool encoded_out = io::is_integer_format(format);
    const double max = p.clipper().gamut().max();
    if (o.bits_option->count() > 0) {
        if (!encoded_out) {
            throw UsageError("--bits applies to PNG and TIFF; " + o.out +
                             " is written as 32-bit float (EXR)");
        }
        if (o.bits != 8 && o.bits != 16) {
            throw UsageError("--bits " + std::to_string(o.bits) + ": valid values are 8 and 16");
        }
        if (format == io::ImageFormat::jpeg && o.bits != 8) {
            throw UsageError("--bits " + std::to_string(o.bits) + ": JPEG holds 8 bits per sample; "
                             "write PNG or TIFF for 16");
        }
    }
    try {
        check_file_holds(p.destination(), format);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    if (encoded_out && max > 1.0) {
        throw UsageError("--max " + format_shortest(max) +
                         " is above 1, which PNG and TIFF (encoded " +
                         "values in [0, 1]) cannot hold; write an EXR");
    }

    io::Image image = io::read_image(o.in);
    const ImageColourChannels channels = image_colour_channels(image, o.in);
    // Where the colours come from is the library's decision (irid/exchange/image_source.h):
    // the channels, --from, the file's profile or chromaticities; this prints its notes.
    std::optional<ColorSpace> given;
    if (o.from_option->count() > 0) given = p.from();
    ImageSource source;
    try {
        source = decide_image_source(image, channels.xyz, given, o.in, "--from");
    } catch (const ImageSourceConflict& e) {
        throw UsageError(e.what());
    }
    for (const std::string& note : source.notes) fmt::print(stderr, "irid clip: note: {}\n", note);
    if (const std::string note = io::windows_dropped(image, format); !note.empty()) {
        fmt::print(stderr, "irid clip: note: {}\n", note);
    }
    const ClipPipeline pipe = make_clip_pipeline(o, true, &source.space);
    // PNG and TIFF keep a 16-bit input's depth unless --bits says otherwise; JPEG holds 8.
    const int bits =
        o.bits_option->count() > 0 ? o.bits
        : (format != io::ImageFormat::jpeg && image.stored_integer && image.stored_bits > 8) ? 16
                                                                                            : 8;
    const bool alpha = image.channel_index("A") >= 0;
    clip_image(image, channels, pipe,
               ImageClipOptions{.premultiplied_in = alpha && is_exr_path(o.in),
                                .premultiplied_out = alpha && is_exr_path(o.out),
                                .encode = encoded_out,
                                .threads = o.threads,
                                .profile = source.file && source.file->profile ? source.file->profile.get() : nullptr},
               o.in);

    // The output says what it holds: an ICC profile (PNG, TIFF) or chromaticities (EXR).
    tag_image(image, p.destination(), format);
    image.description = fmt::format(
        "irid clip --method {}{} --from {} --to {} --max {}; colour space {} ({})", o.method,
        describe_clip_settings(p.clipper()), source.described, o.to, format_shortest(max), image.color_space,
        encoded_out ? "encoded" : "linear");
    io::write_image(o.out, image, io::ImageEncoding{.bits = bits, .compression = {}});
    return exit_success;
}

int run_clip(const ClipOptions& o) {
    if (o.count_ops) {
        if (!o.in.empty()) throw UsageError("--count-ops takes no files");
        return run_count_ops();
    }
    const ClipPipeline p = make_pipeline(o, !o.in.empty());
    if (o.in.empty()) return run_clip_csv(o, p);
    if (o.out.empty()) throw UsageError("give both IN and OUT (images), or neither (CSV on stdin)");
    return run_clip_image(o, p);
}

}  // namespace

void add_clip_command(CLI::App& app, Runner& runner) {
    auto o = std::make_shared<ClipOptions>();
    CLI::App* cmd = app.add_subcommand(
        "clip",
        "Bring out-of-gamut colours into an RGB space's gamut: CSV triples on stdin (R,G,B out), "
        "or an image IN → OUT");
    cmd->add_option("--method", o->method, "Clipping method: " + clip_method_names());
    cmd->add_option("--param", o->params,
                    "A method's parameter, name=value (repeatable): " + clip_parameter_help() +
                        ". Images get aces-rgc's clip=true unless given")
        ->allow_extra_args(false);  // one name=value per --param; IN and OUT stay positional
    cmd->add_flag("--inverse", o->inverse,
                  "Apply the method's inverse (aces-rgc, smits-soft: undo a compression)");
    o->from_option = cmd->add_option("--from", o->from,
                                     "Source space: " + join(space_names()) +
                                         ". An image with X, Y and Z channels is CIE XYZ")
                         ->capture_default_str();
    cmd->add_option("--to", o->to,
                    "Destination RGB space, whose linear cube [0, max]^3 is the gamut: " +
                        join(rgb_space_names()) +
                        ". CSV: linear values, or encoded for an encoded name. Images: EXR always "
                        "gets linear float values, PNG and TIFF always encoded values (with the "
                        "space's transfer function even for a -linear name)")
        ->capture_default_str();
    cmd->add_option("--max", o->max,
                    "Peak of the destination gamut (HDR), > 0; PNG and TIFF need <= 1")
        ->capture_default_str();
    cmd->add_option(
           "--white", o->white,
           "Reference white of XYZ, CIELUV and CIELAB: " + join(white_point_names()) + " or x,y")
        ->capture_default_str();
    cmd->add_option("--adaptation", o->adaptation,
                    "Chromatic adaptation where whites differ: bradford, cat02, von-kries, none")
        ->capture_default_str();
    add_threads_option(cmd, o->threads, "Threads for images (0: all)");
    o->bits_option =
        cmd->add_option("--bits", o->bits,
                        "Bits per sample of PNG and TIFF output: 8 or 16 (default: 16 for a 16-bit "
                        "input image, else 8)")
            ->capture_default_str();
    cmd->add_flag(
        "--count-ops", o->count_ops,
        "Print Table 1: operations per colour of the thesis' clip, ours beside the thesis'");
    cmd->add_option("IN", o->in,
                    "Input image (EXR, TIFF, PNG, JPEG, HDR, anything OpenImageIO reads). Its space "
                    "is its ICC profile's or its EXR chromaticities', else sRGB (linear sRGB for "
                    "floats); --from overrides it (an encoded name decodes the values with its "
                    "transfer function)");
    cmd->add_option("OUT", o->out,
                    "Output image: .exr (linear float, with the destination's chromaticities), "
                    ".png, .tif, .tiff (8 or 16 bit) or .jpg, .jpeg (8 bit), encoded, with the "
                    "destination's ICC profile");
    cmd->footer(
        "\nForms:\n"
        "  irid clip --method M [--from SPACE] [--to SPACE] < colours.csv   CSV, one colour a "
        "line\n"
        "  irid clip --method M [--from SPACE] [--to SPACE] IN OUT           an image; R, G and B\n"
        "      are clipped, alpha and other channels pass through unchanged\n"
        "  irid clip --count-ops                                             Table 1");
    cmd->callback([o, &runner] { runner = [o] { return run_clip(*o); }; });
}

}  // namespace irid::cli
