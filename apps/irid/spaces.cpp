#include "spaces.h"

#include "cli_common.h"

namespace irid::cli {

Space parse_space(const std::string& name, const char* option) {
    if (const std::optional<ColorSpace> s = find_color_space(name)) return *s;
    throw UsageError("unknown space '" + name + "' for " + option +
                     "; valid names: " + join(space_names()));
}

Xy parse_white(const std::string& name) {
    try {
        return white_point_xy(name);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
}

ChromaticAdaptation parse_adaptation(const std::string& name) {
    try {
        return parse_chromatic_adaptation(name);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
}

}  // namespace irid::cli
