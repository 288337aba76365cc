// The pathcl command line: every command (host/cli/command_*.cpp) in one CLI11 app, with
// --help, --version and the help format of help_format.h.
#pragma once

#include <memory>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.h"

namespace pathcl::cli {

struct CommandLine {
    CLI::App app{"pathcl: a physically based OpenCL path tracer for glTF 2.0 scenes", "pathcl"};
    std::vector<Command> commands;
};

// argc and argv: the command line as typed (a study quotes it).
std::unique_ptr<CommandLine> make_command_line(int argc, char** argv);

// Parses the command line and runs the command it names; returns the exit code. --help
// and --version print to stdout and return 0; no command prints the help to stdout and
// returns 2; every error is one line on stderr ("pathcl: error: ...") and returns 2
// (usage_errors.h), and nothing is written unless the command succeeded.
int run_command_line(int argc, char** argv);

} // namespace pathcl::cli
