// irid: interference colours, colour science and gamut clipping from the command line.
#include "cli_common.h"

#include <irid/error.h>

#include <fmt/core.h>

#include <exception>
#include <string>
#include <iostream>

int main(int argc, char** argv) {
    using namespace irid::cli;
    CLI::App app{"irid: interference colours and gamut clipping (after Smits 1990)", "irid"};
    app.set_version_flag("--version", "irid 0.1.0");
    app.require_subcommand(1);
    // On a usage error, say what was wrong, then the chosen command's options and their valid
    // values, so the message always lists what is allowed.
    app.failure_message([](const CLI::App* root, const CLI::Error& e) {
        const auto chosen = root->get_subcommands();
        const CLI::App* shown = chosen.empty() ? root : chosen.front();
        return std::string("irid: ") + e.what() + "\n\n" + shown->help();
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
    add_figure_command(app, runner);
    add_render_command(app, runner);
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
            fmt::print(stderr, "irid: unknown command '{}'; valid commands: {}\n", word, names);
            return exit_usage;
        }
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int status = app.exit(e);
        return status == 0 ? exit_success : exit_usage;
    }

    const std::string command = app.get_subcommands().front()->get_name();
    try {
        return runner();
    } catch (const UsageError& e) {
        fmt::print(stderr, "irid {}: {}\n", command, e.what());
        return exit_usage;
    } catch (const irid::Error& e) {
        fmt::print(stderr, "irid {}: {}\n", command, e.what());
        return exit_bad_data;
    } catch (const std::exception& e) {
        fmt::print(stderr, "irid {}: {}\n", command, e.what());
        return exit_bad_data;
    }
}
