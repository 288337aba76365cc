// Renders a scene on one or more OpenCL devices: uploads the device scene, builds the
// program for the scene's features, runs one camera pass and one path pass per sample
// index (sample indices dealt round-robin to the devices), and sums the devices' films.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"

namespace pathcl {

struct RenderOptions {
    std::uint32_t width = 512, height = 512;
    std::uint32_t spp = 64;
    std::uint32_t max_bounces = 8; // scattering events: 0 = emission only, 1 = direct light
    std::uint32_t seed = 0;
    std::uint32_t strategy = 3; // STRATEGY_MIS; see kernels/shared_types.h
    std::uint32_t sampler = 0;  // SAMPLER_INDEPENDENT; spp is rounded as sampler_spp() says
    // Camera-ray log (--ray-log): the rays of the first ray_log_samples sample indices of
    // the pixels on an evenly spaced grid of at most ray_log_grid x ray_log_grid pixels.
    std::uint32_t ray_log_samples = 0;
    std::uint32_t ray_log_grid = 16;
    std::vector<int> devices{0};
    std::string extra_build_options; // appended to the feature defines (tests, opt-ins)
};

struct RenderStats {
    std::size_t triangles = 0, lights = 0, bvh_nodes = 0;
    double bvh_build_seconds = 0.0;
    double kernel_build_seconds = 0.0; // summed over devices
    bool kernel_from_cache = false;    // every device's program came from the cache
    double render_seconds = 0.0;       // passes only, from first enqueue to finished films
    double samples_per_second = 0.0;   // camera samples (paths) per second
    std::uint64_t bad_samples = 0;     // NaN/Inf samples the film rejected
    std::size_t texel_bytes = 0;       // device memory of all texture images (per device)
    std::uint32_t spp = 0;             // samples per pixel taken (the sampler may round up)
};

// One logged camera ray, in world space.
struct CameraRayRecord {
    glm::dvec3 origin;
    glm::vec3 direction; // unit
    std::uint32_t x, y, sample;
};

struct RenderResult {
    Image image;
    RenderStats stats;
    std::vector<CameraRayRecord> camera_rays; // RenderOptions::ray_log_samples > 0
};

RenderResult render(const Scene& scene, const RenderOptions& options);

} // namespace pathcl
