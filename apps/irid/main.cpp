// irid: interference colours, colour science and gamut clipping from the command line.
#include "cli_common.h"

#include <irid/error.h>
#include <irid/exchange/lut.h>
#include <irid/text_input.h>

#include <fmt/core.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

namespace {

/// A message on stderr, made safe for a terminal (it may quote input irid did not write).
void report(const std::string& message) {
    const std::string safe = irid::terminal_safe(message);
    std::fputs(safe.c_str(), stderr);
}

/// Whatever is still buffered for standard output is written now; a failure (a full disk, a
/// closed pipe) is an I/O error of the command, not a success.
bool flush_standard_output() {
    std::cout.flush();
    const bool ok = std::cout.good() && std::fflush(stdout) == 0 && !std::ferror(stdout);
    return ok;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace irid::cli;
    // Past a file-size limit (ulimit -f) a write fails with EFBIG ("File too large") and the
    // command cleans up after itself, instead of SIGXFSZ ending the process with its temporary
    // file left behind.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app{"irid: interference colours and gamut clipping (after Smits 1990)", "irid"};
    app.set_version_flag("--version", "irid " + std::string(irid::irid_version()));
    app.require_subcommand(1);
    // On a usage error, say what was wrong, then the chosen command's options and their valid
    // values, so the message always lists what is allowed.
    app.failure_message([](const CLI::App* root, const CLI::Error& e) {
        const auto chosen = root->get_subcommands();
        // A subcommand's usage line names the program too: "Usage: irid render [OPTIONS] scene".
        const std::string help = chosen.empty() ? root->help() : chosen.front()->help("irid");
        return irid::terminal_safe(std::string("irid: ") + e.what() + "\n\n" + help);
    });

    Runner runner;
    add_convert_command(app, runner);
    add_xyz_command(app, runner);
    add_delta_e_command(app, runner);
    add_film_command(app, runner);
    add_film_table_command(app, runner);
    add_film_error_command(app, runner);
    add_clip_command(app, runner);
    add_clip_report_command(app, runner);
    add_display_command(app, runner);
    add_lut_command(app, runner);
    add_ocio_config_command(app, runner);
    add_figure_command(app, runner);
    add_render_command(app, runner);
    add_shader_command(app, runner);
    add_gallery_command(app, runner);

    // CLI11 reports an unknown command word as a missing subcommand; name it instead.
    if (argc > 1 && argv[1][0] != '-') {
        const std::string word = argv[1];
        std::string names;
        bool known = false;
        for (const CLI::App* sub : app.get_subcommands({})) {
            known = known || sub->get_name() == word;
            names += (names.empty() ? "" : ", ") + sub->get_name();
        }
        if (!known) {
            report(fmt::format("irid: unknown command {}; valid commands: {}\n",
                               irid::quote_untrusted(word), names));
            return exit_usage;
        }
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int status = app.exit(e);  // --help and --version print to stdout
        if (status == 0 && !flush_standard_output()) {
            report(fmt::format("irid: cannot write to standard output: {}\n", std::strerror(errno)));
            return exit_bad_data;
        }
        return status == 0 ? exit_success : exit_usage;
    }

    const std::string command = app.get_subcommands().front()->get_name();
    int status = exit_success;
    try {
        status = runner();
    } catch (const UsageError& e) {
        report(fmt::format("irid {}: {}\n", command, e.what()));
        return exit_usage;
    } catch (const irid::Error& e) {
        report(fmt::format("irid {}: {}\n", command, e.what()));
        return exit_bad_data;
    } catch (const std::bad_alloc&) {
        report(fmt::format("irid {}: out of memory\n", command));
        return exit_bad_data;
    } catch (const std::exception& e) {
        report(fmt::format("irid {}: {}\n", command, e.what()));
        return exit_bad_data;
    }
    if (!flush_standard_output()) {
        report(fmt::format("irid {}: cannot write to standard output: {}\n", command,
                           std::strerror(errno)));
        return exit_bad_data;
    }
    return status;
}
