// What both fuzz targets need to hand an input to code that reads files: a per-process
// temporary directory (made on first use, removed when the process exits) and writing the
// input into a file there.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace fuzz {

// Never destroyed, so that the exit handler can still read it.
inline std::string* scratch = nullptr;

inline void remove_scratch()
{
    std::error_code ec;
    std::filesystem::remove_all(*scratch, ec);
}

// $TMPDIR/pathcl-fuzz-TARGET.XXXXXX (TMPDIR defaults to /tmp).
inline const std::string& scratch_directory(const char* target)
{
    if (!scratch) {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/pathcl-fuzz-" + target + ".XXXXXX";
        if (!mkdtemp(pattern.data())) {
            std::perror("fuzz: mkdtemp");
            std::abort();
        }
        scratch = new std::string(pattern);
        std::atexit(remove_scratch);
    }
    return *scratch;
}

inline void write_file(const std::string& path, const std::uint8_t* data, std::size_t size)
{
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f || (size && std::fwrite(data, 1, size, f) != size) || std::fclose(f) != 0) {
        std::perror(("fuzz: cannot write " + path).c_str());
        std::abort();
    }
}

} // namespace fuzz
