// What a render is asked for: image size, samples, bounces, seed, strategy, sampler,
// devices and model options. The defaults are the CLI's (host/cli).
#pragma once

#include <cstdint>
#include <vector>

#include "cl/kernel_source.h"
#include "sampling/samplers.h"
#include "types.h"

namespace pathcl {

// How direct light is found (FrameParams.strategy: the STRATEGY_* values of
// kernels/types.h); every strategy converges to the same image.
enum class Strategy : std::uint32_t {
    Bsdf = STRATEGY_BSDF,            // BSDF sampling only: lights are found by chance
    Nee = STRATEGY_NEE,              // light sampling for direct light, BSDF rays for indirect
    OneSample = STRATEGY_ONE_SAMPLE, // one of {light, BSDF} per bounce, mixture-pdf weight
    Mis = STRATEGY_MIS,              // both, power heuristic
};

// "bsdf", "nee", "one-sample" or "mis".
inline const char* strategy_name(Strategy s)
{
    switch (s) {
    case Strategy::Bsdf:
        return "bsdf";
    case Strategy::Nee:
        return "nee";
    case Strategy::OneSample:
        return "one-sample";
    case Strategy::Mis:
        return "mis";
    }
    return "unknown";
}

// Which kernel features a render's program is compiled with (compile/kernel_features.h).
enum class Specialization : std::uint32_t {
    Scene, // those the scene uses: the default, and the fastest
    All,   // every scene feature, whatever the scene (for measuring what specializing saves)
};

// How next event estimation picks a light (--light-sampler).
enum class LightSampler : std::uint32_t {
    Power,   // in proportion to each light's power, wherever the shading point is (an alias table)
    Tree,    // by the light tree: power, distance and orientation at the shading point
    Uniform, // every light alike (Mitsuba 3's default; for comparisons)
    Auto,    // tree or power, by the scene's lights (compile/light_tree.h, resolve_light_sampler)
};

// "power", "tree", "uniform" or "auto".
inline const char* light_sampler_name(LightSampler s)
{
    switch (s) {
    case LightSampler::Auto:
        return "auto";
    case LightSampler::Power:
        return "power";
    case LightSampler::Tree:
        return "tree";
    case LightSampler::Uniform:
        return "uniform";
    }
    return "unknown";
}

// How an emissive triangle is sampled for next event estimation (--triangle-sampling).
enum class TriangleSampling : std::uint32_t {
    Area,       // uniformly by area
    SolidAngle, // uniformly within the solid angle it subtends, where that is large enough
    Auto,       // solid-angle where emitters light surfaces near them (compile/near_emitters.h), else area
};

// "area", "solid-angle" or "auto".
inline const char* triangle_sampling_name(TriangleSampling s)
{
    switch (s) {
    case TriangleSampling::Area:
        return "area";
    case TriangleSampling::SolidAngle:
        return "solid-angle";
    case TriangleSampling::Auto:
        return "auto";
    }
    return "unknown";
}

// How a pass is run on the device (kernels/integrator/megakernel.cl,
// kernels/wavefront/wavefront.cl); both render the same image.
enum class Integrator : std::uint32_t {
    Megakernel, // one work-item follows one path through every bounce
    Wavefront,  // one kernel per stage over all the pass's paths, shading in lanes
};

struct RenderOptions {
    std::uint32_t width = 512, height = 512;
    // Samples per pixel: the render's count, or its cap when a budget below can end it
    // sooner.
    std::uint32_t spp = 64;
    std::uint32_t max_bounces = 8; // scattering events: 0 = emission only, 1 = direct light
    std::uint32_t seed = 0;
    Strategy strategy = Strategy::Mis;
    LightSampler light_sampler = LightSampler::Auto;
    TriangleSampling triangle_sampling = TriangleSampling::Auto;
    // Owen-scrambled Sobol': the most efficient sampler on the committed scenes
    // (docs/accuracy.md, "On the committed scenes"). spp is rounded as sampler_spp() says.
    SamplerType sampler = SamplerType::Sobol;
    // The decisions of the camera and of the first stratified_bounces bounces take the
    // sampler's stratified sets; deeper bounces take independent numbers (cheaper, and
    // nearly all of stratification's gain is in the first bounce; docs/accuracy.md).
    std::uint32_t stratified_bounces = 1;
    // Rough microfacets without multiple-scattering compensation (pbrt's and Mitsuba's
    // model, for cross-checks).
    bool single_scattering = false;
    Specialization specialization = Specialization::Scene;
    Integrator integrator = Integrator::Megakernel;
    // The wavefront's paths per shading work-item (1 or 8); 0: by device kind
    // (host/render/wavefront.h).
    std::uint32_t wavefront_lanes = 0;
    // Builds with -cl-unsafe-math-optimizations (fast math without the finite-math
    // assumption, which traversal cannot take): a measured opt-in, docs/accuracy.md.
    bool fast_math = false;
    // Camera-ray log: the rays of the first ray_log_samples sample indices of the pixels
    // on an evenly spaced grid of at most ray_log_grid x ray_log_grid pixels.
    std::uint32_t ray_log_samples = 0;
    std::uint32_t ray_log_grid = 16;
    // The devices a render runs on, each taking a band of rows (render/device_bands.h):
    // the image is the same bit for bit on one or several devices of one kind.
    std::vector<int> devices{0};
    // Their initial shares of the rows (empty: equal); the render measures each device's
    // speed on its second pass and deals the rows again in proportion to it.
    std::vector<double> device_weights;

    // Batches and budgets (host/render/batches.h). A render is a run of batches, each a
    // whole point set of batch_spp samples per pixel scrambled by its own seed; the spread
    // of the batch means is the image's error estimate. 0: one batch of spp (no budget),
    // or 16 per batch with a budget.
    std::uint32_t batch_spp = 0;
    double time_budget = 0.0;  // seconds (> 0): stop after the pass that spends them
    double target_error = 0.0; // relMSE (> 0): stop once the estimate falls to it
    std::uint32_t min_spp = 0; // with target_error: never stop before (0: two batches)
    // Per-pixel adaptive sampling (needs target_error): a pixel whose estimated relMSE,
    // and its neighbours', is at most target_error takes no more samples.
    bool adaptive = false;
    // A sample range: only sample indices sample_first .. sample_first + sample_count - 1
    // of the render of spp samples (sample_count 0: the whole render). A range is made of
    // whole batches; its image carries its exact film state, and `pathcl merge` adds
    // ranges rendered apart into the whole render's image bit for bit
    // (render/partial_renders.h).
    std::uint32_t sample_first = 0, sample_count = 0;
    // Test-only: mutations of the kernel source (host/cl/kernel_source.h), for the tests
    // that prove a render test fails on a deliberately broken kernel.
    std::vector<KernelPatch> kernel_patches;
};

} // namespace pathcl
