#include "cl/program_cache.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace pathcl {
namespace {

std::uint64_t fnv1a64(const std::string& s, std::uint64_t h = 0xcbf29ce484222325ull)
{
    for (unsigned char c : s) {
        h ^= c;
        h *= 0x100000001b3ull;
    }
    return h;
}

std::filesystem::path cache_dir()
{
    if (const char* d = std::getenv("PATHCL_CACHE_DIR"); d && *d)
        return d;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
        return std::filesystem::path(x) / "pathcl";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "pathcl";
    return {};
}

} // namespace

std::string program_cache_key(const std::string& device_identity, const std::string& options, const std::string& source)
{
    // Two independent 64-bit hashes: an accidental collision is not a practical concern.
    std::string all = device_identity + '\x1f' + options + '\x1f' + source;
    char buf[40];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(fnv1a64(all)),
                  static_cast<unsigned long long>(fnv1a64(all, 0x84222325cbf29ce4ull)));
    return buf;
}

std::optional<std::vector<unsigned char>> program_cache_load(const std::string& key)
{
    std::filesystem::path dir = cache_dir();
    if (dir.empty())
        return std::nullopt;
    std::ifstream f(dir / (key + ".bin"), std::ios::binary);
    if (!f)
        return std::nullopt;
    std::vector<unsigned char> data((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    if (data.empty())
        return std::nullopt;
    return data;
}

void program_cache_store(const std::string& key, const std::vector<unsigned char>& binary)
{
    std::filesystem::path dir = cache_dir();
    if (dir.empty() || binary.empty())
        return;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    // Write to a private name, then rename: readers never see a partial binary.
    std::filesystem::path tmp = dir / (key + ".tmp." + std::to_string(::getpid()));
    {
        std::ofstream f(tmp, std::ios::binary);
        if (!f)
            return;
        f.write(reinterpret_cast<const char*>(binary.data()), static_cast<std::streamsize>(binary.size()));
        if (!f)
            return;
    }
    std::filesystem::rename(tmp, dir / (key + ".bin"), ec);
    if (ec)
        std::filesystem::remove(tmp, ec);
}

} // namespace pathcl
