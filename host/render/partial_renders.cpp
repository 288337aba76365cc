#include "render/partial_renders.h"

#include <algorithm>
#include <optional>

#include "common/error.h"
#include "common/text_fields.h"
#include "image/image_io.h"
#include "render/film.h"
#include "render/film_channels.h"
#include "render/render_metadata.h"

namespace pathcl {
namespace {

// A decimal uint32, or nothing.
std::optional<std::uint32_t> parse_u32(const std::string& s)
{
    auto v = parse_whole_number(s, 0xffffffffu);
    if (!v)
        return std::nullopt;
    return static_cast<std::uint32_t>(*v);
}

std::optional<SampleRange> parse_range(const std::string& text)
{
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos)
        return std::nullopt;
    auto first = parse_u32(text.substr(0, colon)), count = parse_u32(text.substr(colon + 1));
    if (!first || !count || *count == 0 || std::uint64_t(*first) + *count > 0xffffffffull)
        return std::nullopt;
    return SampleRange{*first, *count};
}

const std::string& meta(const Image& img, const std::string& key, const std::string& path)
{
    auto it = img.metadata.find(key);
    if (it == img.metadata.end())
        throw Error(path + ": is not a partial render (--sample-range): it has no pathcl:" + key);
    return it->second;
}

std::uint32_t meta_u32(const Image& img, const std::string& key, const std::string& path)
{
    auto v = parse_u32(meta(img, key, path));
    if (!v)
        throw Error(path + ": pathcl:" + key + " is not a number");
    return *v;
}

std::vector<SampleRange> meta_ranges(const Image& img, const std::string& path)
{
    const std::string& text = meta(img, "sample_ranges", path);
    std::vector<SampleRange> out;
    for (const std::string& item : split_commas(text)) {
        auto r = parse_range(item);
        if (!r)
            throw Error(path + ": pathcl:sample_ranges " + quote(text) + " is not a list of FIRST:COUNT");
        out.push_back(*r);
    }
    return out;
}

// The value of `field` in a render key ("...; batch spp 16; spp 64; ..."), or "".
std::string key_field(const std::string& key, const std::string& field)
{
    const std::string tag = "; " + field + " ";
    const std::size_t at = key.find(tag);
    if (at == std::string::npos)
        return "";
    const std::size_t begin = at + tag.size(), end = key.find(';', begin);
    return key.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

// What a partial render says of the render it belongs to, checked against its own key
// (which names the render): numbers a hand may have edited must still describe it.
struct RenderLayout {
    std::uint32_t spp_total = 0, batch_spp = 0, seed = 0;
    SamplerType sampler = SamplerType::Sobol;
};

RenderLayout render_layout(const Image& img, const std::string& key, const std::string& path)
{
    RenderLayout l;
    l.spp_total = meta_u32(img, "spp_total", path);
    l.batch_spp = meta_u32(img, "batch_spp", path);
    l.seed = meta_u32(img, "seed", path);
    auto s = sampler_names().find(meta(img, "sampler", path));
    if (s == sampler_names().end())
        throw Error(path + ": pathcl:sampler names no sampler");
    l.sampler = s->second;
    auto agrees = [&](const char* name, const std::string& field, const std::string& value) {
        if (key_field(key, field) != value)
            throw Error(path + ": pathcl:" + name + " " + quote(value) + " is not what its pathcl:render_key says (" +
                        field + " " + quote(key_field(key, field)) + ")");
    };
    agrees("spp_total", "spp", std::to_string(l.spp_total));
    agrees("batch_spp", "batch spp", std::to_string(l.batch_spp));
    agrees("seed", "seed", std::to_string(l.seed));
    agrees("sampler", "sampler", sampler_name(l.sampler));
    agrees("size", "size", std::to_string(img.width) + "x" + std::to_string(img.height));
    if (l.spp_total == 0 || l.batch_spp == 0 || l.batch_spp > (1u << 31))
        throw Error(path + ": pathcl:spp_total " + std::to_string(l.spp_total) + " and pathcl:batch_spp " +
                    std::to_string(l.batch_spp) + " describe no render");
    return l;
}

} // namespace

SampleRange parse_sample_range(const std::string& text)
{
    auto r = parse_range(text);
    if (!r)
        throw Error("--sample-range: " + quote(text) + " is not FIRST:COUNT (sample indices, COUNT at least 1)");
    return *r;
}

std::string format_sample_ranges(std::vector<SampleRange> ranges)
{
    std::sort(ranges.begin(), ranges.end(),
              [](const SampleRange& a, const SampleRange& b) { return a.first < b.first; });
    std::vector<SampleRange> joined;
    for (const SampleRange& r : ranges) {
        if (!joined.empty() && joined.back().first + joined.back().count == r.first)
            joined.back().count += r.count;
        else
            joined.push_back(r);
    }
    std::string text;
    for (const SampleRange& r : joined)
        text += (text.empty() ? "" : ",") + std::to_string(r.first) + ":" + std::to_string(r.count);
    return text;
}

Image merge_partial_renders(const std::vector<std::string>& paths)
{
    if (paths.empty())
        throw Error("merge: no partial renders given");
    std::optional<FilmAccumulator> film;
    std::string key, first_path;
    std::uint32_t width = 0, height = 0, spp = 0;
    RenderLayout layout;
    struct Owned {
        SampleRange range;
        const std::string* path;
    };
    std::vector<Owned> owned;
    for (const std::string& path : paths) {
        Image img = read_image(path);
        const std::string& its_key = meta(img, "render_key", path);
        const std::string& stop = meta(img, "stop", path);
        if (stop != "spp")
            throw Error(path + ": stopped early (" + stop + "): finish its range first (--resume its checkpoint)");
        const RenderLayout its_layout = render_layout(img, its_key, path);
        if (!film) {
            key = its_key;
            first_path = path;
            width = img.width;
            height = img.height;
            layout = its_layout;
            film.emplace(static_cast<std::size_t>(width) * height, layout.batch_spp);
        } else if (its_key != key || img.width != width || img.height != height) {
            throw Error(path + ": is a range of another render than " + first_path + " (its key " + quote(its_key) +
                        ", not " + quote(key) + ")");
        }
        const std::uint32_t spp_total = layout.spp_total, batch_spp = layout.batch_spp;
        std::uint64_t its_samples = 0, its_batches = 0;
        for (const SampleRange& r : meta_ranges(img, path)) {
            const std::uint64_t end = std::uint64_t(r.first) + r.count;
            if (end > spp_total)
                throw Error(path + ": its sample range ends past the render's " + std::to_string(spp_total) +
                            " samples");
            if (r.first % batch_spp != 0 || (end % batch_spp != 0 && end != spp_total))
                throw Error(path + ": its sample range " + format_sample_ranges({r}) +
                            " is not made of whole batches of " + std::to_string(batch_spp));
            its_samples += r.count;
            its_batches += (r.count + batch_spp - 1) / batch_spp; // only the render's last batch may be short
            for (const Owned& o : owned)
                if (r.first < o.range.first + o.range.count && o.range.first < r.first + r.count)
                    throw Error(path + ": its samples " + format_sample_ranges({r}) + " overlap " + *o.path + "'s " +
                                format_sample_ranges({o.range}) + ": a sample would count twice");
            owned.push_back({r, &path});
            spp += r.count;
        }
        read_film_part(path, img);
        const FilmAccumulator::State state = load_film_state(img, path);
        const std::string problem = FilmAccumulator::state_problem(
            state, static_cast<std::size_t>(width) * height, static_cast<std::uint32_t>(its_batches), its_samples);
        if (!problem.empty())
            throw Error(path + ": " + problem);
        film->merge(state);
    }
    std::vector<SampleRange> ranges;
    for (const Owned& o : owned)
        ranges.push_back(o.range);
    const std::string union_text = format_sample_ranges(ranges);
    const std::uint32_t spp_total = layout.spp_total;
    Image out = film->image(width, height, spp);
    describe_render({StopReason::Spp, layout.seed, layout.sampler, layout.batch_spp}, *film,
                    estimate_error(*film, layout.sampler), out);
    if (union_text != format_sample_ranges({{0, spp_total}})) { // still partial
        store_film_state(film->state(), out);
        out.metadata["render_key"] = key;
        out.metadata["sample_ranges"] = union_text;
        out.metadata["spp_total"] = std::to_string(spp_total);
    }
    return out;
}

} // namespace pathcl
