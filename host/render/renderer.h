// Renders a scene on one or more OpenCL devices. A Renderer owns what a render needs and
// keeps it between renders: the compiled scene uploaded to every device, the program
// built for the scene's features, and the films. A render is a run of batches
// (render/batches.h); a batch is a run of passes (one camera pass and one path pass per
// sample index, dealt round-robin to the devices), after which the devices' films are
// read, added to the image and cleared. Between passes the render reports progress and
// checks its budget; between batches it estimates its error.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "render/batches.h"
#include "render/checkpoint.h"
#include "render/render_options.h"
#include "scene/scene.h"

namespace pathcl {

struct CompiledScene;

struct RenderStats {
    std::size_t triangles = 0, lights = 0, bvh_nodes = 0; // triangles stored (each instanced mesh once)
    std::size_t drawn_triangles = 0;                      // instances' included
    double bvh_build_seconds = 0.0;
    // --light-sampler tree: the tree's eight-wide nodes, levels, build time and device bytes
    std::size_t light_tree_nodes = 0;
    std::uint32_t light_tree_depth = 0;
    double light_tree_build_seconds = 0.0;
    std::size_t light_tree_bytes = 0;
    double kernel_build_seconds = 0.0; // summed over devices
    bool kernel_from_cache = false;    // every device's program came from the cache
    double render_seconds = 0.0;       // passes only, from first enqueue to finished films
    double film_seconds = 0.0;         // of render_seconds: films read back and added (below)
    double samples_per_second = 0.0;   // camera samples (paths) per second
    std::uint64_t bad_samples = 0;     // NaN/Inf samples the film rejected
    std::size_t texel_bytes = 0;       // device memory of all texture images (per device)
    std::uint32_t spp = 0;             // samples per pixel taken (the sampler may round up)
    std::uint32_t batch_spp = 0;       // samples per whole batch
    std::uint32_t batches = 0;         // whole batches taken
    StopReason stop = StopReason::Spp;
    // The image's estimated relMSE (FilmAccumulator): from the spread of the batch means
    // with two whole batches or more, else from the per-sample variance (an upper bound
    // but for the independent sampler: error_is_bound). Negative: none.
    double error_estimate = -1.0;
    bool error_is_bound = false;
    // film_seconds is host work while the devices wait (read_films, FilmAccumulator): on
    // one core about 0.15 s a million pixels, over a third of an H200's 0.42 s for 64
    // samples of those pixels (docs/gpu.md); it runs on every core (common/parallel.h).
};

// What a render reports after every finished pass.
struct RenderProgress {
    std::uint32_t spp = 0, max_spp = 0; // sample indices done per pixel, and at most
    std::uint32_t batches = 0;          // whole batches done
    double elapsed_seconds = 0.0;
    double samples_per_second = 0.0; // camera samples (paths) per second so far
    double eta_seconds = -1.0;       // negative: unknown
    double error_estimate = -1.0;    // relMSE from the batches so far; negative: none yet
};
// Returns false to stop the render after the passes in flight (StopReason::Interrupted).
using ProgressCallback = std::function<bool(const RenderProgress&)>;

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

// One render of a Renderer: its seed, what may change from one render to the next, and
// the progress callback.
struct RenderRun {
    std::uint32_t seed = 0;
    std::uint32_t spp = 0;      // > 0: instead of the options' (e.g. a convergence ladder)
    double target_error = -1.0; // >= 0: instead of the options' (0: none)
    ProgressCallback progress;
    // Checkpoints (render/checkpoint.h). With `checkpoint` set, the render drains its
    // passes and hands over its state whenever `checkpoint_due` says so at a pass
    // boundary, and once more when a budget or the caller stopped it early. `resume`
    // continues such a state. `scene_key` names the scene (its fingerprint) in the key,
    // and in the render key of a sample range's image (RenderOptions::sample_count).
    std::function<bool()> checkpoint_due;
    std::function<void(const RenderCheckpoint&)> checkpoint;
    const RenderCheckpoint* resume = nullptr;
    std::string scene_key;
};

class Renderer {
public:
    // Compiles the scene, opens the devices, builds (or loads) the program and uploads
    // everything; throws pathcl::Error for bad options or a failing device.
    Renderer(const Scene& scene, const RenderOptions& options);
    ~Renderer(); // stores the programs (store_programs)
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // The samples per pixel of a whole render (options.spp, rounded up by the sampler for
    // one batch), the most a budgeted render takes.
    std::uint32_t spp() const;
    const BatchPlan& plan() const;
    // Figures of the setup (scene size, BVH and kernel build times).
    const RenderStats& setup_stats() const;
    // The options as rendered: auto light and triangle sampling resolved for the scene.
    const RenderOptions& options() const;

    // A render with this seed: runs batches until the plan's samples are taken or a budget
    // or `progress` ends it, and forms the image with its metadata.
    RenderResult render(const RenderRun& run);
    RenderResult render(std::uint32_t seed, const ProgressCallback& progress = {});
    RenderResult render(); // with the options' seed

    // Stores the programs this renderer compiled in pathcl's binary cache. They are built
    // with CacheStore::Deferred so that a cold render can write its image first; the
    // destructor stores them for a caller that does not. Never throws.
    void store_programs() noexcept;

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
