// pathcl command line: `render`, `devices`, `bench`, `compare`, `samples`, `info`, `converge` (one file each,
// host/cli/command_*.cpp). Every error is one line on stderr ("pathcl: error: ...") and
// exit code 2; nothing is written unless the command succeeded. The library names
// parameters in its errors; here they are named by their flags.
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/options.h"
#include "cli/version.h"
#include "common/error.h"

int main(int argc, char** argv)
{
    CLI::App app{"pathcl: a physically based OpenCL path tracer for glTF 2.0 scenes"};
    app.require_subcommand(1);
    app.set_version_flag("--version", pathcl::cli::version_text,
                         "print the version, the commit it was built from and the OpenCL platforms found");
    // Usage errors follow the same contract as every other error: one line, exit code 2.
    // (Set before the subcommands are added: they inherit it.)
    app.failure_message([](const CLI::App*, const CLI::Error& e) {
        return "pathcl: error: " + pathcl::printable_line(pathcl::one_line(e.what())) + "\n";
    });
    std::vector<pathcl::cli::Command> commands = {
        pathcl::cli::add_render_command(app),  pathcl::cli::add_devices_command(app),
        pathcl::cli::add_bench_command(app),   pathcl::cli::add_samples_command(app),
        pathcl::cli::add_compare_command(app), pathcl::cli::add_merge_command(app),
        pathcl::cli::add_info_command(app),    pathcl::cli::add_converge_command(app, argc, argv)};
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    try {
        for (const pathcl::cli::Command& c : commands)
            if (c.app->parsed())
                return c.run();
        return 2;
    } catch (const pathcl::ParameterError& e) {
        std::cerr << "pathcl: error: " << pathcl::printable_line(e.describe(pathcl::cli::flag_for)) << '\n';
    } catch (const std::bad_alloc&) {
        // Admission checks count what a command will hold; this is what they missed.
        std::cerr << "pathcl: error: out of host memory (a limit of the process or the machine was reached)\n";
    } catch (const std::exception& e) {
        std::cerr << "pathcl: error: " << pathcl::printable_line(e.what()) << '\n';
    }
    return 2;
}
