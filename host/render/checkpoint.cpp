#include "render/checkpoint.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <type_traits>
#include <unistd.h>

#include "common/error.h"
#include "common/fnv1a.h"
#include "common/staged_files.h"
#include "scene/confined_files.h"

namespace pathcl {
namespace {

constexpr char kMagic[8] = {'P', 'A', 'T', 'H', 'C', 'L', 'C', 'P'};
// 2: the film's totals are exact sums (render/exact_sum.h) instead of doubles.
constexpr std::uint32_t kVersion = 2;

static_assert(std::is_trivially_copyable_v<ExactSum> && sizeof(ExactSum) == 24, "checkpoints store ExactSum's bytes");

class Writer {
public:
    template <typename T>
    void value(const T& v)
    {
        const auto* p = reinterpret_cast<const unsigned char*>(&v);
        bytes.insert(bytes.end(), p, p + sizeof(T));
    }
    template <typename T>
    void array(const std::vector<T>& v)
    {
        value(static_cast<std::uint64_t>(v.size()));
        const auto* p = reinterpret_cast<const unsigned char*>(v.data());
        bytes.insert(bytes.end(), p, p + v.size() * sizeof(T));
    }
    std::vector<unsigned char> bytes;
};

class Reader {
public:
    Reader(const std::vector<unsigned char>& b, const std::string& path) : bytes_(b), path_(path) {}
    template <typename T>
    T value()
    {
        need(sizeof(T));
        T v;
        std::memcpy(&v, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return v;
    }
    template <typename T>
    std::vector<T> array()
    {
        auto n = value<std::uint64_t>();
        if (n > (bytes_.size() - at_) / sizeof(T))
            throw Error(path_ + ": checkpoint is truncated or corrupt");
        std::vector<T> v(static_cast<std::size_t>(n));
        std::memcpy(v.data(), bytes_.data() + at_, v.size() * sizeof(T));
        at_ += v.size() * sizeof(T);
        return v;
    }
    std::size_t at() const { return at_; }

private:
    void need(std::size_t n)
    {
        if (n > bytes_.size() - at_)
            throw Error(path_ + ": checkpoint is truncated or corrupt");
    }
    const std::vector<unsigned char>& bytes_;
    const std::string& path_;
    std::size_t at_ = 0;
};

} // namespace

void write_checkpoint(const std::string& path, const RenderCheckpoint& cp)
{
    Writer w;
    for (char c : kMagic)
        w.value(c);
    w.value(kVersion);
    w.array(std::vector<char>(cp.key.begin(), cp.key.end()));
    w.value(cp.batch);
    w.value(cp.pass);
    w.value(cp.spp_done);
    w.value(cp.samples);
    w.array(cp.film.sum);
    w.array(cp.film.sum_sq);
    w.array(cp.film.batch_mean_sum);
    w.array(cp.film.batch_mean_sq);
    w.array(cp.film.samples);
    w.array(cp.film.pixel_batches);
    w.value(cp.film.bad);
    w.value(cp.film.batches);
    w.value(static_cast<std::uint64_t>(cp.device_films.size()));
    for (std::size_t d = 0; d < cp.device_films.size(); ++d) {
        w.array(cp.device_films[d]);
        w.array(cp.device_bad[d]);
    }
    w.array(cp.active);
    w.value(fnv1a64(w.bytes.data(), w.bytes.size()));

    StagedFiles staged;
    const std::string tmp = staged.stage(path);
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
        throw Error(path + ": cannot write the checkpoint: " + std::strerror(errno));
    std::size_t done = 0;
    int err = 0;
    while (done < w.bytes.size()) {
        ssize_t n = ::write(fd, w.bytes.data() + done, w.bytes.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            err = n < 0 ? errno : EIO;
            break;
        }
        done += static_cast<std::size_t>(n);
    }
    if (!err && ::fsync(fd) != 0) // a full disk may only show here
        err = errno;
    if (::close(fd) != 0 && !err)
        err = errno;
    if (err)
        throw Error(path + ": cannot write the checkpoint: " + std::strerror(err)); // staged removes tmp
    staged.commit();
}

RenderCheckpoint read_checkpoint(const std::string& path)
{
    std::vector<unsigned char> bytes = read_regular_file(path, std::size_t(1) << 36);
    if (bytes.size() < sizeof kMagic + 8 || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        throw Error(path + ": is not a pathcl checkpoint");
    std::uint64_t stored;
    std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
    if (stored != fnv1a64(bytes.data(), bytes.size() - 8))
        throw Error(path + ": checkpoint is truncated or corrupt (checksum)");
    bytes.resize(bytes.size() - 8);
    Reader r(bytes, path);
    for (std::size_t i = 0; i < sizeof kMagic; ++i)
        r.value<char>();
    if (r.value<std::uint32_t>() != kVersion)
        throw Error(path + ": checkpoint of another pathcl version");
    RenderCheckpoint cp;
    std::vector<char> key = r.array<char>();
    cp.key.assign(key.begin(), key.end());
    cp.batch = r.value<std::uint32_t>();
    cp.pass = r.value<std::uint32_t>();
    cp.spp_done = r.value<std::uint32_t>();
    cp.samples = r.value<double>();
    cp.film.sum = r.array<ExactSum>();
    cp.film.sum_sq = r.array<ExactSum>();
    cp.film.batch_mean_sum = r.array<ExactSum>();
    cp.film.batch_mean_sq = r.array<ExactSum>();
    cp.film.samples = r.array<double>();
    cp.film.pixel_batches = r.array<std::uint32_t>();
    cp.film.bad = r.value<std::uint64_t>();
    cp.film.batches = r.value<std::uint32_t>();
    auto devices = r.value<std::uint64_t>();
    if (devices > 1024)
        throw Error(path + ": checkpoint is truncated or corrupt");
    for (std::uint64_t d = 0; d < devices; ++d) {
        cp.device_films.push_back(r.array<FilmPixel>());
        cp.device_bad.push_back(r.array<pcl_uint>());
    }
    cp.active = r.array<pcl_uint>();
    if (r.at() != bytes.size())
        throw Error(path + ": checkpoint is truncated or corrupt");
    return cp;
}

} // namespace pathcl
