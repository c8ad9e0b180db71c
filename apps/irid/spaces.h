#pragma once

// The colour spaces of the command line (irid/color/convert.h), with the command line's errors:
// an unknown name is a usage error (exit 2) naming the option.

#include <irid/color.h>
#include <irid/color/convert.h>

#include <string>
#include <vector>

namespace irid::cli {

using Space = ColorSpace;
using Family = SpaceFamily;

/// True for NAME and NAME-linear of an RGB space.
[[nodiscard]] inline bool is_rgb(const Space& s) noexcept { return s.is_rgb(); }

[[nodiscard]] inline std::vector<std::string> space_names() { return color_space_names(); }
[[nodiscard]] inline std::vector<std::string> rgb_space_names() { return rgb_color_space_names(); }
[[nodiscard]] inline std::string space_name(const Space& s) { return color_space_name(s); }
[[nodiscard]] inline const char* header_of(const Space& s) { return channel_names(s); }

/// The space with this name; throws UsageError naming `option` and listing the names otherwise.
[[nodiscard]] Space parse_space(const std::string& name, const char* option);
/// --white: a named white or "x,y"; throws UsageError listing the names otherwise.
[[nodiscard]] Xy parse_white(const std::string& name);
/// --adaptation; throws UsageError listing the methods otherwise.
[[nodiscard]] ChromaticAdaptation parse_adaptation(const std::string& name);

}  // namespace irid::cli
