// What a render may write, through the binary: outputs (-o, --checkpoint, --ray-log)
// replace only regular files, never a FIFO or a device; no output is the same file as an
// input (the scene's files, the environment map, the checkpoint resumed) or as another
// output, however the paths are spelled; an output that cannot be written is found
// before the render; and the temporary file a killed write leaves is removed by the next
// write of the same output, while one a living process holds is not.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "support/tool_run.h"

namespace pathcl::test_cli_output_files {
namespace {

namespace fs = std::filesystem;
using test::ToolRun;

const std::string kScene = "'" + std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box.gltf'";
const std::string kTiny = " --width 4 --height 4 --quiet";

class OutputFiles : public ToolRun {
protected:
    // The contract of a refusal: exit 2, one line naming `name`.
    void expect_refused(int status, const std::string& name) const
    {
        const std::string err = text("stderr.txt");
        EXPECT_EQ(status, 2) << err;
        EXPECT_EQ(err.rfind("pathcl: error: ", 0), 0u) << err;
        EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
        EXPECT_NE(err.find(name), std::string::npos) << "does not name " << name << ": " << err;
    }
    bool is_fifo(const std::string& name) const
    {
        struct stat st {};
        return ::lstat((dir_ / name).c_str(), &st) == 0 && S_ISFIFO(st.st_mode);
    }
};

// A FIFO named as the checkpoint, the image or the ray log stays what it is (and so would
// a device: --checkpoint /dev/null run as root replaced the system's /dev/null). Broken variant seen to fail: the FIFO
// was replaced by a regular file.
TEST_F(OutputFiles, AnOutputNeverReplacesAFifoOrADevice)
{
    ASSERT_EQ(::mkfifo((dir_ / "pipe.bin").c_str(), 0644), 0);
    ASSERT_EQ(::mkfifo((dir_ / "pipe.exr").c_str(), 0644), 0);
    expect_refused(run("render " + kScene + " -o out.exr --checkpoint pipe.bin --time 0.5 --max-spp 4" + kTiny),
                   "pipe.bin");
    EXPECT_TRUE(is_fifo("pipe.bin"));
    expect_refused(run("render " + kScene + " -o pipe.exr --spp 1" + kTiny), "pipe.exr");
    EXPECT_TRUE(is_fifo("pipe.exr"));
    ASSERT_EQ(::mkfifo((dir_ / "pipe.ply").c_str(), 0644), 0);
    expect_refused(run("render " + kScene + " -o out.exr --ray-log pipe.ply --spp 1" + kTiny), "pipe.ply");
    EXPECT_TRUE(is_fifo("pipe.ply"));
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
}

// Outputs and inputs compared as files, not as strings. Broken variant seen to fail: each
// of these rendered (the checkpoint was then replaced by the image, or the image by the
// checkpoint).
TEST_F(OutputFiles, NoOutputIsAnInputOrAnotherOutputHoweverSpelled)
{
    const std::string here = dir_.string();
    expect_refused(run("render " + kScene + " -o " + here + "/out.exr --checkpoint ./out.exr --spp 1" + kTiny),
                   "out.exr");
    expect_refused(run("render " + kScene + " -o out.exr --ray-log r.ply --checkpoint ./r.ply --spp 1" + kTiny),
                   "r.ply");
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));

    // A real checkpoint, then an image written over it and one over a hard link to it.
    ASSERT_EQ(run("render " + kScene + " -o first.exr --checkpoint cp.exr --time 0.3 --max-spp 1000000" + kTiny), 0)
        << text("stderr.txt");
    ASSERT_TRUE(fs::exists(dir_ / "cp.exr"));
    const std::string checkpoint = text("cp.exr");
    expect_refused(run("render " + kScene + " -o cp.exr --resume cp.exr --time 0.3 --max-spp 1000000" + kTiny),
                   "cp.exr");
    fs::create_hard_link(dir_ / "cp.exr", dir_ / "link.exr");
    expect_refused(run("render " + kScene + " -o link.exr --resume cp.exr --time 0.3 --max-spp 1000000" + kTiny),
                   "link.exr");
    EXPECT_EQ(text("cp.exr"), checkpoint);
    // The checkpoint a render resumes from is the one it goes on writing.
    EXPECT_EQ(run("render " + kScene +
                  " -o second.exr --resume cp.exr --checkpoint ./cp.exr --time 0.3 --max-spp 1000000" + kTiny),
              0)
        << text("stderr.txt");
}

// An output where nothing can be written is an error before the render starts, the
// checkpoint's too (it is first written only --checkpoint-every seconds in). /proc takes
// no new file, even from root. Broken variant seen to fail: the render ran and exited 0
// (its one checkpoint would have come a minute in).
TEST_F(OutputFiles, AnUnwritableCheckpointIsFoundBeforeTheRender)
{
    expect_refused(run("render " + kScene + " -o out.exr --checkpoint /proc/pathcl-cp.bin --spp 1" + kTiny),
                   "/proc/pathcl-cp.bin");
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
}

// A write killed outright (SIGKILL, a power cut) leaves its temporary file; the next
// render of the same output removes it, but not one that a living process holds locked.
// Broken variant seen to fail: the dead process's 0-byte file stayed for good.
TEST_F(OutputFiles, TheNextWriteRemovesTheTemporaryFileOfAKilledOne)
{
    const fs::path dead = dir_ / ".out.exr.tmp4242-0.exr", live = dir_ / ".out.exr.tmp4343-0.exr";
    for (const fs::path& p : {dead, live}) {
        std::FILE* f = std::fopen(p.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fclose(f);
        // As old as a temporary file of a write that died a minute ago.
        fs::last_write_time(p, fs::file_time_type::clock::now() - std::chrono::minutes(1));
    }
    const int held = ::open(live.c_str(), O_RDONLY | O_CLOEXEC);
    ASSERT_GE(held, 0);
    ASSERT_EQ(::flock(held, LOCK_EX), 0); // as the process writing it holds it
    ASSERT_EQ(run("render " + kScene + " -o out.exr --spp 1" + kTiny), 0) << text("stderr.txt");
    EXPECT_FALSE(fs::exists(dead)) << "the killed write's temporary file is still there";
    EXPECT_TRUE(fs::exists(live)) << "a living process's temporary file was removed";
    EXPECT_TRUE(fs::exists(dir_ / "out.exr"));
    ::close(held);
}

} // namespace
} // namespace pathcl::test_cli_output_files
