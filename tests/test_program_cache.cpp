// The on-disk program binary cache: what it stores it loads back, and an entry that is not
// exactly what this key stored (truncated, corrupted, another key's, an older format) is a
// miss, never a binary for the driver. A store that fails leaves no file behind.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include <csignal>
#include <sys/resource.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "cl/program_cache.h"
#include "support/scoped_env.h"

namespace pathcl::test_program_cache {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;

Bytes pseudo_random_bytes(std::size_t n, std::uint32_t seed)
{
    Bytes b(n);
    for (auto& c : b) {
        seed = seed * 1664525u + 1013904223u;
        c = static_cast<unsigned char>(seed >> 24);
    }
    return b;
}

Bytes read_bytes(const fs::path& p)
{
    std::ifstream f(p, std::ios::binary);
    return Bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

void write_bytes(const fs::path& p, const Bytes& b)
{
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

// Each test gets a fresh, empty $PATHCL_CACHE_DIR; the previous value comes back after.
class ProgramCache : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        root_ = fs::temp_directory_path() / ("pathcl-cache-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(root_);
        dir_ = root_ / "cache";
        fs::create_directories(dir_);
        cache_env_.emplace("PATHCL_CACHE_DIR", dir_.string());
    }

    void TearDown() override
    {
        cache_env_.reset();
        std::error_code ec;
        fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(root_, ec);
    }

    void set_cache_dir(const fs::path& d) { cache_env_->set(d.string()); }

    fs::path entry(const std::string& key) const { return dir_ / (key + ".bin"); }

    // Names in the cache directory, sorted: shows any temporary file left behind.
    std::vector<std::string> listing() const
    {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir_))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

    const std::string key_a_ = program_cache_key("device A", "-cl-std=CL1.2", "kernel source A");
    const std::string key_b_ = program_cache_key("device A", "-cl-std=CL1.2", "kernel source B");
    const Bytes binary_a_ = pseudo_random_bytes(4096, 1);
    const Bytes binary_b_ = pseudo_random_bytes(4096, 2);
    fs::path root_, dir_;
    std::optional<test::ScopedEnv> cache_env_;
};

TEST_F(ProgramCache, StoreThenLoadRoundTrips)
{
    EXPECT_EQ(program_cache_load(key_a_), std::nullopt) << "empty cache";
    program_cache_store(key_a_, binary_a_);
    program_cache_store(key_b_, binary_b_);
    EXPECT_EQ(program_cache_load(key_a_), binary_a_);
    EXPECT_EQ(program_cache_load(key_b_), binary_b_);
    std::vector<std::string> entries{key_a_ + ".bin", key_b_ + ".bin"};
    std::sort(entries.begin(), entries.end());
    EXPECT_EQ(listing(), entries) << "no temporary files";

    program_cache_store(key_a_, binary_b_); // a later store replaces the entry
    EXPECT_EQ(program_cache_load(key_a_), binary_b_);
    const Bytes one{42};
    program_cache_store(key_a_, one);
    EXPECT_EQ(program_cache_load(key_a_), one);
}

TEST_F(ProgramCache, TruncatedEntryIsAMissAndTheNextStoreRepairsIt)
{
    program_cache_store(key_a_, binary_a_);
    const Bytes whole = read_bytes(entry(key_a_));
    ASSERT_GT(whole.size(), binary_a_.size());
    for (std::size_t size :
         {whole.size() / 2, whole.size() - 1, whole.size() - binary_a_.size(), std::size_t(1), std::size_t(0)}) {
        fs::resize_file(entry(key_a_), size);
        EXPECT_EQ(program_cache_load(key_a_), std::nullopt) << "truncated to " << size << " of " << whole.size();
    }
    program_cache_store(key_a_, binary_a_);
    EXPECT_EQ(program_cache_load(key_a_), binary_a_);
}

TEST_F(ProgramCache, FlippedBytesAreAMiss)
{
    program_cache_store(key_a_, binary_a_);
    const Bytes whole = read_bytes(entry(key_a_));
    const std::size_t header = whole.size() - binary_a_.size();

    Bytes bad = whole; // a few bytes in the middle of the body
    for (std::size_t i = header + 1000; i < header + 1004; ++i)
        bad[i] ^= 0x5a;
    write_bytes(entry(key_a_), bad);
    EXPECT_EQ(program_cache_load(key_a_), std::nullopt);

    bad = whole; // a valid header with a random body (a crash in the driver)
    const Bytes noise = pseudo_random_bytes(binary_a_.size(), 7);
    std::copy(noise.begin(), noise.end(), bad.begin() + static_cast<std::ptrdiff_t>(header));
    write_bytes(entry(key_a_), bad);
    EXPECT_EQ(program_cache_load(key_a_), std::nullopt);

    bad = whole; // one extra byte
    bad.push_back(0);
    write_bytes(entry(key_a_), bad);
    EXPECT_EQ(program_cache_load(key_a_), std::nullopt);

    // Any single changed byte, header or body: magic, version, key, lengths, checksum.
    const Bytes small = pseudo_random_bytes(64, 3);
    program_cache_store(key_a_, small);
    const Bytes small_whole = read_bytes(entry(key_a_));
    for (std::size_t i = 0; i < small_whole.size(); ++i) {
        bad = small_whole;
        bad[i] ^= 0x01;
        write_bytes(entry(key_a_), bad);
        EXPECT_EQ(program_cache_load(key_a_), std::nullopt) << "byte " << i << " of " << small_whole.size();
    }
    write_bytes(entry(key_a_), small_whole);
    EXPECT_EQ(program_cache_load(key_a_), small) << "the unchanged entry still loads";
}

TEST_F(ProgramCache, EntryUnderAnotherKeysNameIsAMiss)
{
    program_cache_store(key_a_, binary_a_);
    program_cache_store(key_b_, binary_b_);
    fs::copy_file(entry(key_a_), entry(key_b_), fs::copy_options::overwrite_existing);
    EXPECT_EQ(program_cache_load(key_b_), std::nullopt);
    EXPECT_EQ(program_cache_load(key_a_), binary_a_);
}

TEST_F(ProgramCache, OldFormatRawBinaryIsAMiss)
{
    // What earlier versions stored: the driver's binary alone.
    Bytes raw = binary_a_;
    const char elf[] = "\x7f"
                       "ELF";
    std::copy(elf, elf + 4, raw.begin());
    write_bytes(entry(key_a_), raw);
    EXPECT_EQ(program_cache_load(key_a_), std::nullopt);
    write_bytes(entry(key_a_), Bytes{});
    EXPECT_EQ(program_cache_load(key_a_), std::nullopt) << "empty file";
}

TEST_F(ProgramCache, StoreIntoUnwritableDirLeavesNoFiles)
{
    fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
    if (std::ofstream(dir_ / "probe")) { // root ignores permissions
        fs::remove(dir_ / "probe");
        GTEST_SKIP() << "permissions are not enforced for this user";
    }
    program_cache_store(key_a_, binary_a_);
    fs::permissions(dir_, fs::perms::owner_all);
    EXPECT_TRUE(listing().empty());
    EXPECT_EQ(program_cache_load(key_a_), std::nullopt);
}

TEST_F(ProgramCache, StoreUnderAFileLeavesNoFiles)
{
    // The cache directory cannot be created: its parent is a regular file.
    write_bytes(dir_ / "file", Bytes{1});
    set_cache_dir(dir_ / "file" / "cache");
    program_cache_store(key_a_, binary_a_);
    EXPECT_EQ(program_cache_load(key_a_), std::nullopt);
    EXPECT_EQ(listing(), std::vector<std::string>{"file"});
}

TEST_F(ProgramCache, FailedRenameLeavesNoTemporaryFile)
{
    // The entry's name is taken by a non-empty directory, so the final rename fails after
    // the temporary file was written in full.
    fs::create_directories(entry(key_a_) / "x");
    program_cache_store(key_a_, binary_a_);
    EXPECT_EQ(listing(), std::vector<std::string>{key_a_ + ".bin"});
    EXPECT_TRUE(fs::is_directory(entry(key_a_) / "x"));
    EXPECT_EQ(program_cache_load(key_a_), std::nullopt);
}

TEST_F(ProgramCache, FailedWriteLeavesNoPartialEntry)
{
    // A file size limit stands in for a full disk: the write stops part way.
    program_cache_store(key_a_, binary_a_);
    rlimit old{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
    rlimit small = old;
    small.rlim_cur = 1000;
    auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    program_cache_store(key_a_, binary_b_);
    program_cache_store(key_b_, binary_b_);
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, old_handler);

    EXPECT_EQ(listing(), std::vector<std::string>{key_a_ + ".bin"}) << "no partial entry, no temporary file";
    EXPECT_EQ(program_cache_load(key_a_), binary_a_) << "the earlier entry is untouched";
    EXPECT_EQ(program_cache_load(key_b_), std::nullopt);
}

} // namespace
} // namespace pathcl::test_program_cache
