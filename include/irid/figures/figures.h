#pragma once

// The thesis' figures and tables, drawn from the library's own numbers (irid_figures).
//
// Every figure is a name in a catalog; draw_figure() computes what the figure shows with
// irid_color, irid_optics and irid_gamut, draws it with Cairo and writes the file atomically
// (include/irid/io/atomic_file.h). The output's extension picks the format: ".svg" or ".png"
// for plots, ".md" or ".html" for tables (FigureInfo::extensions lists what a figure accepts).

#include <irid/error.h>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace irid::figures {

/// Smallest and largest image size accepted by draw_figure, in pixels (PNG) or points (SVG).
inline constexpr int min_size_px = 64;
inline constexpr int max_size_px = 8192;

/// The irid::Error thrown for a bad request (unknown figure name, unsupported extension, size
/// out of range, unknown option or bad option value), as opposed to a failure to compute or
/// write (plain irid::Error): a program can map the first to a usage error.
class FigureRequestError : public Error {
public:
    using Error::Error;
};

/// What to draw, where, and with which figure-specific options.
struct FigureRequest {
    /// A name from figure_catalog() ("cmf-primaries", ...).
    std::string name;
    /// The file to write; its extension picks the format.
    std::filesystem::path output;
    /// Image size: PNG pixels, SVG points (1/72 in). Ignored for tables.
    int width_px = 960, height_px = 600;
    /// Figure-specific key=value pairs, validated: an unknown key or a bad value throws
    /// irid::Error naming the key and the allowed values. A key given twice: the last wins.
    std::vector<std::pair<std::string, std::string>> options;
};

/// What was written.
struct FigureResult {
    /// What the figure shows, with the parameters used (one paragraph, plain text).
    std::string caption;
    /// Numbers worth showing beside the figure: (label, value as text).
    std::vector<std::pair<std::string, std::string>> measurements;
    /// Size of the written image in pixels (PNG) or points (SVG); 0 for tables.
    int width_px = 0, height_px = 0;
};

/// One figure of the catalog.
struct FigureInfo {
    /// "cmf-primaries".
    std::string name;
    /// "Figure 2" / "Table 1" / "" when the thesis has no such figure.
    std::string thesis_figure;
    /// A one-line title.
    std::string title;
    /// The accepted output extensions, with the dot: ".svg", ".png" or ".md", ".html".
    std::vector<std::string> extensions;
    /// The options and their defaults, for --help and the gallery
    /// ("spaces=LIST (default srgb,display-p3,rec2020) ...").
    std::string options_help;
};

/// Every figure, in a stable order (thesis order first, then irid's own figures).
[[nodiscard]] std::span<const FigureInfo> figure_catalog();

/// The catalog entry with this name, or nullptr.
[[nodiscard]] const FigureInfo* find_figure(std::string_view name) noexcept;

/// Computes and writes one figure. Throws FigureRequestError for an unknown name (listing the
/// valid names), an extension the figure does not accept (listing the allowed ones), a size
/// outside [min_size_px, max_size_px] or a bad option (naming the key and the allowed values);
/// irid::Error for a failed write (naming the file). Nothing is left at `output` then.
FigureResult draw_figure(const FigureRequest& request);

/// Text made safe for HTML element content and attribute values: & < > " become entities.
[[nodiscard]] std::string html_escape(std::string_view text);

}  // namespace irid::figures
