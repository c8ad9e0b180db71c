// irid shader: the exact film colour as a shader chunk and its table, for real-time renderers.
//
//   irid shader --lang glsl|wgsl [--illuminant D65] [--space srgb] -o DIR
//     → DIR/irid_iridescence.glsl (.wgsl), DIR/irid_film_table.f32, DIR/irid_film_table.json
//
// The chunk, the table and their description are the library's (irid/optics/film_shader.h);
// this file parses and writes.
#include "../cli_common.h"

#include <irid/color/illuminant.h>
#include <irid/error.h>
#include <irid/io/output_file.h>
#include <irid/optics/film_shader.h>
#include <irid/text_input.h>

#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <string>

namespace irid::cli {
namespace {

struct ShaderArgs {
    std::string lang;
    std::string illuminant = "D65";
    std::string space = "srgb";
    std::string out;
};

int run_shader(const ShaderArgs& a) {
    if (a.lang.empty()) throw UsageError("--lang is required; valid: glsl, wgsl");
    if (a.out.empty())
        throw UsageError("-o DIR is required (the folder of the chunk and its table)");
    ShaderLanguage language{};
    try {
        language = parse_shader_language(a.lang);
    } catch (const Error& e) {
        throw UsageError(std::string("--lang: ") + e.what());
    }
    const auto usage = [](const char* option, auto&& parse) {
        try {
            return parse();
        } catch (const Error& e) {
            throw UsageError(std::string(option) + ": " + e.what());
        }
    };
    // Checked one at a time, so that the message names the option at fault.
    (void)usage("--illuminant", [&] { return canonical_illuminant_name(a.illuminant); });
    const FilmShaderSetup setup =
        usage("--space", [&] { return film_shader_setup(a.illuminant, a.space); });
    if (std::filesystem::exists(a.out) && !std::filesystem::is_directory(a.out)) {
        throw UsageError("-o " + quote_untrusted(a.out, 200) + " exists and is not a folder");
    }
    const FilmShader shader(setup.colorimeter, setup.illuminant, setup.space);
    for (const std::filesystem::path& p : io::write_output_files(a.out, shader.files(language))) {
        fmt::print("{}\n", p.string());
    }
    return exit_success;
}

}  // namespace

void add_shader_command(CLI::App& app, Runner& runner) {
    auto a = std::make_shared<ShaderArgs>();
    CLI::App* cmd = app.add_subcommand(
        "shader",
        "Write the exact thin-film colour as a shader chunk for real-time renderers "
        "(evalIridescence, as three.js and glTF's KHR_materials_iridescence call it) with its "
        "table: DIR/irid_iridescence.glsl (or .wgsl), DIR/irid_film_table.f32, "
        "DIR/irid_film_table.json");
    cmd->add_option("--lang", a->lang, "The shading language: glsl (GLSL ES 3.00) or wgsl (WebGPU)");
    cmd->add_option("--illuminant", a->illuminant, "D65, D50, A, E, D<CCT>, blackbody:<T>")
        ->capture_default_str();
    cmd->add_option(
           "--space", a->space,
           "The working space of the chunk's linear RGB, by name or NAME-linear: srgb, "
           "display-p3, rec2020, adobe-rgb, smpte-c, ntsc1953, aces2065-1, acescg (an encoding "
           "such as rec2100-pq is refused: the chunk returns linear light)")
        ->capture_default_str();
    cmd->add_option("-o,--output", a->out, "The folder (created if missing)");
    cmd->footer(
        "\nExample: irid shader --lang glsl -o irid-shader\n"
        "  then bind irid-shader/irid_film_table.f32 (width x height RGBA32F texels, as the .json "
        "says) to the uniform iridFilmTable and paste the chunk in place of three.js's "
        "iridescence_fragment. docs/OPTICS.md, \"In a renderer\", describes it.");
    cmd->callback([a, &runner] { runner = [a] { return run_shader(*a); }; });
}

}  // namespace irid::cli
