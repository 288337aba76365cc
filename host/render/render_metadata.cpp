#include "render/render_metadata.h"

#include <cstdio>
#include <string>

namespace pathcl {

ErrorEstimate estimate_error(const FilmAccumulator& film, SamplerType sampler)
{
    ErrorEstimate e;
    if (film.batches() >= 2) {
        e.relmse = film.relmse_estimate();
    } else {
        e.relmse = film.per_sample_relmse_estimate();
        e.is_bound = sampler != SamplerType::Independent;
    }
    return e;
}

void describe_render(const RenderDescription& r, const FilmAccumulator& film, const ErrorEstimate& error, Image& image)
{
    auto& meta = image.metadata;
    meta["stop"] = stop_reason_name(r.stop);
    meta["seed"] = std::to_string(r.seed);
    meta["sampler"] = sampler_name(r.sampler);
    meta["batch_spp"] = std::to_string(r.batch_spp);
    meta["batches"] = std::to_string(film.batches());
    if (error.relmse >= 0.0) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6g", error.relmse);
        meta["relmse_estimate"] = buf;
        meta["relmse_estimate_method"] =
            film.batches() >= 2 ? "batch means"
                                : (error.is_bound ? "per-sample variance (upper bound)" : "per-sample variance");
    }
}

} // namespace pathcl
