// Reading the files a glTF scene names (buffers, images, the environment map) so that a
// scene cannot make pathcl read anything but regular files inside its own directory: no
// "../" or absolute escapes, no links leading out, no directories, FIFOs or devices (a
// FIFO would block forever), and no fallback to the current working directory (the glTF
// library tries "./uri" after the scene's directory). A render service that shows users
// their images must not show them /etc/passwd as vertex colours.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace tinygltf {
struct FsCallbacks;
}

namespace pathcl {

// The canonical form of `path` when it names a regular file inside the canonical
// directory `dir` (the scene's; "" means the working directory); otherwise throws
// pathcl::Error "WHAT: REASON" (leaves the scene's directory, not a regular file, missing).
std::string confined_path(const std::string& dir, const std::string& relative, const std::string& what);

// Reads a whole regular file without blocking on a FIFO (opened non-blocking, checked with
// fstat before any read); at most max_bytes. Throws pathcl::Error naming `path`.
std::vector<unsigned char> read_regular_file(const std::string& path, std::size_t max_bytes);

// The file-system callbacks handed to tinygltf, confined to one directory. The library
// reports a refused file as "not found"; refusals() keeps the real reason per path so the
// loader's error can say it.
class ConfinedFiles {
public:
    explicit ConfinedFiles(const std::string& scene_dir);
    tinygltf::FsCallbacks callbacks();
    // "URI: reason" lines for the files refused so far, in the order they were asked for.
    const std::vector<std::string>& refusals() const { return refusals_; }
    // The files read, canonical.
    const std::vector<std::string>& files_read() const { return read_; }

private:
    static bool exists(const std::string& path, void* self);
    static std::string expand(const std::string& path, void* self);
    static bool read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* self);
    static bool write(std::string* err, const std::string& path, const std::vector<unsigned char>&, void* self);

    std::string dir_; // as the scene names it ("" for the working directory)
    std::vector<std::string> refusals_, read_;
};

} // namespace pathcl
