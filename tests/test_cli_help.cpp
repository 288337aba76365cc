// What the command line teaches, through the real binary: `pathcl` alone prints the help
// (and is a usage error), --version names the version, the commit and the OpenCL
// platforms, each command's help lists its options in groups with enum values by name and
// ends with examples whose flags and scenes exist, and a misspelt flag, command or value
// gets one error line with the nearest names.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/tool_run.h"

namespace pathcl::test_cli_help {
namespace {

const std::string kCornell = "'" + std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box.gltf'";
// Small, so that a regression that renders instead of refusing stays quick.
const std::string kTiny = " --width 4 --height 4 --spp 1";
const std::vector<std::string> kCommands = {"render",  "merge", "converge", "info",
                                            "devices", "bench", "compare",  "samples"};

using test::lines_of;

// A help text read back: its section headings in order, the section each flag is listed
// in, and the example command lines.
struct Help {
    std::vector<std::string> sections;
    std::map<std::string, std::string> section_of; // "--spp" -> "Image and sampling"
    std::vector<std::string> examples;             // "pathcl render ..."

    explicit Help(const std::string& text)
    {
        for (const std::string& line : lines_of(text)) {
            if (!line.empty() && line[0] != ' ' && line.back() == ':') {
                sections.push_back(line.substr(0, line.size() - 1));
            } else if (!sections.empty() && sections.back() == "Examples" && line.rfind("  pathcl", 0) == 0) {
                examples.push_back(line.substr(2));
            } else if (!sections.empty() && line.rfind("  -", 0) == 0) {
                // "  -o,--output FILE ...": each name before the first space
                std::string names = line.substr(2, line.find(' ', 2) - 2);
                std::istringstream split(names);
                for (std::string name; std::getline(split, name, ',');)
                    section_of[name] = sections.back();
            }
        }
    }
};

class CliHelp : public test::ToolRun {
protected:
    // A failing run's contract: exit code 2, one line on stderr starting "pathcl: error: ",
    // which is returned.
    std::string one_line_error() const
    {
        const std::string err = text("stderr.txt");
        EXPECT_EQ(err.rfind("pathcl: error: ", 0), 0u) << err;
        EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << "not one line: " << err;
        return err;
    }
    Help help_of(const std::string& command) const
    {
        EXPECT_EQ(run(command + " --help"), 0) << text("stderr.txt");
        return Help(text("stdout.txt"));
    }
};

// Broken variant seen to fail: "A subcommand is required" and no help.
TEST_F(CliHelp, NoCommandPrintsTheHelpAndIsAUsageError)
{
    EXPECT_EQ(run(""), 2);
    const std::string err = one_line_error();
    EXPECT_NE(err.find("no command"), std::string::npos) << err;
    const std::string out = text("stdout.txt");
    EXPECT_NE(out.find("Usage: pathcl"), std::string::npos) << out;
    const Help help(out);
    EXPECT_EQ(help.section_of.at("--version"), "Options");
    for (const std::string& command : kCommands)
        EXPECT_NE(out.find("\n  " + command + " "), std::string::npos) << command << " is not listed:\n" << out;
    EXPECT_FALSE(help.examples.empty()) << out;
}

// Broken variant seen to fail: --version was an unknown flag.
TEST_F(CliHelp, VersionNamesTheVersionTheCommitAndThePlatforms)
{
    ASSERT_EQ(run("--version"), 0) << text("stderr.txt");
    const std::vector<std::string> lines = lines_of(text("stdout.txt"));
    ASSERT_GE(lines.size(), 2u);
    EXPECT_EQ(lines[0], "pathcl " PATHCL_PROJECT_VERSION " (commit " PATHCL_PROJECT_COMMIT ")");
    const std::string commit = PATHCL_PROJECT_COMMIT;
    EXPECT_TRUE(
        commit == "unknown" ||
        (commit.size() == 12 && std::all_of(commit.begin(), commit.end(),
                                            [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); })))
        << commit;
    // One line per platform: each platform `pathcl devices` names is listed.
    ASSERT_EQ(lines[1], "OpenCL platforms:") << text("stdout.txt");
    const std::string version = text("stdout.txt");
    ASSERT_EQ(run("devices"), 0) << text("stderr.txt");
    for (const std::string& device : lines_of(text("stdout.txt"))) {
        const std::size_t from = device.find(": ") + 2;
        const std::string platform = device.substr(from, device.find(" | ") - from);
        EXPECT_NE(version.find("\n  " + platform + " | "), std::string::npos) << platform << " not in\n" << version;
    }
}

// No platform is not an error. Broken variant seen to fail: --version was an unknown flag.
TEST_F(CliHelp, VersionWithoutAnyOpenClPlatformSaysSo)
{
    ASSERT_EQ(run("--version", "OCL_ICD_VENDORS=/nonexistent-pathcl-test OCL_ICD_FILENAMES="), 0) << text("stderr.txt");
    const std::vector<std::string> lines = lines_of(text("stdout.txt"));
    ASSERT_EQ(lines.size(), 2u) << text("stdout.txt");
    EXPECT_EQ(lines[1].rfind("OpenCL platforms: none found", 0), 0u) << lines[1];
}

// Broken variant seen to fail: one "Options" list of every flag.
TEST_F(CliHelp, RenderHelpListsItsOptionsInGroups)
{
    const Help help = help_of("render");
    const std::vector<std::string> groups = {
        "Output",  "Image and sampling",    "Budgets and progress", "Camera",  "Environment", "Scene",
        "Devices", "Distributed rendering", "Checkpoints",          "Kernels", "Diagnostics", "Options",
        "Examples"};
    std::vector<std::string> listed = help.sections;
    listed.erase(listed.begin(), std::find(listed.begin(), listed.end(), "Output")); // the usage, the scene
    EXPECT_EQ(listed, groups);
    const std::map<std::string, std::string> expected = {
        {"--output", "Output"},
        {"--tone", "Output"},
        {"--spp", "Image and sampling"},
        {"--strategy", "Image and sampling"},
        {"--light-sampler", "Image and sampling"},
        {"--seed", "Image and sampling"},
        {"--time", "Budgets and progress"},
        {"--target-error", "Budgets and progress"},
        {"--look-at", "Camera"},
        {"--env", "Environment"},
        {"--background", "Environment"},
        {"--variant", "Scene"},
        {"--device", "Devices"},
        {"--device-shares", "Devices"},
        {"--sample-range", "Distributed rendering"},
        {"--resume", "Checkpoints"},
        {"--integrator", "Kernels"},
        {"--ray-log", "Diagnostics"},
    };
    for (const auto& [flag, group] : expected)
        EXPECT_EQ(help.section_of.count(flag) ? help.section_of.at(flag) : "(absent)", group) << flag;
    // Every option is in a group but the help flag.
    for (const auto& [flag, group] : help.section_of) {
        if (flag != "-h" && flag != "--help") {
            EXPECT_NE(group, "Options") << flag << " is in no group";
        }
    }
}

// Broken variant seen to fail: "ENUM:value in {bsdf->0,mis->3,nee->1,one-sample->2} OR {0,3,1,2}".
TEST_F(CliHelp, EnumValuesAreShownByName)
{
    for (const std::string command : {"render", "bench", "converge", "info", "samples"}) {
        EXPECT_EQ(run(command + " --help"), 0);
        const std::string out = text("stdout.txt");
        EXPECT_EQ(out.find("->"), std::string::npos) << command << ":\n" << out;
        EXPECT_EQ(out.find("ENUM"), std::string::npos) << command << ":\n" << out;
    }
    EXPECT_EQ(run("render --help"), 0);
    const std::string out = text("stdout.txt");
    for (const char* shown :
         {"--strategy NAME:{bsdf,nee,one-sample,mis}=mis", "--light-sampler NAME:{auto,power,tree,uniform}=auto",
          "--sampler NAME:{independent,jittered,multi-jittered,n-rooks,sobol,halton,hammersley}=sobol",
          "--tone NAME:{clip,filmic}=clip", "--integrator NAME:{megakernel,wavefront}=megakernel",
          "--specialization NAME:{scene,all}=scene"})
        EXPECT_NE(out.find(shown), std::string::npos) << shown << " not in:\n" << out;
}

// A value is taken by its name in any case, and only by its name. Broken variant seen to
// fail: "Check mys value in {bsdf->0,...} OR {0,3,1,2} FAILED", and "--strategy 3" taken
// as mis.
TEST_F(CliHelp, AMisspeltValueGetsTheNamesAndTheNearest)
{
    EXPECT_EQ(run("render " + kCornell + " -o out.exr --strategy mys" + kTiny), 2);
    EXPECT_EQ(one_line_error(),
              "pathcl: error: --strategy: \"mys\" is not bsdf, nee, one-sample or mis; did you mean mis?\n");
    EXPECT_EQ(run("render " + kCornell + " -o out.exr --strategy 3" + kTiny), 2);
    EXPECT_EQ(one_line_error(), "pathcl: error: --strategy: \"3\" is not bsdf, nee, one-sample or mis\n");
    EXPECT_EQ(run("render " + kCornell + " -o out.exr --tone aces" + kTiny), 2);
    EXPECT_EQ(one_line_error(), "pathcl: error: --tone: \"aces\" is not clip or filmic\n");
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out.exr"));
}

// Broken variant seen to fail: no "Examples" section.
TEST_F(CliHelp, EveryHelpEndsWithExamplesThatNameRealFlagsAndScenes)
{
    std::map<std::string, Help> helps = {{"", help_of("")}}; // "": pathcl --help
    for (const std::string& command : kCommands)
        helps.emplace(command, help_of(command));
    for (const auto& [command, help] : helps) {
        ASSERT_FALSE(help.sections.empty()) << command;
        EXPECT_EQ(help.sections.back(), "Examples") << command;
        EXPECT_FALSE(help.examples.empty()) << command;
        for (const std::string& example : help.examples) {
            std::istringstream words(example);
            std::string word, named;
            words >> word >> named; // "pathcl", the command
            if (!command.empty()) {
                EXPECT_TRUE(named == command || command == "devices") << "in " << command << "'s help: " << example;
            }
            const Help& of_named = named.rfind("-", 0) == 0 ? help : helps.at(named);
            while (words >> word) {
                if (word.rfind("-", 0) == 0 && !std::isdigit(static_cast<unsigned char>(word[1]))) {
                    EXPECT_TRUE(of_named.section_of.count(word))
                        << word << " is no flag of " << named << ": " << example;
                }
                if (word.rfind("scenes/", 0) == 0) {
                    EXPECT_TRUE(std::filesystem::exists(std::string(PATHCL_SOURCE_DIR) + "/" + word)) << example;
                }
            }
        }
    }
}

// Broken variant seen to fail: "The following arguments were not expected: 4 --sp".
TEST_F(CliHelp, AMisspeltFlagGetsTheNearestFlags)
{
    const std::string render = "render " + kCornell + " -o out.exr" + kTiny + " ";
    const std::map<std::string, std::string> typed = {
        {"--sp 4", "--sp: render has no such flag; did you mean --spp?"},
        {"--widht 8", "--widht: render has no such flag; did you mean --width?"},
        {"--look_at=0,0,0", "--look_at: render has no such flag; did you mean --look-at?"},
        {"--SEED 3", "--SEED: render has no such flag; did you mean --seed?"},
        {"--check x.ckpt", "--check: render has no such flag; did you mean --checkpoint or --checkpoint-every?"},
        {"--frobnicate", "--frobnicate: render has no such flag ('pathcl render --help' lists them)"},
    };
    for (const auto& [args, message] : typed) {
        EXPECT_EQ(run(render + args), 2) << args;
        EXPECT_EQ(one_line_error(), "pathcl: error: " + message + "\n");
    }
    // Reported before the missing required flag, which may be the misspelt one.
    EXPECT_EQ(run("render " + kCornell + kTiny + " --outptu out.exr"), 2);
    EXPECT_EQ(one_line_error(), "pathcl: error: --outptu: render has no such flag; did you mean --output?\n");
    EXPECT_EQ(run("render --sp 4 " + kCornell), 2);
    EXPECT_EQ(one_line_error(), "pathcl: error: --sp: render has no such flag; did you mean --spp?\n");
    EXPECT_EQ(run("render " + kCornell), 2);
    EXPECT_EQ(one_line_error(), "pathcl: error: --output is required\n");
    EXPECT_EQ(run("bench " + kCornell + " --run 3" + kTiny), 2);
    EXPECT_EQ(one_line_error(), "pathcl: error: --run: bench has no such flag; did you mean --runs?\n");
    EXPECT_EQ(run("--verison"), 2);
    EXPECT_EQ(one_line_error(), "pathcl: error: --verison: pathcl has no such flag; did you mean --version?\n");
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out.exr"));
}

// Broken variant seen to fail: "A subcommand is required".
TEST_F(CliHelp, AMisspeltCommandGetsTheNearestCommand)
{
    EXPECT_EQ(run("rendr " + kCornell + " -o out.exr" + kTiny), 2);
    EXPECT_EQ(one_line_error(), "pathcl: error: \"rendr\": no such command; did you mean render?\n");
    EXPECT_EQ(run("convrege"), 2);
    EXPECT_EQ(one_line_error(), "pathcl: error: \"convrege\": no such command; did you mean converge?\n");
    EXPECT_EQ(run("frobnicate"), 2);
    EXPECT_EQ(one_line_error(), "pathcl: error: \"frobnicate\": no such command (render, merge, converge, info, "
                                "devices, bench, compare or samples)\n");
    EXPECT_EQ(run("render " + kCornell + " second.gltf -o out.exr" + kTiny), 2);
    EXPECT_EQ(one_line_error(), "pathcl: error: render: unexpected argument \"second.gltf\"\n");
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out.exr"));
}

} // namespace
} // namespace pathcl::test_cli_help
