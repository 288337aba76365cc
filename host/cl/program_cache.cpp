#include "cl/program_cache.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

#include "common/fnv1a.h"

namespace pathcl {
namespace {

constexpr char kMagic[8] = {'P', 'A', 'T', 'H', 'C', 'L', 'K', 'C'};
// Bump when the entry layout changes: older entries then read as misses.
constexpr std::uint32_t kFormatVersion = 1;

void put_le(std::vector<unsigned char>& out, std::uint64_t v, int bytes)
{
    for (int i = 0; i < bytes; ++i)
        out.push_back(static_cast<unsigned char>(v >> (8 * i)));
}

std::uint64_t get_le(const unsigned char* p, int bytes)
{
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i)
        v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
    return v;
}

// Everything the checksum follows: magic, version, key length and key, body length.
std::vector<unsigned char> entry_header(const std::string& key, std::uint64_t body_size)
{
    std::vector<unsigned char> h(std::begin(kMagic), std::end(kMagic));
    put_le(h, kFormatVersion, 4);
    put_le(h, key.size(), 4);
    h.insert(h.end(), key.begin(), key.end());
    put_le(h, body_size, 8);
    return h;
}

std::uint64_t entry_checksum(const std::vector<unsigned char>& header, const unsigned char* body, std::size_t n)
{
    return fnv1a64(body, n, fnv1a64(header.data(), header.size()));
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

// Removes the temporary file on every way out of a store but a successful rename.
struct TempFile {
    std::filesystem::path path;
    bool renamed = false;
    ~TempFile()
    {
        if (!renamed) {
            std::error_code ec;
            std::filesystem::remove(path, ec);
        }
    }
};

} // namespace

std::string program_cache_key(const std::string& device_identity, const std::string& options, const std::string& source)
{
    // Two independent 64-bit hashes: an accidental collision is not a practical concern.
    std::string all = device_identity + '\x1f' + options + '\x1f' + source;
    char buf[40];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(fnv1a64(all.data(), all.size())),
                  static_cast<unsigned long long>(fnv1a64(all.data(), all.size(), 0x84222325cbf29ce4ull)));
    return buf;
}

std::optional<std::vector<unsigned char>> program_cache_load(const std::string& key)
{
    std::filesystem::path dir = cache_dir();
    if (dir.empty())
        return std::nullopt;
    // The body length is whatever the file holds past the header; the stored header must
    // then match, byte for byte, the one this key and length give. A bad entry is left in
    // place (the rebuild's store replaces it): deleting it could race a writer's rename.
    const std::filesystem::path path = dir / (key + ".bin");
    const std::size_t overhead = sizeof kMagic + 4 + 4 + key.size() + 8 + 8;
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec); // fails for a directory
    if (ec || size <= overhead)
        return std::nullopt;
    // read(), unlike a streambuf iterator, reports a read error in the stream state rather
    // than by throwing.
    std::vector<unsigned char> data(size);
    std::ifstream f(path, std::ios::binary);
    if (!f.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(size)))
        return std::nullopt;
    const std::size_t body_size = data.size() - overhead;
    const std::vector<unsigned char> header = entry_header(key, body_size);
    if (!std::equal(header.begin(), header.end(), data.begin()))
        return std::nullopt;
    if (get_le(data.data() + header.size(), 8) != entry_checksum(header, data.data() + overhead, body_size))
        return std::nullopt;
    data.erase(data.begin(), data.begin() + static_cast<std::ptrdiff_t>(overhead));
    return data;
}

void program_cache_store(const std::string& key, const std::vector<unsigned char>& binary)
{
    std::filesystem::path dir = cache_dir();
    if (dir.empty() || binary.empty())
        return;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    std::vector<unsigned char> header = entry_header(key, binary.size());
    put_le(header, entry_checksum(header, binary.data(), binary.size()), 8);
    // Write to a private name (per process and per call), then rename: readers never see a
    // partial entry.
    static std::atomic<unsigned> serial{0};
    TempFile tmp{dir / (key + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(serial++))};
    {
        std::ofstream f(tmp.path, std::ios::binary);
        f.write(reinterpret_cast<const char*>(header.data()), static_cast<std::streamsize>(header.size()));
        f.write(reinterpret_cast<const char*>(binary.data()), static_cast<std::streamsize>(binary.size()));
        // Buffered bytes reach the file at close: a full disk may only show there.
        f.close();
        if (f.fail())
            return;
    }
    std::filesystem::rename(tmp.path, dir / (key + ".bin"), ec);
    tmp.renamed = !ec;
}

} // namespace pathcl
