// What a render is asked for: image size, samples, bounces, seed, strategy, sampler,
// devices and model options. The defaults are the CLI's (host/cli).
#pragma once

#include <cstdint>
#include <vector>

#include "cl/kernel_source.h"
#include "types.h"

namespace pathcl {

struct RenderOptions {
    std::uint32_t width = 512, height = 512;
    std::uint32_t spp = 64;
    std::uint32_t max_bounces = 8; // scattering events: 0 = emission only, 1 = direct light
    std::uint32_t seed = 0;
    std::uint32_t strategy = STRATEGY_MIS;
    std::uint32_t sampler = SAMPLER_INDEPENDENT; // spp is rounded as sampler_spp() says
    // Rough microfacets without multiple-scattering compensation (pbrt's and Mitsuba's
    // model, for cross-checks).
    bool single_scattering = false;
    // Camera-ray log: the rays of the first ray_log_samples sample indices of the pixels
    // on an evenly spaced grid of at most ray_log_grid x ray_log_grid pixels.
    std::uint32_t ray_log_samples = 0;
    std::uint32_t ray_log_grid = 16;
    std::vector<int> devices{0};
    // Test-only: mutations of the kernel source (host/cl/kernel_source.h), for the tests
    // that prove a render test fails on a deliberately broken kernel.
    std::vector<KernelPatch> kernel_patches;
};

} // namespace pathcl
