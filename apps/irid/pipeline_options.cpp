#include "pipeline_options.h"

#include "cli_common.h"
#include "spaces.h"

#include <irid/color/numeric_table.h>
#include <irid/error.h>

#include <cmath>
#include <optional>

namespace irid::cli {

std::string clip_method_names() {
    std::vector<std::string> names;
    for (const ClipMethod m : clip_methods()) names.emplace_back(clip_method_name(m));
    return join(names);
}

std::string clip_parameter_help() {
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

std::string describe_clip_settings(const GamutClipper& clipper) {
    std::string out;
    for (const auto& [name, value] : clipper.parameters()) {
        out += " --param " + name + "=" + format_shortest(value);
    }
    if (clipper.inverse()) out += " --inverse";
    return out;
}

namespace {

ClipSettings make_settings(const PipelineArgs& o, ClipMethod method, bool final_clip) {
    ClipSettings settings;
    settings.inverse = o.inverse;
    for (const std::string& p : o.params) {
        try {
            settings.set(p);
        } catch (const Error& e) {
            throw UsageError(std::string("--param: ") + e.what());
        }
    }
    return final_clip ? display_clip_settings(method, std::move(settings)) : settings;
}

}  // namespace

ClipPipeline make_clip_pipeline(const PipelineArgs& o, bool final_clip, const ColorSpace* from_file) {
    if (o.method.empty()) throw UsageError("--method is required; valid methods: " + clip_method_names());
    ClipMethod method{};
    try {
        method = parse_clip_method(o.method);
    } catch (const Error& e) {
        throw UsageError(std::string("--method: ") + e.what());
    }
    const Space from = from_file != nullptr ? *from_file : parse_space(o.from, "--from");
    const Space to = [&] {
        const std::string valid = "; the destination gamut is an RGB space's cube, valid names: " +
                                  join(rgb_space_names());
        const std::optional<Space> s = find_color_space(o.to);
        if (!s) throw UsageError("unknown space '" + o.to + "' for --to" + valid);
        if (!is_rgb(*s)) throw UsageError("--to '" + o.to + "' is not an RGB space" + valid);
        return *s;
    }();
    ClipPipelineOptions options;
    options.white = parse_white(o.white);
    options.adaptation = parse_adaptation(o.adaptation);
    if (o.threads < 0)
        throw UsageError("--threads " + std::to_string(o.threads) + " must be >= 0 (0: all)");
    if (!(std::isfinite(o.max) && o.max > 0.0 && o.max <= 1e6)) {
        throw UsageError("--max " + format_shortest(o.max) +
                         ": the peak must be finite, > 0 and <= 1e6");
    }
    options.max = o.max;
    options.settings = make_settings(o, method, final_clip);
    try {
        return ClipPipeline(method, from, to, options);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
}

}  // namespace irid::cli
