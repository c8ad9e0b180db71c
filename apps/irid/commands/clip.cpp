// irid clip: bring out-of-gamut colours into a display's gamut (Smits 1990, §4.3, and the
// methods it is compared with).
//
//   irid clip --method M [--from SPACE] [--to SPACE] [--max PEAK]        CSV on stdin → stdout
//   irid clip --method M [--from SPACE] [--to SPACE] [--bits 8|16] IN OUT         an image
//   irid clip --count-ops                                   Table 1, ours beside the thesis'
//
// Pipeline: the input in --from → XYZ relative to the reference white (--white, as convert) →
// linear RGB of the --to space (chromatically adapted where the whites differ, as convert) →
// the clip into [0, max]³ → encoded when --to names an encoded space (CSV) or when OUT is PNG or
// TIFF. smits-xyz runs the thesis' XYZ form on XYZ relative to the destination's white.
#include "../cli_common.h"
#include "../spaces.h"

#include <irid/color.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>
#include <irid/io/image.h>
#include <irid/text_input.h>

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace irid::cli {
namespace {

struct ClipOptions {
    std::string method;
    std::string from = "srgb-linear";
    std::string to = "srgb-linear";
    double max = 1.0;
    std::string white = "D65";
    std::string adaptation = "bradford";
    int threads = 0;
    int bits = 8;
    bool count_ops = false;
    std::vector<std::string> params;
    bool inverse = false;
    std::string in;
    std::string out;
    const CLI::Option* bits_option = nullptr;
    const CLI::Option* from_option = nullptr;
};

std::string method_names() {
    std::vector<std::string> names;
    for (const ClipMethod m : clip_methods()) names.emplace_back(clip_method_name(m));
    return join(names);
}

/// "aces-rgc: limit-cyan (default 1.147), ...; oklab-adaptive: ..." for --help.
std::string parameter_help() {
    std::string out;
    for (const ClipMethod m : clip_methods()) {
        std::string list;
        for (const ClipParameterInfo& p : clip_parameters(m)) {
            list += (list.empty() ? "" : ", ") + std::string(p.name) + " (default " +
                    (p.boolean ? std::string(p.default_value != 0.0 ? "true" : "false")
                               : format_shortest(p.default_value)) +
                    ")";
        }
        if (!list.empty()) out += (out.empty() ? "" : "; ") + std::string(clip_method_name(m)) + ": " + list;
    }
    return out;
}

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

/// Everything validated once: the spaces, the destination gamut, the clipper.
struct Pipeline {
    Space from;
    Space to;
    const RgbSpace* dest;
    Converter convert;  // --from → the destination's linear RGB
    GamutClipper clipper;
    /// The source and the destination are the same RGB space: no conversion at all (in-gamut
    /// colours come back bit for bit).
    bool same_space;
    /// The source is XYZ or (linear or encoded) RGB: after decoding, one 3×3 matrix takes it to
    /// the destination's linear RGB.
    bool linear_source;
    Mat3 to_destination;

    /// Linear RGB of the destination from one source triple (encoded RGB decoded, non-finite
    /// values taken by the clipper's rule first). Throws irid::Error for xyY with y = 0, Y ≠ 0.
    [[nodiscard]] Rgb to_linear(const Vec3& in) const {
        Vec3 v{finite_or_default(in[0]), finite_or_default(in[1]), finite_or_default(in[2])};
        if (from.family == Family::rgb_encoded) {
            const Rgb d = from.rgb->decode({v[0], v[1], v[2]});
            v = {d.r, d.g, d.b};
        }
        if (same_space) return {v[0], v[1], v[2]};
        const Vec3 l = linear_source ? to_destination * v : convert.from_xyz(convert.to_xyz(v));
        return {l[0], l[1], l[2]};
    }
};

/// The method's settings from --param and --inverse. An image gets aces-rgc's final clip unless
/// --param clip= says otherwise: a file cannot hold what a display cannot show.
ClipSettings make_settings(const ClipOptions& o, ClipMethod method, bool image) {
    ClipSettings settings;
    settings.inverse = o.inverse;
    bool clip_given = false;
    for (const std::string& p : o.params) {
        try {
            settings.set(p);
        } catch (const Error& e) {
            throw UsageError(std::string("--param: ") + e.what());
        }
        clip_given = clip_given || p.starts_with("clip=");
    }
    if (image && method == ClipMethod::aces_rgc && !clip_given) settings.set("clip", 1.0);
    return settings;
}

/// "--param k=v ..." of the method's settings, for an image's description.
std::string describe_settings(const GamutClipper& clipper) {
    std::string out;
    for (const auto& [name, value] : clipper.parameters()) {
        out += " --param " + name + "=" + format_shortest(value);
    }
    if (clipper.inverse()) out += " --inverse";
    return out;
}

Pipeline make_pipeline(const ClipOptions& o, bool image) {
    if (o.method.empty()) {
        throw UsageError("--method is required (or --count-ops); valid methods: " + method_names());
    }
    ClipMethod method{};
    try {
        method = parse_clip_method(o.method);
    } catch (const Error& e) {
        throw UsageError(std::string("--method: ") + e.what());
    }
    const Space from = parse_space(o.from, "--from");
    const Space to = [&] {
        const std::string valid = "; the destination gamut is an RGB space's cube, valid names: " +
                                  join(rgb_space_names());
        Space s{};
        try {
            s = parse_space(o.to, "--to");
        } catch (const UsageError&) {
            throw UsageError("unknown space '" + o.to + "' for --to" + valid);
        }
        if (!is_rgb(s)) throw UsageError("--to '" + o.to + "' is not an RGB space" + valid);
        return s;
    }();
    const Xy white = parse_white(o.white);
    const ChromaticAdaptation cat = parse_adaptation(o.adaptation);
    if (o.threads < 0)
        throw UsageError("--threads " + std::to_string(o.threads) + " must be >= 0 (0: all)");
    std::optional<Gamut> gamut;
    try {
        gamut.emplace(*to.rgb, o.max);
    } catch (const Error&) {
        throw UsageError("--max " + format_shortest(o.max) +
                         ": the peak must be finite, > 0 and <= 1e6");
    }
    const ClipSettings settings = make_settings(o, method, image);
    std::optional<GamutClipper> clipper;
    try {
        clipper.emplace(method, *gamut, settings);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    const Space dest_linear{Family::rgb_linear, to.rgb};
    const bool same_space = is_rgb(from) && from.rgb == to.rgb;
    const bool linear_source = from.family == Family::xyz || is_rgb(from);
    Mat3 to_destination = Mat3::identity();
    if (linear_source && !same_space) {
        // The map is linear: its columns are the images of the unit vectors.
        const Space source =
            from.family == Family::xyz ? from : Space{Family::rgb_linear, from.rgb};
        const Converter linear(source, dest_linear, white, cat);
        const Vec3 c0 = linear({1.0, 0.0, 0.0}), c1 = linear({0.0, 1.0, 0.0}),
                   c2 = linear({0.0, 0.0, 1.0});
        to_destination = Mat3::from_columns(c0, c1, c2);
    }
    return Pipeline{from,
                    to,
                    to.rgb,
                    Converter(from, dest_linear, white, cat),
                    *clipper,
                    same_space,
                    linear_source,
                    to_destination};
}

// --- CSV -------------------------------------------------------------------------------------

int run_clip_csv(const ClipOptions& o, const Pipeline& p) {
    if (o.bits_option->count() > 0) {
        throw UsageError("--bits applies to PNG and TIFF images (IN OUT), not to CSV");
    }
    const double max = p.clipper.gamut().max();
    const NumericTable table = read_stdin_table(3);
    std::string out = "R,G,B\n";
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const std::span<const double> row = table.row(r);
        const Vec3 in{row[0], row[1], row[2]};
        Rgb c{};
        try {
            const Rgb linear = p.to_linear(in);
            if (p.clipper.method() != ClipMethod::smits_xyz || p.clipper.gamut().contains(linear)) {
                c = p.clipper.clip(linear);  // in-gamut colours come back unchanged
            } else {
                // The thesis' XYZ form on XYZ relative to the destination's white.
                const Xyz xyz = p.same_space ? p.dest->to_xyz(linear)
                                             : p.convert.to_destination_white(p.convert.to_xyz(in));
                c = p.dest->from_xyz(p.clipper.clip_xyz(xyz));
                // The XYZ → RGB matrix's rounding (a few ulps) must not leave the cube.
                c = {std::clamp(c.r, 0.0, max), std::clamp(c.g, 0.0, max),
                     std::clamp(c.b, 0.0, max)};
            }
        } catch (const Error& e) {
            throw Error("<stdin>:" + std::to_string(table.line_numbers[r]) + ": " + e.what());
        }
        if (p.to.family == Family::rgb_encoded) c = p.dest->encode(c);
        append_csv_line(out, std::array{c.r, c.g, c.b});
    }
    write_stdout(out);
    return exit_success;
}

// --- images ----------------------------------------------------------------------------------

/// Runs body(begin, end) over [0, n) in contiguous chunks on up to `threads` threads (0: all);
/// rethrows the first exception.
template <class Body>
void parallel_for(std::size_t n, int threads, const Body& body) {
    constexpr std::size_t min_chunk = 1 << 16;
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t wanted = threads > 0 ? static_cast<std::size_t>(threads) : hardware;
    const std::size_t workers =
        std::max<std::size_t>(1, std::min(wanted, (n + min_chunk - 1) / min_chunk));
    if (workers == 1) {
        body(std::size_t{0}, n);
        return;
    }
    std::exception_ptr failure;
    std::mutex failure_mutex;
    std::vector<std::thread> pool;
    const std::size_t chunk = (n + workers - 1) / workers;
    for (std::size_t w = 0; w < workers; ++w) {
        const std::size_t begin = w * chunk, end = std::min(n, begin + chunk);
        if (begin >= end) break;
        pool.emplace_back([&, begin, end] {
            try {
                body(begin, end);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(failure_mutex);
                if (!failure) failure = std::current_exception();
            }
        });
    }
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

/// The three colour channels of an image and what they hold.
struct ColourChannels {
    std::array<int, 3> index;
    /// X, Y and Z channels: the image is CIE XYZ, whatever --from names for RGB.
    bool xyz = false;
};

/// R, G and B by name; else X, Y and Z by name (an XYZ EXR); else refused, naming the channels.
ColourChannels colour_channels(const io::Image& image, const std::string& path) {
    const std::array<int, 3> rgb{image.channel_index("R"), image.channel_index("G"),
                                 image.channel_index("B")};
    if (rgb[0] >= 0 && rgb[1] >= 0 && rgb[2] >= 0) return {rgb, false};
    const std::array<int, 3> xyz{image.channel_index("X"), image.channel_index("Y"),
                                 image.channel_index("Z")};
    if (xyz[0] >= 0 && xyz[1] >= 0 && xyz[2] >= 0) return {xyz, true};
    throw Error(path + ": channels " + quote_untrusted(join(image.channel_names), 80) +
                "; clip needs colour channels named R, G and B (or X, Y and Z for CIE XYZ)");
}

int run_clip_image(const ClipOptions& o, const Pipeline& p) {
    io::ImageFormat format{};
    try {
        format = io::image_format_for(o.out);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    const bool encoded_out = io::is_integer_format(format);
    const double max = p.clipper.gamut().max();
    if (o.bits_option->count() > 0) {
        if (!encoded_out) {
            throw UsageError("--bits applies to PNG and TIFF; " + o.out +
                             " is written as 32-bit float (EXR)");
        }
        if (o.bits != 8 && o.bits != 16) {
            throw UsageError("--bits " + std::to_string(o.bits) + ": valid values are 8 and 16");
        }
    }
    if (encoded_out && max > 1.0) {
        throw UsageError("--max " + format_shortest(max) +
                         " is above 1, which PNG and TIFF (encoded " +
                         "values in [0, 1]) cannot hold; write an EXR");
    }

    io::Image image = io::read_image(o.in);
    const ColourChannels channels = colour_channels(image, o.in);
    const std::array<int, 3>& rgb = channels.index;
    // An image's channel names say what it holds: X, Y, Z is CIE XYZ. --from may say so too
    // (or be left out); naming an RGB space for it would clip XYZ as RGB.
    std::optional<Pipeline> xyz_pipeline;
    if (channels.xyz && p.from.family != Family::xyz) {
        if (o.from_option->count() > 0) {
            throw UsageError(o.in + " holds X, Y and Z channels (CIE XYZ) but --from is " + o.from +
                             "; give --from xyz, or leave --from out");
        }
        ClipOptions as_xyz = o;
        as_xyz.from = "xyz";
        xyz_pipeline.emplace(make_pipeline(as_xyz, true));
    }
    const Pipeline& pipe = xyz_pipeline ? *xyz_pipeline : p;
    // PNG and TIFF keep a 16-bit input's depth unless --bits says otherwise.
    const int bits =
        o.bits_option->count() > 0 ? o.bits
        : (image.stored_integer && image.stored_bits > 8) ? 16
                                                          : 8;
    if (image.stored_integer && p.from.family == Family::rgb_linear) {
        fmt::print(
            stderr,
            "irid clip: note: {} holds {}-bit encoded values; --from {} takes them as linear "
            "light (give --from {} to decode them)\n",
            o.in, image.stored_bits, o.from, p.from.rgb->name());
    }

    // Gather the colour channels as the destination's linear RGB, clip, scatter back (encoded for
    // PNG and TIFF); every other channel is left as it was. EXR colour is premultiplied by alpha
    // (associated alpha, the OpenEXR convention), PNG and TIFF colour is not: the colour is
    // clipped unpremultiplied and premultiplied again only for an EXR output.
    const std::size_t pixels = image.pixel_count();
    const std::size_t stride = static_cast<std::size_t>(image.channels);
    const int alpha = image.channel_index("A");
    const auto is_exr = [](const std::string& path) {
        std::string e = std::filesystem::path(path).extension().string();
        for (char& ch : e) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        return e == ".exr";
    };
    const bool premultiplied_in = alpha >= 0 && is_exr(o.in);
    const bool premultiplied_out = alpha >= 0 && is_exr(o.out);
    std::vector<float> colours(pixels * 3);
    parallel_for(pixels, o.threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const float* s = &image.pixels[i * stride];
            // Unpremultiply where alpha is above 0; a fully transparent pixel keeps its values.
            const float a = premultiplied_in ? s[alpha] : 1.0f;
            const float k = a > 0.0f ? 1.0f / a : 1.0f;
            Rgb c{};
            try {
                c = pipe.to_linear({s[rgb[0]] * k, s[rgb[1]] * k, s[rgb[2]] * k});
            } catch (const Error& e) {
                throw Error(o.in + ": pixel (" +
                            std::to_string(i % static_cast<std::size_t>(image.width)) + ", " +
                            std::to_string(i / static_cast<std::size_t>(image.width)) +
                            "): " + e.what());
            }
            colours[i * 3] = static_cast<float>(c.r);
            colours[i * 3 + 1] = static_cast<float>(c.g);
            colours[i * 3 + 2] = static_cast<float>(c.b);
        }
    });
    clip_batch(p.clipper, colours, BatchOptions{.threads = o.threads, .simd = true});
    parallel_for(pixels, o.threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            Rgb c{colours[i * 3], colours[i * 3 + 1], colours[i * 3 + 2]};
            if (encoded_out) c = p.dest->encode(c);
            float* d = &image.pixels[i * stride];
            // Premultiply for EXR, except a transparent EXR pixel, whose colour (light added
            // without covering) was never divided by its alpha of 0.
            if (premultiplied_out && (d[alpha] > 0.0f || !premultiplied_in)) {
                const double a = d[alpha];
                c = {c.r * a, c.g * a, c.b * a};
            }
            d[rgb[0]] = static_cast<float>(c.r);
            d[rgb[1]] = static_cast<float>(c.g);
            d[rgb[2]] = static_cast<float>(c.b);
        }
    });

    if (channels.xyz) {  // the colour channels now hold RGB of the destination
        const char* const names[] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c) image.channel_names[static_cast<std::size_t>(rgb[c])] = names[c];
    }
    const std::string written = encoded_out ? p.dest->name() : p.dest->name() + "-linear";
    image.color_space = written;
    image.description = fmt::format(
        "irid clip --method {}{} --from {} --to {} --max {}; colour space {} ({})", o.method,
        describe_settings(p.clipper), channels.xyz ? std::string("xyz") : o.from, o.to,
        format_shortest(max), written, encoded_out ? "encoded" : "linear");
    io::write_image(o.out, image, io::ImageEncoding{.bits = bits, .compression = {}});
    return exit_success;
}

int run_clip(const ClipOptions& o) {
    if (o.count_ops) {
        if (!o.in.empty()) throw UsageError("--count-ops takes no files");
        return run_count_ops();
    }
    const Pipeline p = make_pipeline(o, !o.in.empty());
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
    cmd->add_option("--method", o->method, "Clipping method: " + method_names());
    cmd->add_option("--param", o->params,
                    "A method's parameter, name=value (repeatable): " + parameter_help() +
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
    cmd->add_option("--threads", o->threads, "Threads for images (0: all)")->capture_default_str();
    o->bits_option =
        cmd->add_option("--bits", o->bits,
                        "Bits per sample of PNG and TIFF output: 8 or 16 (default: 16 for a 16-bit "
                        "input image, else 8)")
            ->capture_default_str();
    cmd->add_flag(
        "--count-ops", o->count_ops,
        "Print Table 1: operations per colour of the thesis' clip, ours beside the thesis'");
    cmd->add_option("IN", o->in,
                    "Input image (EXR, TIFF, PNG, HDR, anything OpenImageIO reads). Its values are "
                    "in --from: decoded with that space's transfer function when --from is an "
                    "encoded name (an 8-bit sRGB PNG wants --from srgb)");
    cmd->add_option("OUT", o->out,
                    "Output image: .exr (linear float), .png, .tif or .tiff (encoded)");
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
