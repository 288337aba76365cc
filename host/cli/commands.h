// The subcommands of the pathcl command line, one file each (command_*.cpp). Each adds
// its CLI11 subcommand with its options to the app and returns what runs it once parsed.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace pathcl::cli {

struct Command {
    CLI::App* app = nullptr;  // the subcommand
    std::function<int()> run; // runs it after parsing; returns the exit code
};

Command add_render_command(CLI::App& app);
Command add_devices_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_samples_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_merge_command(CLI::App& app);
Command add_info_command(CLI::App& app);
// argc and argv: the command line as typed, quoted in the study's summary.
Command add_converge_command(CLI::App& app, int argc, char** argv);

} // namespace pathcl::cli
