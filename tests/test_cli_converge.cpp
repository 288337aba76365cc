// `pathcl converge` through the binary: the command writes a CSV with every row, both
// plots and the summary, caches its reference (and renders it again when the options
// change), and an interrupted study keeps the rows it finished.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <thread>

#include <spawn.h>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "support/tool_run.h"

extern char** environ;

namespace pathcl::test_cli_converge {
namespace {

const std::string kSource = PATHCL_SOURCE_DIR;
const std::string kCornell = "'" + kSource + "/scenes/cornell-box.gltf'";

using test::lines_of;
using test::ToolRun;

TEST_F(ToolRun, ConvergeWritesEveryRowItsPlotsAndSummary)
{
    const std::string study = "converge " + kCornell +
                              " -o study --vary strategy=nee,mis --vary max-bounces=3 --width 16 --height 16 "
                              "--spp-ladder 1,4 --seeds 2 --reference-spp 256";
    ASSERT_EQ(run(study), 0) << text("stderr.txt");
    EXPECT_NE(text("stderr.txt").find("reference: 256 spp"), std::string::npos) << text("stderr.txt");
    std::vector<std::string> csv = lines_of(text("study/convergence.csv"));
    ASSERT_EQ(csv.size(), 1u + 2u * 2u * 2u); // header, 2 settings x 2 spp x 2 seeds
    EXPECT_EQ(csv[0].rfind("setting,strategy,max-bounces,spp,spp_taken,seed,render_seconds,", 0), 0u) << csv[0];
    for (std::size_t i = 1; i < csv.size(); ++i)
        EXPECT_EQ(std::count(csv[i].begin(), csv[i].end(), ','), std::count(csv[0].begin(), csv[0].end(), ','))
            << csv[i];
    EXPECT_EQ(csv.back().rfind("1,mis,3,4,4,1,", 0), 0u) << csv.back();
    std::string md = text("study/summary.md");
    for (const char* label : {"strategy=nee, max-bounces=3", "strategy=mis, max-bounces=3", "slope vs spp"})
        EXPECT_NE(md.find(label), std::string::npos) << label;
    for (const char* png : {"study/error_vs_time.png", "study/error_vs_spp.png"}) {
        EXPECT_GT(read_image((dir_ / png).string()).width, 500u) << png;
    }
    // Again: the cached reference serves; with another seed it is rendered again.
    ASSERT_EQ(run(study), 0) << text("stderr.txt");
    EXPECT_EQ(text("stderr.txt").find("reference:"), std::string::npos) << text("stderr.txt");
    ASSERT_EQ(run(study + " --seed 9"), 0) << text("stderr.txt");
    EXPECT_NE(text("stderr.txt").find("reference: 256 spp"), std::string::npos) << text("stderr.txt");
}

TEST_F(ToolRun, InterruptedConvergeKeepsItsRows)
{
    // The reference first (cached), then a study far too long to finish, stopped by SIGINT.
    const std::string common = " -o study --vary sampler=independent,sobol --width 32 --height 32 --seeds 3 "
                               "--reference-spp 64 --quiet";
    ASSERT_EQ(run("converge " + kCornell + common + " --spp-ladder 1"), 0) << text("stderr.txt");
    std::filesystem::remove(dir_ / "study" / "convergence.csv"); // the rows to wait for are the next run's
    std::string binary = PATHCL_BINARY;
    std::string cmd = "cd '" + dir_.string() + "' && exec '" + binary + "' converge " + kCornell + common +
                      " --spp-ladder 1,2,4,8,16,32,64,128,256,512,1024,2048,4096,8192,16384 >stdout.txt "
                      "2>stderr.txt";
    const char* argv[] = {"/bin/sh", "-c", cmd.c_str(), nullptr};
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ), 0);
    // Interrupted once its first row is written (a fixed 3 s delay failed on a loaded
    // machine), well before it can finish. The rows go to the CSV's staged copy
    // (.convergence.csv.tmp*, flushed row by row) until the study commits them.
    auto rows_started = [&] {
        std::error_code ec;
        for (const auto& e : std::filesystem::directory_iterator(dir_ / "study", ec))
            if (e.path().filename().string().rfind(".convergence.csv.tmp", 0) == 0 &&
                lines_of(text("study/" + e.path().filename().string())).size() >= 2)
                return true;
        return false;
    };
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!rows_started() && std::chrono::steady_clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    kill(pid, SIGINT);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130) << text("stderr.txt");
    std::vector<std::string> csv = lines_of(text("study/convergence.csv"));
    std::cout << csv.size() - 1 << " rows kept\n";
    EXPECT_GT(csv.size(), 1u);
    EXPECT_LT(csv.size(), 1u + 2u * 15u * 3u);
    EXPECT_NE(text("study/summary.md").find("Interrupted"), std::string::npos);
}

} // namespace
} // namespace pathcl::test_cli_converge
