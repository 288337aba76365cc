#include "cli/command_line.h"

#include <iostream>
#include <new>
#include <string>

#include "cli/help_format.h"
#include "cli/options.h"
#include "cli/usage_errors.h"
#include "cli/version.h"
#include "common/error.h"

namespace pathcl::cli {

std::unique_ptr<CommandLine> make_command_line(int argc, char** argv)
{
    auto line = std::make_unique<CommandLine>();
    CLI::App& app = line->app;
    use_help_format(app, {{"pathcl devices", "the OpenCL devices, with the index --device takes"},
                          {"pathcl render scenes/cornell-box.gltf -o box.png", "render the Cornell box to a PNG"},
                          {"pathcl render --help", "every flag of render, in groups, with examples"}});
    app.set_help_flag("-h,--help", "print this help and exit"); // (before the commands: they copy it)
    app.require_subcommand(0, 1);
    app.set_version_flag("--version", version_text,
                         "print the version, the commit it was built from and the OpenCL platforms found");
    line->commands = {add_render_command(app),  add_merge_command(app),   add_converge_command(app, argc, argv),
                      add_info_command(app),    add_devices_command(app), add_bench_command(app),
                      add_compare_command(app), add_samples_command(app)};
    for (const Command& c : line->commands)
        c.app->group("Commands");
    return line;
}

int run_command_line(int argc, char** argv)
{
    std::unique_ptr<CommandLine> line = make_command_line(argc, argv);
    CLI::App& app = line->app;
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) { // --help, --version
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "pathcl: error: " << printable_line(usage_error(app, e)) << '\n';
        return 2;
    }
    try {
        for (const Command& c : line->commands)
            if (c.app->parsed())
                return c.run();
        std::cout << app.help();
        std::cerr << "pathcl: error: no command given ('pathcl COMMAND --help' tells more of each)\n";
        return 2;
    } catch (const ParameterError& e) {
        std::cerr << "pathcl: error: " << printable_line(e.describe(flag_for)) << '\n';
    } catch (const std::bad_alloc&) {
        // Admission checks count what a command will hold; this is what they missed.
        std::cerr << "pathcl: error: out of host memory (a limit of the process or the machine was reached)\n";
    } catch (const std::exception& e) {
        std::cerr << "pathcl: error: " << printable_line(e.what()) << '\n';
    }
    return 2;
}

} // namespace pathcl::cli
