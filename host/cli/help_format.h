// How `pathcl --help` and each command's --help read: the options in named groups, in the
// order the command gives them (that of docs/usage.md), descriptions wrapped to the
// page, and literal example command lines at the end.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace pathcl::cli {

// The groups options shared by several commands belong to (docs/usage.md's sections).
inline constexpr const char* kOutputGroup = "Output";
inline constexpr const char* kSamplingGroup = "Image and sampling";
inline constexpr const char* kBudgetGroup = "Budgets and progress";
inline constexpr const char* kCameraGroup = "Camera";
inline constexpr const char* kEnvironmentGroup = "Environment";
inline constexpr const char* kSceneGroup = "Scene";
inline constexpr const char* kDeviceGroup = "Devices";
inline constexpr const char* kDistributedGroup = "Distributed rendering";
inline constexpr const char* kCheckpointGroup = "Checkpoints";
inline constexpr const char* kKernelGroup = "Kernels";
inline constexpr const char* kDiagnosticGroup = "Diagnostics";

struct HelpGroup {
    std::string name;                 // "Output"
    std::vector<std::string> options; // their flags: "--output", "--tone", ...
};

struct HelpExample {
    std::string command; // a command line as typed: "pathcl render scenes/cornell-box.gltf -o box.png"
    std::string what;    // what it does
};

// Lists `command`'s option groups in the order of `groups`, putting the options each
// names into it (every flag named must be one of the command's: std::logic_error
// otherwise; the shared options of options.h come in their groups already), and ends its
// help with `examples`. Options in no group are listed last, under "Options".
void describe_command(CLI::App* command, const std::vector<HelpGroup>& groups,
                      const std::vector<HelpExample>& examples);

// The help format of `app` and the commands added to it after this call, with
// `examples` at the end of the app's own help.
void use_help_format(CLI::App& app, const std::vector<HelpExample>& examples);

} // namespace pathcl::cli
