#pragma once

// The options that choose a clip pipeline (irid/gamut/pipeline.h), shared by `irid clip` and
// `irid lut`: the method, its parameters and direction, the spaces, the peak, the white and the
// adaptation. Every refusal is a UsageError (exit 2) naming the option.

#include <irid/gamut/clip.h>
#include <irid/gamut/pipeline.h>

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace irid::cli {

struct PipelineArgs {
    std::string method;
    std::string from = "srgb-linear";
    std::string to = "srgb-linear";
    double max = 1.0;
    std::string white = "D65";
    std::string adaptation = "bradford";
    int threads = 0;
    std::vector<std::string> params;
    bool inverse = false;
};

/// "clamp, smits, ...": the methods, for --help and messages.
[[nodiscard]] std::string clip_method_names();
/// "oklab-adaptive: alpha (default 0.05); ...": every method's parameters, for --help.
[[nodiscard]] std::string clip_parameter_help();
/// " --param k=v ... [--inverse]" of a clipper's settings, for the descriptions files carry.
[[nodiscard]] std::string describe_clip_settings(const GamutClipper& clipper);

/// The arguments checked and turned into the library's pipeline. `final_clip`: aces-rgc gets
/// clip=true unless --param clip= says otherwise (an integer file cannot hold what a display
/// cannot show). `from`, when given, replaces args.from (a space an image file named; it must
/// outlive the pipeline).
[[nodiscard]] ClipPipeline make_clip_pipeline(const PipelineArgs& args, bool final_clip,
                                              const ColorSpace* from = nullptr);

}  // namespace irid::cli
