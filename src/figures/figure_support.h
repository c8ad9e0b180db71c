#pragma once

// What every figure of irid_figures shares (private to the module and its tests): the catalog
// entry type, validated reading of FigureRequest::options, and number formatting for captions.

#include <irid/figures/figures.h>

#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace irid::figures::detail {

/// Computes one figure and writes request.output. The request has been checked already: the
/// name is this figure's, the extension is one of its FigureInfo::extensions, the size lies in
/// [min_size_px, max_size_px]. Options are checked by the function (Options below).
using DrawFunction = FigureResult (*)(const FigureRequest& request);

struct CatalogEntry {
    FigureInfo info;
    DrawFunction draw;
};

/// The catalog with the draw functions (src/figures/catalog.cpp).
[[nodiscard]] std::span<const CatalogEntry> catalog_entries();

/// A figure's options, validated. Construction rejects keys not in `known_keys` (the message
/// names the figure, the key and the known keys); the accessors reject bad values (naming the
/// key, the value and what is allowed). A key given twice: the last value wins.
class Options {
public:
    Options(const FigureRequest& request, std::initializer_list<std::string_view> known_keys);

    [[nodiscard]] bool has(std::string_view key) const noexcept;
    /// The raw value, or `fallback` when the key is absent.
    [[nodiscard]] std::string text(std::string_view key, std::string_view fallback) const;
    /// One of `allowed` (exact match), or `fallback` when absent.
    [[nodiscard]] std::string choice(std::string_view key,
                                     std::initializer_list<std::string_view> allowed,
                                     std::string_view fallback) const;
    [[nodiscard]] std::string choice(std::string_view key,
                                     const std::vector<std::string>& allowed,
                                     std::string_view fallback) const;
    /// A finite number in [lo, hi], or `fallback` when absent.
    [[nodiscard]] double number(std::string_view key, double fallback, double lo,
                                double hi) const;
    /// An integer in [lo, hi], or `fallback` when absent.
    [[nodiscard]] int integer(std::string_view key, int fallback, int lo, int hi) const;
    /// Comma-separated items, trimmed, none empty; `fallback` (also comma-separated) when absent.
    [[nodiscard]] std::vector<std::string> list(std::string_view key,
                                                std::string_view fallback) const;
    /// Comma-separated finite numbers, each in [lo, hi]; exactly `count` of them unless
    /// count == 0 (then at least one).
    [[nodiscard]] std::vector<double> numbers(std::string_view key, std::string_view fallback,
                                              double lo, double hi, std::size_t count = 0) const;

    /// Throws irid::Error "<figure>: option KEY=VALUE: <what>; allowed: <allowed>".
    [[noreturn]] void fail(std::string_view key, std::string_view value, std::string_view what,
                           std::string_view allowed) const;

    [[nodiscard]] const std::string& figure() const noexcept { return m_figure; }

private:
    [[nodiscard]] const std::string* find(std::string_view key) const noexcept;

    std::string m_figure;
    std::vector<std::pair<std::string, std::string>> m_values;
};

/// Items joined with `separator`.
[[nodiscard]] std::string join(const std::vector<std::string>& items,
                               std::string_view separator);
/// A number with `decimals` fixed decimals ("0.123"), never "-0.000".
[[nodiscard]] std::string fixed(double value, int decimals);
/// A number in the shortest form that reads back exactly (like the CLI's output).
[[nodiscard]] std::string shortest(double value);
/// The extension of `path`, lower case, with the dot (".svg"); "" when none.
[[nodiscard]] std::string lower_extension(const std::filesystem::path& path);

}  // namespace irid::figures::detail
