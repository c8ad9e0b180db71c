// irid: interference colours, colour science and gamut clipping from the command line.
#include "cli_common.h"

#include <irid/error.h>

#include <fmt/core.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    using namespace irid::cli;
    CLI::App app{"irid: interference colours and gamut clipping (after Smits 1990)", "irid"};
    app.set_version_flag("--version", "irid 0.1.0");
    app.require_subcommand(1);

    Runner runner;
    add_convert_command(app, runner);
    add_xyz_command(app, runner);
    add_delta_e_command(app, runner);

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
