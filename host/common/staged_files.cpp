#include "common/staged_files.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <ctime>
#include <dirent.h>
#include <fcntl.h>
#include <filesystem>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/error.h"

namespace pathcl {

namespace fs = std::filesystem;

namespace {

// The staged names a signal handler may have to remove: fixed storage, so the handler
// reads it without allocating; a slot is published by setting its flag last.
constexpr int kSignalSlots = 16;
char g_slot_path[kSignalSlots][4096];
volatile std::sig_atomic_t g_slot_used[kSignalSlots];

int claim_slot(const std::string& path)
{
    if (path.size() >= sizeof g_slot_path[0])
        return -1;
    for (int i = 0; i < kSignalSlots; ++i)
        if (!g_slot_used[i]) {
            std::memcpy(g_slot_path[i], path.c_str(), path.size() + 1);
            g_slot_used[i] = 1;
            return i;
        }
    return -1;
}

void release_slot(const std::string& path)
{
    for (int i = 0; i < kSignalSlots; ++i)
        if (g_slot_used[i] && path == g_slot_path[i])
            g_slot_used[i] = 0;
}

// A temporary file beside `target`: ".NAME.tmpPID-TAIL", which no user file is likely to
// be named and remove_stale_temporaries recognises.
std::string temporary_name(const std::string& target, const std::string& tail)
{
    const fs::path t(target);
    return (t.parent_path() / ("." + t.filename().string() + ".tmp" + std::to_string(::getpid()) + "-" + tail))
        .string();
}

// Older than this and unlocked, a temporary file is a dead process's.
constexpr int kStaleSeconds = 5;

// Removes the temporaries of `target` that no living process holds: those a process
// killed outright left behind (its lock went with it).
void remove_stale_temporaries(const std::string& target)
{
    const fs::path t(target);
    const std::string prefix = "." + t.filename().string() + ".tmp";
    DIR* dir = ::opendir(t.parent_path().empty() ? "." : t.parent_path().c_str());
    if (dir == nullptr)
        return;
    const std::time_t now = std::time(nullptr);
    while (const dirent* e = ::readdir(dir)) {
        const std::string name = e->d_name;
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
            !std::isdigit(static_cast<unsigned char>(name[prefix.size()])))
            continue;
        const std::string path = (t.parent_path() / name).string();
        const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0)
            continue;
        struct stat st {
        }, again{};
        if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && now - st.st_mtime >= kStaleSeconds &&
            ::flock(fd, LOCK_EX | LOCK_NB) == 0 && ::lstat(path.c_str(), &again) == 0 && again.st_dev == st.st_dev &&
            again.st_ino == st.st_ino)
            ::unlink(path.c_str());
        ::close(fd);
    }
    ::closedir(dir);
}

// What path is when it exists and is not a regular file, or "" (a link counts as what it
// leads to: a link to /dev/null is a device).
std::string special_kind(const std::string& path)
{
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode))
        return "";
    if (S_ISDIR(st.st_mode))
        return "a directory";
    if (S_ISFIFO(st.st_mode))
        return "a FIFO";
    if (S_ISCHR(st.st_mode))
        return "a character device";
    if (S_ISBLK(st.st_mode))
        return "a block device";
    if (S_ISSOCK(st.st_mode))
        return "a socket";
    return "not a regular file";
}

void check_replaceable(const std::string& path)
{
    const std::string kind = special_kind(path);
    if (!kind.empty())
        throw Error(path + ": is " + kind + ", not a regular file: an output replaces only a regular file");
}

} // namespace

void remove_staged_files_on_signal()
{
    for (int i = 0; i < kSignalSlots; ++i)
        if (g_slot_used[i])
            ::unlink(g_slot_path[i]);
}

std::string lowercase_extension(const std::string& path)
{
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

void check_output_location(const std::string& path)
{
    fs::path dir = fs::path(path).parent_path();
    std::error_code ec;
    if (!dir.empty() && !fs::is_directory(dir, ec))
        throw Error(path + ": directory " + dir.string() + " does not exist");
    check_replaceable(path);
    // Found now, not when the first file is written (a checkpoint a minute into a render):
    // a file without a name in the directory (O_TMPFILE: the directory is left as it was),
    // or, where the file system has none, one with a name, removed at once.
    const std::string where = dir.empty() ? "." : dir.string();
    int fd = ::open(where.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
    if (fd < 0 && (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL)) {
        const std::string probe = temporary_name(path, "probe");
        fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        if (fd >= 0)
            ::unlink(probe.c_str());
        else if (errno == EEXIST)
            return; // this process's own probe: the directory takes files
    }
    if (fd < 0)
        throw Error(path + ": cannot write in " + (dir.empty() ? std::string("the working directory") : dir.string()) +
                    ": " + std::strerror(errno));
    ::close(fd);
}

StagedFiles::~StagedFiles()
{
    for (const Staged& f : files_) {
        ::unlink(f.tmp.c_str());
        ::close(f.lock_fd);
        release_slot(f.tmp);
    }
}

std::string StagedFiles::stage(const std::string& target)
{
    remove_stale_temporaries(target);
    static std::atomic<unsigned> counter{0};
    const std::string tmp = temporary_name(target, std::to_string(counter++) + fs::path(target).extension().string());
    // Created here (so no one else's file is taken over) and locked for as long as this
    // process lives: the lock is what tells a later run that the file is not stale.
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0)
        throw Error(target + ": cannot write: " + std::strerror(errno));
    ::flock(fd, LOCK_EX);
    files_.push_back({tmp, target, fd});
    claim_slot(tmp);
    return tmp;
}

void StagedFiles::commit()
{
    while (!files_.empty()) {
        const Staged f = files_.front();
        check_replaceable(f.target); // what was checked before the render may have changed since
        if (::rename(f.tmp.c_str(), f.target.c_str()) != 0)
            throw Error(f.target + ": cannot write: " + std::strerror(errno)); // the destructor removes the rest
        release_slot(f.tmp);
        ::close(f.lock_fd);
        files_.erase(files_.begin());
    }
}

} // namespace pathcl
