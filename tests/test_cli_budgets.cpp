// The budget, progress and interrupt flags of `pathcl render`, and `pathcl info`, end to
// end through the binary: a time budget reports its stop and error estimate on the
// summary line and in the EXR's metadata; --spp with a budget and --adaptive without a
// target are one-line errors naming the flags; SIGINT and SIGTERM keep the samples taken
// (a valid image saying it was interrupted, exit 130 / 143); `info` names the scene's
// features and the program's cache key.
#include <chrono>
#include <csignal>
#include <string>
#include <thread>

#include <spawn.h>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "support/tool_run.h"

extern char** environ;

namespace pathcl::test_cli_budgets {
namespace {

using test::ToolRun;

const std::string kCornell = "'" + std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box.gltf'";

TEST_F(ToolRun, TimeBudgetReportsItsStopAndErrorEstimate)
{
    ASSERT_EQ(run("render " + kCornell + " -o img.exr --width 32 --height 32 --time 0.5 --progress"), 0)
        << text("stderr.txt");
    std::string out = text("stdout.txt");
    EXPECT_NE(out.find("stopped: time"), std::string::npos) << out;
    EXPECT_NE(out.find("relMSE est."), std::string::npos) << out;
    EXPECT_NE(text("stderr.txt").find("pass "), std::string::npos) << "no progress line with --progress";
    Image img = read_image((dir_ / "img.exr").string());
    EXPECT_EQ(img.metadata["stop"], "time");
    EXPECT_EQ(img.metadata["relmse_estimate_method"], "batch means");
    EXPECT_GT(std::stod(img.metadata["relmse_estimate"]), 0.0);
    EXPECT_GT(img.spp, 32u);
}

TEST_F(ToolRun, QuietRenderPrintsNoProgress)
{
    ASSERT_EQ(run("render " + kCornell + " -o img.exr --width 8 --height 8 --spp 4 --quiet"), 0);
    EXPECT_EQ(text("stderr.txt"), "");
}

TEST_F(ToolRun, BudgetFlagMisuseIsAOneLineError)
{
    EXPECT_EQ(run("render " + kCornell + " -o img.exr --width 8 --height 8 --spp 4 --time 1"), 2);
    std::string err = text("stderr.txt");
    EXPECT_NE(err.find("--max-spp"), std::string::npos) << err;
    EXPECT_EQ(run("render " + kCornell + " -o img.exr --width 8 --height 8 --spp 4 --adaptive"), 2);
    err = text("stderr.txt");
    EXPECT_NE(err.find("--adaptive: needs a target error"), std::string::npos) << err;
    EXPECT_NE(err.find("--target-error"), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "img.exr"));
}

// Starts a render that would take minutes, signals it once it is rendering, and returns
// its exit status.
int render_and_signal(const std::filesystem::path& dir, int sig)
{
    std::string binary = PATHCL_BINARY, scene = std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box.gltf",
                output = (dir / "img.exr").string();
    std::vector<std::string> args = {binary, "render",   scene, "-o",     output, "--width",
                                     "32",   "--height", "32",  "--time", "600",  "--quiet"};
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawn(&pid, binary.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
        return -1;
    std::this_thread::sleep_for(std::chrono::seconds(2)); // loaded, built (cached) and rendering
    kill(pid, sig);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_F(ToolRun, InterruptKeepsTheSamplesTaken)
{
    for (int sig : {SIGINT, SIGTERM}) {
        std::filesystem::remove(dir_ / "img.exr");
        EXPECT_EQ(render_and_signal(dir_, sig), 128 + sig);
        Image img = read_image((dir_ / "img.exr").string());
        EXPECT_EQ(img.metadata["stop"], "interrupted");
        EXPECT_GT(img.spp, 0u);
    }
}

TEST_F(ToolRun, InfoNamesFeaturesAndCacheKey)
{
    ASSERT_EQ(run("info '" + std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box-glass-mirror.gltf'"), 0)
        << text("stderr.txt");
    std::string out = text("stdout.txt");
    for (const char* part : {"triangles", "transmission", "features     area-lights, glossy, transmission",
                             "compiled cold in", "cache key "})
        EXPECT_NE(out.find(part), std::string::npos) << part << " missing in:\n" << out;
}

} // namespace
} // namespace pathcl::test_cli_budgets
