#include "scene/confined_files.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

#include <tiny_gltf.h>

#include "common/error.h"

namespace pathcl {
namespace fs = std::filesystem;

namespace {

// Larger files are refused: a GLB cannot be larger (its length field is 32 bits), and a
// buffer this large would not fit a device's memory anyway.
constexpr std::size_t kMaxSceneFileBytes = std::size_t(4) << 30;

} // namespace

std::string confined_path(const std::string& dir, const std::string& relative, const std::string& what)
{
    if (relative.empty())
        throw Error(what + ": the path is empty");
    if (fs::path(relative).is_absolute() || relative[0] == '/' || relative[0] == '\\')
        throw Error(what + ": is an absolute path (paths are relative to the scene's directory)");
    std::error_code ec;
    fs::path base = fs::weakly_canonical(fs::path(dir.empty() ? "." : dir), ec);
    fs::path file = ec ? fs::path() : fs::weakly_canonical(base / relative, ec);
    if (ec)
        throw Error(what + ": cannot resolve the path: " + ec.message());
    // Compared component by component after links and ".." are resolved, so neither leads out.
    auto [b, f] = std::mismatch(base.begin(), base.end(), file.begin(), file.end());
    if (b != base.end() || f == file.end())
        throw Error(what + ": leaves the scene's directory");
    fs::file_status st = fs::status(file, ec);
    if (!fs::exists(st))
        throw Error(what + ": no such file in the scene's directory");
    if (!fs::is_regular_file(st))
        throw Error(what + ": is not a regular file");
    return file.string();
}

std::vector<unsigned char> read_regular_file(const std::string& path, std::size_t max_bytes)
{
    // Non-blocking, so that a FIFO put in a regular file's place after the check cannot
    // block the open; fstat then refuses it before any read.
    int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        throw Error(path + ": cannot open: " + std::strerror(errno));
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
        throw Error(path + ": is not a regular file");
    std::size_t size = static_cast<std::size_t>(st.st_size);
    if (size > max_bytes)
        throw Error(path + ": is " + std::to_string(size) + " bytes, more than the limit of " +
                    std::to_string(max_bytes));
    std::vector<unsigned char> data(size);
    std::size_t done = 0;
    while (done < size) {
        ssize_t n = ::read(fd, data.data() + done, size - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            throw Error(path + ": cannot read: " + (n < 0 ? std::strerror(errno) : "the file shrank while read"));
        done += static_cast<std::size_t>(n);
    }
    return data;
}

ConfinedFiles::ConfinedFiles(const std::string& scene_dir) : dir_(scene_dir)
{}

tinygltf::FsCallbacks ConfinedFiles::callbacks()
{
    tinygltf::FsCallbacks cb{};
    cb.FileExists = &ConfinedFiles::exists;
    cb.ExpandFilePath = &ConfinedFiles::expand;
    cb.ReadWholeFile = &ConfinedFiles::read;
    cb.WriteWholeFile = &ConfinedFiles::write;
    cb.user_data = this;
    return cb;
}

bool ConfinedFiles::exists(const std::string& path, void* self)
{
    auto* me = static_cast<ConfinedFiles*>(self);
    // tinygltf asks for "DIR/uri" and then "./uri"; only the first is beside the scene.
    std::string prefix = me->dir_.empty() || me->dir_.back() == '/' ? me->dir_ : me->dir_ + "/";
    if (path.compare(0, prefix.size(), prefix) != 0)
        return false;
    std::string uri = path.substr(prefix.size());
    try {
        confined_path(me->dir_, uri, uri);
        return true;
    } catch (const Error& e) {
        if (std::find(me->refusals_.begin(), me->refusals_.end(), e.what()) == me->refusals_.end())
            me->refusals_.push_back(e.what());
        return false;
    }
}

std::string ConfinedFiles::expand(const std::string& path, void*)
{
    return path; // no "~" or "$VAR" expansion: a URI means the same wherever pathcl runs
}

bool ConfinedFiles::read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* self)
{
    if (!exists(path, self)) {
        if (err)
            *err += "refused";
        return false;
    }
    try {
        *out = read_regular_file(path, kMaxSceneFileBytes);
        static_cast<ConfinedFiles*>(self)->read_.push_back(fs::weakly_canonical(path).string());
        return true;
    } catch (const Error& e) {
        if (err)
            *err += e.what();
        return false;
    }
}

bool ConfinedFiles::write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*)
{
    if (err)
        *err += "pathcl never writes through the glTF library";
    return false;
}

} // namespace pathcl
