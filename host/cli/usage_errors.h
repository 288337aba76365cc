// What a command line that cannot be parsed is told: one line, and for a misspelt flag,
// command or value the nearest names there are ("did you mean --spp?").
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace pathcl::cli {

// The names among `names` nearest to `typed`, ignoring case: those at the least edit
// distance (insertions, deletions, substitutions and swaps of neighbours), if it is at
// most a third of the typed name's length without its leading dashes (at least 1, at most
// 3), and of those the ones that begin with it if any do; else those that begin with it
// (when it has at least three characters); at most three, in the order of `names`.
std::vector<std::string> nearest_names(const std::string& typed, const std::vector<std::string>& names);

// "; did you mean A?" (or "A or B", "A, B or C"), or "" when `names` is empty.
std::string did_you_mean(const std::vector<std::string>& names);

// The error line (without "pathcl: error: ") for `error`, thrown by parsing `app`'s
// command line: an unknown flag or command is named with the nearest names the command
// has, an unexpected argument with the command it was given to; other errors keep
// CLI11's message.
std::string usage_error(const CLI::App& app, const CLI::ParseError& error);

} // namespace pathcl::cli
