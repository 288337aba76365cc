// A convergence study (`pathcl converge`): every setting rendered at every spp of a ladder
// with several seeds, each render timed (kernel build excluded, reported per setting cold
// and cached) and measured against a converged reference.
//
// A setting with adaptive sampling on is rendered to a per-row target instead: a pilot
// render of two 16-spp batches per seed estimates the relMSE c / n a uniform render of n
// spp reaches, and the row of ladder point n asks for relMSE c / n with at most 4 n spp.
// The row's time is the adaptive render's alone; its spp is the mean samples per pixel
// taken.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "converge/knobs.h"
#include "image/image_error.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace pathcl {

struct ConvergenceStudy {
    RenderOptions base; // size, bounces, seed, sampler ... as given; the settings vary it
    std::vector<Setting> settings;
    std::vector<std::uint32_t> ladder; // spp, ascending
    std::uint32_t seeds = 3;           // seeds base.seed, base.seed + 1, ...
};

// The options of the reference render: the base options with the largest bounce limit of
// any setting, one batch, no budget, scene specialization, no fast math, and a seed no
// row uses.
RenderOptions reference_options(const ConvergenceStudy& study, std::uint32_t reference_spp);

// What a cached reference must match: the scene's fingerprint and the reference's options.
std::string reference_key(const Scene& scene, const RenderOptions& reference);

struct SettingBuild {
    double cold_seconds = 0.0;   // compiled with every cache bypassed
    double cached_seconds = 0.0; // loaded from pathcl's binary cache
    // A render before the ladder, not a row (1 spp; two batches for adaptive settings):
    // drivers may finish compiling at the first dispatch (PoCL did, about 0.8 s, after a
    // build that did not come from its cache), which would otherwise land on a row.
    double first_render_seconds = 0.0;
};

struct ConvergenceRow {
    std::size_t setting = 0;
    std::uint32_t spp = 0;  // the ladder's
    double spp_taken = 0.0; // mean samples per pixel the render took
    std::uint32_t seed = 0;
    double render_seconds = 0.0, samples_per_second = 0.0;
    ImageError error;
    double error_estimate = -1.0; // the render's own (RenderStats::error_estimate)
    std::string stop;
};

struct ConvergenceCallbacks {
    std::function<void(std::size_t setting, const SettingBuild&)> setting_built;
    // Called after every row; false stops the study.
    std::function<bool(const ConvergenceRow&)> row;
    // Progress of each render (the row it will become: setting, spp, seed); false stops it.
    std::function<bool(const ConvergenceRow&, const RenderProgress&)> progress;
};

// Runs the study against `reference`; returns false when a callback stopped it.
bool run_convergence(const Scene& scene, const ConvergenceStudy& study, const Image& reference,
                     const ConvergenceCallbacks& callbacks);

} // namespace pathcl
