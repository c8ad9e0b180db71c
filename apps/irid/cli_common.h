#pragma once

#include <irid/color/numeric_table.h>

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace irid::cli {

/// Exit statuses of every irid command (DESIGN.md): success, bad data or failed I/O, usage.
inline constexpr int exit_success = 0;
inline constexpr int exit_bad_data = 1;
inline constexpr int exit_usage = 2;

/// A usage error found after parsing (an unknown name in an option's value): exit status 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// What a subcommand does once its options are parsed; returns the exit status.
using Runner = std::function<int()>;

/// Each subcommand registers itself on the app and, when chosen, stores its runner.
void add_convert_command(CLI::App& app, Runner& runner);
void add_display_command(CLI::App& app, Runner& runner);
void add_xyz_command(CLI::App& app, Runner& runner);
void add_delta_e_command(CLI::App& app, Runner& runner);
void add_film_command(CLI::App& app, Runner& runner);
void add_film_table_command(CLI::App& app, Runner& runner);
void add_film_error_command(CLI::App& app, Runner& runner);
void add_clip_command(CLI::App& app, Runner& runner);
void add_clip_report_command(CLI::App& app, Runner& runner);
void add_lut_command(CLI::App& app, Runner& runner);
void add_ocio_config_command(CLI::App& app, Runner& runner);
void add_figure_command(CLI::App& app, Runner& runner);
void add_render_command(CLI::App& app, Runner& runner);
void add_gallery_command(CLI::App& app, Runner& runner);
void add_shader_command(CLI::App& app, Runner& runner);

/// Reads all of standard input as a numeric CSV table (source name "<stdin>").
[[nodiscard]] NumericTable read_stdin_table(int columns, int min_columns = 1);

/// Writes one CSV line of numbers in shortest round-trip form.
void append_csv_line(std::string& out, std::span<const double> values);

/// Writes the whole output at once; throws irid::Error when standard output fails.
void write_stdout(const std::string& text);

/// An option's transform to a whole number in [lo, hi]: "--width abc" is "'abc' is not a whole
/// number; allowed: 1 to 16384", not "out of range"; a whole number written another way
/// ("1e3", "12.0") becomes that number. Give it with ->transform (->check cannot rewrite).
[[nodiscard]] CLI::Validator whole_number_in(long long lo, long long hi);

/// Adds `--threads` (0: all) to `cmd`, a whole number in [0, irid::max_threads] as Python's
/// `threads=` takes it; anything else is a usage error naming the range.
CLI::Option* add_threads_option(CLI::App* cmd, int& threads, const std::string& description);

/// "LO,HI" as two numbers; throws UsageError "OPTION 'TEXT': give ... as LO,HI (two numbers,
/// e.g. EXAMPLE)" otherwise. `what` says what the pair is ("the inputs covered").
[[nodiscard]] std::pair<double, double> parse_number_pair(const std::string& option, const std::string& text,
                                                          const std::string& what, const std::string& example);

/// "a, b, c" for messages.
[[nodiscard]] std::string join(const std::vector<std::string>& names);

/// The image file's name ends in .exr (any case): OpenEXR, whose colour is premultiplied by its
/// alpha. Any other name (an input OpenImageIO reads: .hdr, .dpx, ...) is not.
[[nodiscard]] bool is_exr_path(const std::string& path);

}  // namespace irid::cli
