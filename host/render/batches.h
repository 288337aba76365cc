// How a render's samples are laid out, and what ends it.
//
// A render is a run of batches. Batch b is a whole point set of batch_spp samples per pixel
// (the sampler's set size, FrameParams.spp) scrambled by its own seed batch_seed(seed, b);
// its sample indices 0 .. batch_spp - 1 are the render's passes. Batch 0's seed is the
// render's seed, so a render of one batch is the render of one point set of spp samples.
// Independently scrambled batches give an error estimate every sampler can be trusted
// with (the spread of the batch means, render/film.h); the price is that a quasi-Monte
// Carlo sampler stratifies within a batch only (docs/accuracy.md).
//
// The last batch may be partial (a budget ended it, or spp is not a multiple of
// batch_spp): every padded sampler maps sample indices onto its set through a random
// permutation, so any prefix of a set is an unbiased, if less stratified, estimate. A
// render's image depends only on (seed, batch_spp, the sample indices it took), never on
// the devices, the pass order or what stopped it, so `--spp N --batch-spp B` reproduces a
// budgeted render that reached N.
#pragma once

#include <cstdint>

#include "render/render_options.h"

namespace pathcl {

struct BatchPlan {
    std::uint32_t batch_spp = 1; // point-set size of every batch (after sampler_spp)
    std::uint32_t max_spp = 1;   // sample indices per pixel at most, over all batches
    std::uint32_t min_spp = 0;   // a target error is not trusted before
    bool budgeted = false;       // a time budget or a target error may end it early
    // The sample indices this render takes: all (0 .. max_spp) or a range of whole batches
    // (RenderOptions::sample_first, sample_count).
    std::uint32_t first_spp = 0, end_spp = 1;
    // A range was asked for (even one covering every sample): the image carries its film
    // state for `pathcl merge`.
    bool ranged = false;

    std::uint32_t first_batch() const { return first_spp / batch_spp; }
    std::uint32_t batch_count() const { return (end_spp + batch_spp - 1) / batch_spp; } // one past the last
    // Passes of batch b (batch_spp, or fewer for the last).
    std::uint32_t batch_passes(std::uint32_t b) const;
};

// Checks the options' batch and budget fields (ParameterError) and lays the render out.
BatchPlan plan_batches(const RenderOptions& options);

// The scrambling seed of batch b: the render's seed for batch 0, a hash of (seed, b)
// otherwise.
std::uint32_t batch_seed(std::uint32_t seed, std::uint32_t batch);

// Why a render ended.
enum class StopReason {
    Spp,         // every planned sample taken
    Time,        // the time budget spent
    TargetError, // the estimated error reached the target (or adaptive sampling stopped every pixel)
    Interrupted, // the caller asked it to stop (Ctrl-C)
};

// "spp", "time", "target error", "interrupted".
const char* stop_reason_name(StopReason reason);

} // namespace pathcl
