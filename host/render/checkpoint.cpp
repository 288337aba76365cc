#include "render/checkpoint.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
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
        if (n > 0) // an empty vector's data() may be null, which memcpy may not take even for 0 bytes
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

std::uint64_t max_checkpoint_bytes(std::size_t pixels)
{
    const std::uint64_t per_pixel = 12 * sizeof(ExactSum) + sizeof(double) + sizeof(std::uint32_t) + sizeof(FilmPixel) +
                                    sizeof(pcl_uint) + sizeof(pcl_uint); // film, device film, mask
    const std::uint64_t fixed = sizeof kMagic + 4 + 8 + kMaxCheckpointKeyBytes + 3 * 4 + 8 + 6 * 8 + 8 + 4 + 8 + 2 * 8 +
                                8 + 8; // header, key, counters, array lengths, checksum
    return fixed + per_pixel * pixels;
}

RenderCheckpoint read_checkpoint(const std::string& path, std::size_t pixels)
{
    const std::uint64_t limit = max_checkpoint_bytes(pixels);
    std::vector<unsigned char> bytes = read_regular_file(path, static_cast<std::size_t>(limit));
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
    if (key.size() > kMaxCheckpointKeyBytes)
        throw Error(path + ": checkpoint is truncated or corrupt (its key is " + std::to_string(key.size()) +
                    " bytes long)");
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

std::string key_difference(const std::string& checkpoint_key, const std::string& render_key)
{
    const auto fields = [](const std::string& key) {
        std::vector<std::string> out;
        for (std::size_t at = 0;;) {
            const std::size_t end = key.find("; ", at);
            out.push_back(key.substr(at, end == std::string::npos ? std::string::npos : end - at));
            if (end == std::string::npos)
                return out;
            at = end + 2;
        }
    };
    const std::vector<std::string> theirs = fields(checkpoint_key), ours = fields(render_key);
    for (std::size_t i = 0; i < std::max(theirs.size(), ours.size()); ++i) {
        const std::string a = i < theirs.size() ? theirs[i] : "", b = i < ours.size() ? ours[i] : "";
        if (a != b)
            return "its " + quote(a) + ", this render's " + quote(b);
    }
    return "its key " + quote(checkpoint_key) + ", this render's " + quote(render_key);
}

void check_checkpoint(const RenderCheckpoint& cp, const BatchPlan& plan, std::size_t pixels, bool adaptive)
{
    auto refuse = [](const std::string& what) { throw ParameterError("resume", "the checkpoint " + what); };
    const std::uint32_t first = plan.first_batch(), end = plan.batch_count();
    if (cp.batch < first || cp.batch >= end || cp.pass >= plan.batch_passes(cp.batch))
        refuse("is at pass " + std::to_string(cp.pass) + " of batch " + std::to_string(cp.batch) +
               ", which this render does not have (batches " + std::to_string(first) + " to " +
               std::to_string(end - 1) + " of " + std::to_string(plan.batch_spp) + " passes)");
    // Every batch before the one in progress is whole, and each pass of it took one
    // sample per pixel.
    const std::uint32_t whole = cp.batch - first;
    const std::uint64_t whole_samples = std::uint64_t(whole) * plan.batch_spp;
    if (cp.spp_done != whole_samples + cp.pass)
        refuse("counts " + std::to_string(cp.spp_done) + " samples per pixel done, not the " +
               std::to_string(whole_samples + cp.pass) + " of its batch and pass");
    if (!(cp.samples >= 0.0 && cp.samples <= static_cast<double>(cp.spp_done) * static_cast<double>(pixels)))
        refuse("counts a number of samples that this render cannot have taken");
    if (cp.device_films.size() != 1 || cp.device_bad.size() != 1 || cp.device_films[0].size() != pixels ||
        cp.device_bad[0].size() != pixels)
        refuse("does not hold one film of this render's " + std::to_string(pixels) + " pixels");
    if (adaptive ? cp.active.size() != pixels : !cp.active.empty())
        refuse(adaptive ? "has no mask of active pixels for this adaptive render"
                        : "has a mask of active pixels, and this render is not adaptive");
    for (pcl_uint a : cp.active)
        if (a > 1)
            refuse("has a mask of active pixels with values other than 0 and 1");
    const std::string film = FilmAccumulator::state_problem(cp.film, pixels, whole, whole_samples);
    if (!film.empty())
        refuse(film);
    for (std::size_t i = 0; i < pixels; ++i) {
        const FilmPixel& f = cp.device_films[0][i];
        const float values[16] = {f.sum.x,
                                  f.sum.y,
                                  f.sum.z,
                                  f.sum.w,
                                  f.sum_compensation.x,
                                  f.sum_compensation.y,
                                  f.sum_compensation.z,
                                  f.sum_compensation.w,
                                  f.sum_sq.x,
                                  f.sum_sq.y,
                                  f.sum_sq.z,
                                  f.sum_sq.w,
                                  f.sum_sq_compensation.x,
                                  f.sum_sq_compensation.y,
                                  f.sum_sq_compensation.z,
                                  f.sum_sq_compensation.w};
        for (float v : values)
            if (!std::isfinite(v))
                refuse("holds a value that is not finite in pixel " + std::to_string(i) + " of its batch in progress");
        if (!(f.sum.w >= 0.0f && f.sum.w <= static_cast<float>(cp.pass)) || cp.device_bad[0][i] > cp.pass)
            refuse("counts more samples in pixel " + std::to_string(i) + " of its batch in progress than its " +
                   std::to_string(cp.pass) + " passes took");
    }
}

} // namespace pathcl
