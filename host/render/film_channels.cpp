#include "render/film_channels.h"

#include <array>
#include <map>

#include "common/error.h"
#include "common/text_fields.h"

namespace pathcl {
namespace {

constexpr int kWords = 6; // 32-bit words of an ExactSum
const char* const kRgb[3] = {"R", "G", "B"};

// The four exact-sum arrays of a state, in channel order.
template <typename State>
auto exact_arrays(State& s)
{
    return std::array{std::pair{"sum", &s.sum}, std::pair{"sum_sq", &s.sum_sq},
                      std::pair{"batch_mean_sum", &s.batch_mean_sum}, std::pair{"batch_mean_sq", &s.batch_mean_sq}};
}

std::vector<std::string> channel_names()
{
    std::vector<std::string> names;
    FilmAccumulator::State none;
    for (const auto& [name, array] : exact_arrays(none))
        for (const char* c : kRgb)
            for (int w = 0; w < kWords; ++w)
                names.push_back(std::string(name) + "." + c + "." + std::to_string(w));
    names.push_back("samples");
    names.push_back("pixel_batches");
    return names;
}

std::uint64_t metadata_number(const Image& image, const std::string& key, const std::string& path,
                              std::uint64_t max = UINT64_MAX)
{
    auto it = image.metadata.find(key);
    auto v = it == image.metadata.end() ? std::nullopt : parse_whole_number(it->second, max);
    if (!v)
        throw Error(path + ": its film part lacks a valid pathcl:" + key);
    return *v;
}

} // namespace

void store_film_state(const FilmAccumulator::State& s, Image& image)
{
    const std::size_t pixels = s.samples.size();
    image.film_channels = channel_names();
    const std::size_t channels = image.film_channels.size();
    image.film.assign(pixels * channels, 0u);
    for (std::size_t i = 0; i < pixels; ++i) {
        std::uint32_t* p = &image.film[i * channels];
        for (const auto& [name, array] : exact_arrays(s))
            for (int c = 0; c < 3; ++c) {
                const ExactSum& e = (*array)[i * 3 + static_cast<std::size_t>(c)];
                for (int w = 0; w < kWords; ++w)
                    *p++ = static_cast<std::uint32_t>(e.limb[w / 2] >> (32 * (w % 2)));
            }
        *p++ = static_cast<std::uint32_t>(s.samples[i]); // whole numbers below 2^32
        *p++ = s.pixel_batches[i];
    }
    image.metadata["film_batches"] = std::to_string(s.batches);
    image.metadata["film_bad_samples"] = std::to_string(s.bad);
}

FilmAccumulator::State load_film_state(const Image& image, const std::string& path)
{
    const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
    const std::size_t channels = image.film_channels.size();
    if (channels == 0 || image.film.size() != pixels * channels)
        throw Error(path + ": has no film part: not a partial render (--sample-range)");
    std::map<std::string, std::size_t> index;
    for (std::size_t c = 0; c < channels; ++c)
        index[image.film_channels[c]] = c;
    std::vector<std::size_t> at; // the file's channel of each of ours
    for (const std::string& name : channel_names()) {
        auto it = index.find(name);
        if (it == index.end())
            throw Error(path + ": its film part has no channel " + name);
        at.push_back(it->second);
    }
    FilmAccumulator::State s;
    for (const auto& [name, array] : exact_arrays(s))
        array->resize(pixels * 3);
    s.samples.resize(pixels);
    s.pixel_batches.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint32_t* p = &image.film[i * channels];
        std::size_t k = 0;
        for (const auto& [name, array] : exact_arrays(s))
            for (int c = 0; c < 3; ++c) {
                ExactSum& e = (*array)[i * 3 + static_cast<std::size_t>(c)];
                for (int w = 0; w < kWords; ++w)
                    e.limb[w / 2] |= static_cast<std::uint64_t>(p[at[k++]]) << (32 * (w % 2));
            }
        s.samples[i] = p[at[k++]];
        s.pixel_batches[i] = p[at[k++]];
    }
    s.batches = static_cast<std::uint32_t>(metadata_number(image, "film_batches", path, 0xffffffffu));
    s.bad = metadata_number(image, "film_bad_samples", path);
    return s;
}

} // namespace pathcl
