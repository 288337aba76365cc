// What an image says about how it was made (Image::metadata, EXR attributes "pathcl:*"):
// the stop reason, seed, sampler, batches and the error estimate. A render and a merge of
// sample ranges (render/partial_renders.h) write it the same way, so a complete merge
// describes itself as the whole render does.
#pragma once

#include <cstdint>

#include "image/image.h"
#include "render/batches.h"
#include "render/film.h"
#include "sampling/samplers.h"

namespace pathcl {

// The image's estimated relMSE: the spread of the batch means after two whole batches,
// else the per-sample variance, an upper bound for every sampler but the independent one.
// Negative when there is none.
struct ErrorEstimate {
    double relmse = -1.0;
    bool is_bound = false;
};
ErrorEstimate estimate_error(const FilmAccumulator& film, SamplerType sampler);

struct RenderDescription {
    StopReason stop = StopReason::Spp;
    std::uint32_t seed = 0;
    SamplerType sampler = SamplerType::Sobol;
    std::uint32_t batch_spp = 0;
};

// Sets stop, seed, sampler, batch_spp, batches and relmse_estimate(_method).
void describe_render(const RenderDescription& render, const FilmAccumulator& film, const ErrorEstimate& error,
                     Image& image);

} // namespace pathcl
