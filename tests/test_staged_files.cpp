// StagedFiles: outputs appear only when committed, and a signal handler can remove every
// staged temporary file at once (the second Ctrl-C during a write leaves nothing behind).
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>

#include "common/staged_files.h"

namespace pathcl::test_staged_files {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir()
{
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    fs::path d = fs::temp_directory_path() / ("pathcl-staged-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::size_t entries(const fs::path& d)
{
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(d), fs::directory_iterator()));
}

TEST(StagedFiles, CommitRenamesAndTheDestructorRemovesWhatWasNotCommitted)
{
    fs::path d = fresh_dir();
    {
        StagedFiles staged;
        std::ofstream(staged.stage((d / "a.png").string())) << "a";
        staged.commit();
    }
    EXPECT_TRUE(fs::exists(d / "a.png"));
    {
        StagedFiles staged;
        std::ofstream(staged.stage((d / "b.png").string())) << "b";
    }
    EXPECT_FALSE(fs::exists(d / "b.png"));
    EXPECT_EQ(entries(d), 1u);
    fs::remove_all(d);
}

// Guards the slots the handler reads: without claim_slot in stage() the file stays.
TEST(StagedFiles, RemoveOnSignalRemovesEveryStagedFileAndNothingCommitted)
{
    fs::path d = fresh_dir();
    StagedFiles done;
    std::ofstream(done.stage((d / "done.exr").string())) << "done";
    done.commit();
    StagedFiles staged;
    std::string t1 = staged.stage((d / "x.exr").string()), t2 = staged.stage((d / "y.png").string());
    std::ofstream(t1) << "x";
    std::ofstream(t2) << "y";
    ASSERT_EQ(entries(d), 3u);
    remove_staged_files_on_signal();
    EXPECT_FALSE(fs::exists(t1));
    EXPECT_FALSE(fs::exists(t2));
    EXPECT_TRUE(fs::exists(d / "done.exr"));
    fs::remove_all(d);
}

} // namespace
} // namespace pathcl::test_staged_files
