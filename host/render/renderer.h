// Renders a scene on one or more OpenCL devices. A Renderer owns what a render needs and
// keeps it between renders: the compiled scene uploaded to every device, the program
// built for the scene's features, and the films. It runs passes (one camera pass and one
// path pass per sample index, sample indices dealt round-robin to the devices) and forms
// the image from the devices' films, summed.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "render/render_options.h"
#include "scene/scene.h"

namespace pathcl {

struct CompiledScene;

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

class Renderer {
public:
    // Compiles the scene, opens the devices, builds (or loads) the program and uploads
    // everything; throws pathcl::Error for bad options or a failing device.
    Renderer(const Scene& scene, const RenderOptions& options);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // The samples per pixel of a whole render (options.spp, rounded up by the sampler).
    std::uint32_t spp() const;
    // Figures of the setup (scene size, BVH and kernel build times).
    const RenderStats& setup_stats() const;

    // A whole render with this seed: clears the films, runs every sample index, and
    // forms the image.
    RenderResult render(std::uint32_t seed);
    RenderResult render();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The pass parameters of a render (all but the sample index) of `compiled` with `options`
// and `spp` samples per pixel (after the sampler's rounding).
FrameParams frame_params(const CompiledScene& compiled, const RenderOptions& options, std::uint32_t spp);

// Renderer(scene, options).render(): a one-off render.
RenderResult render(const Scene& scene, const RenderOptions& options);

} // namespace pathcl
