// Checkpoints end to end through the binary: a render killed with SIGKILL between two
// checkpoints, or stopped by its time budget in the middle of a batch, and then resumed,
// ends with the image of the uninterrupted render bit for bit (every value of the EXR,
// variance included); a checkpoint of another render, or a damaged one, is a one-line
// error.
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "render/checkpoint.h"
#include "support/same_image.h"
#include "support/tool_run.h"

extern char** environ;

namespace pathcl::test_cli_resume {
namespace {

using test::expect_same_image;
using test::ToolRun;

const std::string kScene = std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box-glass-mirror.gltf";
const std::string kSmall = " --width 32 --height 32 --quiet";

// Guards the device films in the checkpoint: restarting the batch in progress from a
// cleared film gives another image (and a resumed render short of samples).
TEST_F(ToolRun, RenderKilledBetweenCheckpointsResumesToTheSameImage)
{
    const std::string options = " --spp 8192" + kSmall;
    ASSERT_EQ(run("render '" + kScene + "' -o full.exr" + options), 0) << text("stderr.txt");

    std::vector<std::string> args = {PATHCL_BINARY,
                                     "render",
                                     kScene,
                                     "-o",
                                     (dir_ / "killed.exr").string(),
                                     "--spp",
                                     "8192",
                                     "--width",
                                     "32",
                                     "--height",
                                     "32",
                                     "--quiet",
                                     "--checkpoint",
                                     (dir_ / "cp.bin").string(),
                                     "--checkpoint-every",
                                     "0.2"};
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, PATHCL_BINARY, nullptr, nullptr, argv.data(), environ), 0);
    for (int i = 0; i < 200 && !std::filesystem::exists(dir_ / "cp.bin"); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::this_thread::sleep_for(std::chrono::milliseconds(300)); // between two checkpoints
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the render ended before it was killed: make it longer";
    ASSERT_TRUE(std::filesystem::exists(dir_ / "cp.bin"));
    EXPECT_FALSE(std::filesystem::exists(dir_ / "killed.exr"));

    ASSERT_EQ(run("render '" + kScene + "' -o resumed.exr --resume cp.bin" + options), 0) << text("stderr.txt");
    expect_same_image(read_image((dir_ / "full.exr").string()), read_image((dir_ / "resumed.exr").string()));
}

// Guards the accumulator state in the checkpoint: a render of several batches stopped in
// the middle of one resumes with the whole batches' sums and spread as they were.
TEST_F(ToolRun, RenderStoppedByItsTimeBudgetResumesToTheSameImage)
{
    const std::string options = " --max-spp 512 --batch-spp 16" + kSmall;
    ASSERT_EQ(run("render '" + kScene + "' -o full.exr --time 600" + options), 0) << text("stderr.txt");
    ASSERT_EQ(run("render '" + kScene + "' -o part.exr --time 0.1 --checkpoint cp.bin" + options), 0)
        << text("stderr.txt");
    Image part = read_image((dir_ / "part.exr").string());
    ASSERT_LT(part.spp, 512u) << "the budget did not stop the render: make it shorter";
    ASSERT_EQ(run("render '" + kScene + "' -o resumed.exr --time 600 --resume cp.bin" + options), 0)
        << text("stderr.txt");
    Image full = read_image((dir_ / "full.exr").string()), resumed = read_image((dir_ / "resumed.exr").string());
    expect_same_image(full, resumed);
    EXPECT_EQ(full.metadata["relmse_estimate"], resumed.metadata["relmse_estimate"]);
}

TEST_F(ToolRun, CheckpointOfAnotherRenderOrDamagedIsAOneLineError)
{
    const std::string options = " --max-spp 256 --batch-spp 16" + kSmall;
    ASSERT_EQ(run("render '" + kScene + "' -o part.exr --time 0.05 --checkpoint cp.bin" + options), 0)
        << text("stderr.txt");
    EXPECT_EQ(run("render '" + kScene + "' -o x.exr --time 600 --seed 7 --resume cp.bin" + options), 2);
    std::string err = text("stderr.txt");
    EXPECT_EQ(err.rfind("pathcl: error: cp.bin: --resume: the checkpoint is of another render: its \"seed 0\", this "
                        "render's \"seed 7\"",
                        0),
              0u)
        << err;
    EXPECT_EQ(err.find('\n'), err.size() - 1) << err;

    std::filesystem::resize_file(dir_ / "cp.bin", std::filesystem::file_size(dir_ / "cp.bin") / 2);
    EXPECT_EQ(run("render '" + kScene + "' -o x.exr --time 600 --resume cp.bin" + options), 2);
    err = text("stderr.txt");
    EXPECT_NE(err.find("cp.bin: checkpoint is truncated or corrupt"), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "x.exr"));
}

// A checkpoint rewritten by hand (the writer recomputes its checksum): counters past the
// render, counters that wrap, a film of another size or holding NaN, a key of 500,000
// line breaks, a file of 3 GB. Each is one short error line naming the file and --resume,
// and nothing is written. Broken variant seen to fail: the batch past the end resumed
// into an image of the samples done so far labelled complete (exit 0), the wrapped counter
// too, the NaN film into NaN pixels, the key into a 500,001-line error, and the 3 GB
// file was read whole before it was refused.
TEST_F(ToolRun, AHandMadeCheckpointIsAOneLineErrorNamingIt)
{
    const std::string options = " --max-spp 256 --batch-spp 16" + kSmall;
    ASSERT_EQ(run("render '" + kScene + "' -o part.exr --time 0.05 --checkpoint cp.bin" + options), 0)
        << text("stderr.txt");
    const RenderCheckpoint good = read_checkpoint((dir_ / "cp.bin").string(), 32 * 32);
    struct Case {
        const char* what;
        void (*spoil)(RenderCheckpoint&);
        const char* says;
    };
    const Case cases[] = {
        {"batch past the end",
         [](RenderCheckpoint& c) {
             c.batch = 16;
             c.pass = 0;
         },
         "the checkpoint is at pass 0 of batch 16, which this render does not have"},
        {"spp counter wrapped", [](RenderCheckpoint& c) { c.spp_done += 0xfffffff0u; }, "samples per pixel done"},
        {"film of another size", [](RenderCheckpoint& c) { c.device_films[0].resize(10); },
         "does not hold one film of this render's 1024 pixels"},
        {"NaN in the film", [](RenderCheckpoint& c) { c.film.samples[5] = NAN; }, "pixel 5 of its film"},
        {"a key of line breaks", [](RenderCheckpoint& c) { c.key = std::string(50000, '\n'); },
         "the checkpoint is of another render"},
    };
    for (const Case& c : cases) {
        RenderCheckpoint cp = good;
        c.spoil(cp);
        write_checkpoint((dir_ / "hand.bin").string(), cp);
        EXPECT_EQ(run("render '" + kScene + "' -o x.exr --time 600 --resume hand.bin" + options), 2) << c.what;
        const std::string err = text("stderr.txt");
        EXPECT_EQ(err.rfind("pathcl: error: hand.bin: --resume: ", 0), 0u) << c.what << ": " << err.substr(0, 300);
        EXPECT_NE(err.find(c.says), std::string::npos) << c.what << ": " << err.substr(0, 300);
        EXPECT_EQ(err.find('\n'), err.size() - 1) << c.what << ": not one line";
        EXPECT_LT(err.size(), 600u) << c.what;
        EXPECT_FALSE(std::filesystem::exists(dir_ / "x.exr")) << c.what;
    }
    // A key longer than any render's (500,000 line breaks) is refused from the file's size.
    RenderCheckpoint cp = good;
    cp.key = std::string(500000, '\n');
    write_checkpoint((dir_ / "hand.bin").string(), cp);
    EXPECT_EQ(run("render '" + kScene + "' -o x.exr --time 600 --resume hand.bin" + options), 2);
    EXPECT_EQ(text("stderr.txt").rfind("pathcl: error: hand.bin: is ", 0), 0u) << text("stderr.txt").substr(0, 300);
    std::ofstream(dir_ / "huge.bin").close();
    std::filesystem::resize_file(dir_ / "huge.bin", std::uintmax_t(3) << 30); // sparse
    EXPECT_EQ(run("render '" + kScene + "' -o x.exr --time 600 --resume huge.bin" + options), 2);
    const std::string err = text("stderr.txt");
    EXPECT_NE(err.find("huge.bin: is 3221225472 bytes, more than the limit of "), std::string::npos) << err;
}

} // namespace
} // namespace pathcl::test_cli_resume
