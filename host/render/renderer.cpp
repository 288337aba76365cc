#include "render/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <deque>
#include <thread>

#include "cl/cl_runtime.h"
#include "common/elapsed.h"
#include "common/error.h"
#include "compile/compile_scene.h"
#include "compile/device_arrays.h"
#include "compile/kernel_features.h"
#include "compile/light_tree.h"
#include "compile/near_emitters.h"
#include "render/device_bands.h"
#include "render/film.h"
#include "render/film_channels.h"
#include "render/partial_renders.h"
#include "render/render_metadata.h"
#include "render/wavefront.h"
#include "sample/dimensions.h"
#include "sampling/samplers.h"
#include "scene/render_space.h"

namespace pathcl {
namespace {

// Work-group shape for the 2D image kernels: 8 x 8 (a multiple of every SIMD width) where
// the device allows 64 work-items for both kernels, else the largest of 8 x 4, 4 x 4,
// 4 x 2, 2 x 2, 1 x 1 it allows (a GPU can cap a kernel with a deep private stack lower).
struct Tile {
    std::uint32_t x, y;
};

Tile work_group_tile(std::size_t max_items)
{
    for (Tile t : {Tile{8, 8}, Tile{8, 4}, Tile{4, 4}, Tile{4, 2}, Tile{2, 2}})
        if (t.x * t.y <= max_items)
            return t;
    return {1, 1};
}

std::uint32_t round_up(std::uint32_t v, std::uint32_t m)
{
    return (v + m - 1) / m * m;
}

std::string cl_error_text(const cl::Error& e)
{
    return std::string(e.what()) + " (OpenCL error " + std::to_string(e.err()) + ")";
}

// When a device finished a timed pass: set by an event callback, which the driver calls
// when the device finishes (a driver that runs commands on the host thread, as PoCL's
// "basic" does, calls it as it runs them), so a device that finishes first is timed then,
// not when the host gets round to it. Shared with the callback, which may run after the
// host has stopped waiting for it (measure_pass waits a second at most): each side holds a
// reference, so a late callback never writes into freed memory.
struct PassFinish {
    std::atomic<std::int64_t> ns{-1}; // since the pass was enqueued; -1 until the callback ran
    std::chrono::steady_clock::time_point start;
};
using PassFinishes = std::vector<std::shared_ptr<PassFinish>>; // one per event of a timed pass

// Everything one device holds for a render.
struct DeviceRender {
    ClDevice dev;
    ProgramBuild build;
    cl::Kernel camera_kernel, path_kernel, clear_kernel;
    std::unique_ptr<WavefrontPass> wavefront; // --integrator wavefront: the pass's stages, instead of path_kernel
    DeviceArrays arrays;
    Tile tile{8, 8};
    std::uint32_t clear_items = 64;
    std::uint32_t y0 = 0, y1 = 0; // its band of rows (render/device_bands.h)
};

// Adaptive sampling stops no pixel before this many whole batches: the spread of fewer
// batch means is too uncertain to trust for one pixel.
constexpr std::uint32_t kMinAdaptiveBatches = 4;

using Clock = std::chrono::steady_clock;

void check_options(const RenderOptions& opt)
{
    if (opt.width == 0 || opt.height == 0)
        throw Error("image size must be at least 1x1");
    if (opt.devices.empty())
        throw Error("no device selected");
    if (static_cast<std::uint32_t>(opt.strategy) > STRATEGY_MIS)
        throw ParameterError("strategy", "unknown light-sampling strategy " +
                                             std::to_string(static_cast<std::uint32_t>(opt.strategy)));
}

// The pixels whose camera rays the ray log keeps: an evenly spaced grid.
std::vector<std::uint32_t> ray_log_axis(std::uint32_t grid, std::uint32_t size)
{
    std::uint32_t n = std::min(std::max(grid, 1u), size);
    std::vector<std::uint32_t> v;
    for (std::uint32_t i = 0; i < n; ++i)
        v.push_back(static_cast<std::uint32_t>((2ull * i + 1) * size / (2ull * n)));
    return v;
}

} // namespace

struct Renderer::Impl {
    RenderOptions options;
    BatchPlan default_plan; // of a render with the options as they are
    glm::dvec3 render_origin{0.0};
    CompiledScene compiled;
    RenderStats setup;
    FrameParams frame{};
    std::vector<std::unique_ptr<DeviceRender>> devices;
    std::vector<FilmPixel> film_readback; // read_films's host copies of one device's film
    std::vector<pcl_uint> bad_readback;

    Impl(const Scene& scene, const RenderOptions& opt) : options(opt)
    {
        options.light_sampler = resolve_light_sampler(scene, opt); // Auto decided once
        options.triangle_sampling = resolve_triangle_sampling(scene, opt);
        check_options(opt);
        default_plan = plan_batches(opt); // throws for an unknown sampler or a bad budget
        render_origin = scene.render_origin;
        compiled = compile_scene(scene, kernel_features(scene, options), options.light_sampler);
        compiled.arrays.camera = {compile_camera(scene.camera, opt.width, opt.height)};
        setup.triangles = compiled.arrays.triangles.size();
        setup.drawn_triangles = scene.drawn_triangles();
        setup.lights = compiled.arrays.lights.size();
        setup.bvh_nodes = compiled.arrays.nodes.size();
        setup.bvh_build_seconds = compiled.bvh_build_seconds;
        setup.light_tree_nodes = compiled.arrays.light_tree.size();
        setup.light_tree_depth = compiled.light_tree_depth;
        setup.light_tree_build_seconds = compiled.light_tree_build_seconds;
        setup.light_tree_bytes = compiled.arrays.light_tree.size() * sizeof(LightTreeNode) +
                                 compiled.arrays.light_tree_cluster.size() * sizeof(LightTreeClusterLight) +
                                 compiled.arrays.light_tree_trail.size() * sizeof(pcl_ulong);
        setup.texel_bytes = compiled.texel_bytes();
        setup.kernel_from_cache = true;
        check_host_memory(host_film_bytes(pixels(), opt.devices.size())); // before the devices' programs are built
        for (int index : opt.devices)
            devices.push_back(open(index));

        frame = frame_params(compiled, opt, default_plan.batch_spp);
    }

    std::unique_ptr<DeviceRender> open(int index)
    {
        auto dr = std::make_unique<DeviceRender>();
        dr->dev = open_device(index);
        check_device_memory(dr->dev, compiled.arrays, pixels()); // before the program is built
        if (options.integrator == Integrator::Wavefront)
            if (std::string why = wavefront_unsupported(compiled.features.mask); !why.empty())
                throw ParameterError("integrator", why);
        ProgramSource source;
        source.patches = options.kernel_patches;
        std::string build_options = program_build_options(compiled.features, options);
        const std::uint32_t lanes = wavefront_lanes(dr->dev.info, options.wavefront_lanes);
        if (options.integrator == Integrator::Wavefront)
            build_options += wavefront_lanes_option(lanes);
        dr->build = build_program(dr->dev, build_options, source, CacheStore::Deferred);
        setup.kernel_build_seconds += dr->build.seconds;
        setup.kernel_from_cache = setup.kernel_from_cache && dr->build.from_cache;
        try {
            const cl::Program& program = dr->build.program;
            dr->camera_kernel = cl::Kernel(program, "generate_camera_rays");
            dr->path_kernel = cl::Kernel(program, "trace_paths");
            dr->clear_kernel = cl::Kernel(program, "clear_film");
            dr->arrays = upload_arrays(dr->dev, compiled.arrays, pixels());
            if (options.integrator == Integrator::Wavefront)
                dr->wavefront = std::make_unique<WavefrontPass>(dr->dev, program, pixels(), lanes);
            auto max_items = [&](const cl::Kernel& k) {
                return k.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(dr->dev.device);
            };
            dr->tile = work_group_tile(std::min(max_items(dr->camera_kernel), max_items(dr->path_kernel)));
            dr->clear_items = static_cast<std::uint32_t>(std::min<std::size_t>(64, max_items(dr->clear_kernel)));
        } catch (const cl::Error& e) {
            throw Error("device " + std::to_string(index) + ": setting up the render failed: " + cl_error_text(e));
        }
        return dr;
    }

    std::size_t pixels() const { return static_cast<std::size_t>(options.width) * options.height; }

    void clear_films()
    {
        for (auto& dr : devices) {
            bind_kernel(dr->clear_kernel, dr->arrays, frame);
            const std::uint32_t items = round_up(static_cast<std::uint32_t>(pixels()), dr->clear_items);
            dr->dev.queue.enqueueNDRangeKernel(dr->clear_kernel, cl::NullRange, cl::NDRange(items),
                                               cl::NDRange(dr->clear_items));
        }
    }

    // Rows [y0, y1) of a device's film (sums and bad-sample counts), blocking: `film` and
    // `bad` point at the rows' first pixel. The one place film rows cross to the host and
    // back: moved between devices (set_bands), saved and restored (checkpoints).
    void read_film_rows(DeviceRender& dr, std::uint32_t y0, std::uint32_t y1, FilmPixel* film, pcl_uint* bad)
    {
        const std::size_t first = std::size_t(y0) * options.width, count = std::size_t(y1 - y0) * options.width;
        dr.dev.queue.enqueueReadBuffer(dr.arrays.film, CL_TRUE, first * sizeof(FilmPixel), count * sizeof(FilmPixel),
                                       film);
        dr.dev.queue.enqueueReadBuffer(dr.arrays.bad_samples, CL_TRUE, first * sizeof(pcl_uint),
                                       count * sizeof(pcl_uint), bad);
    }

    void write_film_rows(DeviceRender& dr, std::uint32_t y0, std::uint32_t y1, const FilmPixel* film,
                         const pcl_uint* bad)
    {
        const std::size_t first = std::size_t(y0) * options.width, count = std::size_t(y1 - y0) * options.width;
        dr.dev.queue.enqueueWriteBuffer(dr.arrays.film, CL_TRUE, first * sizeof(FilmPixel), count * sizeof(FilmPixel),
                                        film);
        dr.dev.queue.enqueueWriteBuffer(dr.arrays.bad_samples, CL_TRUE, first * sizeof(pcl_uint),
                                        count * sizeof(pcl_uint), bad);
    }

    // Deals the rows to the devices in proportion to `weights` (render/device_bands.h). With
    // move_films, the film rows (sums and bad-sample counts) of the batch in progress move:
    // read from the old owner, written to the new one and zeroed at the old one, so every
    // pixel's compensated sums continue exactly where they were.
    void set_bands(const std::vector<double>& weights, bool move_films)
    {
        const std::vector<std::uint32_t> b = band_bounds(options.height, devices.size(), weights);
        auto owner = [&](std::uint32_t y, bool old_bands) {
            for (std::size_t d = 0; d < devices.size(); ++d) {
                const std::uint32_t lo = old_bands ? devices[d]->y0 : b[d], hi = old_bands ? devices[d]->y1 : b[d + 1];
                if (y >= lo && y < hi)
                    return d;
            }
            return devices.size();
        };
        for (std::uint32_t y = 0; move_films && y < options.height;) {
            const std::size_t from = owner(y, true), to = owner(y, false);
            std::uint32_t end = y + 1;
            while (end < options.height && owner(end, true) == from && owner(end, false) == to)
                ++end;
            if (from != to && from < devices.size() && to < devices.size()) {
                const std::size_t count = std::size_t(end - y) * options.width;
                std::vector<FilmPixel> film(count);
                std::vector<pcl_uint> bad(count);
                read_film_rows(*devices[from], y, end, film.data(), bad.data());
                write_film_rows(*devices[to], y, end, film.data(), bad.data());
                std::fill(film.begin(), film.end(), FilmPixel{});
                std::fill(bad.begin(), bad.end(), 0u);
                write_film_rows(*devices[from], y, end, film.data(), bad.data());
            }
            y = end;
        }
        for (std::size_t d = 0; d < devices.size(); ++d) {
            devices[d]->y0 = b[d];
            devices[d]->y1 = b[d + 1];
        }
    }

    // Enqueues the camera and path passes of sample index s of the current batch on every
    // device, each over its band; `done` receives one event per device that has rows, each
    // signalling its path pass's end. Logs the camera rays of batch 0's first sample
    // indices.
    void enqueue_pass(std::uint32_t batch, std::uint32_t s, std::vector<cl::Event>& done,
                      std::vector<CameraRayRecord>& camera_rays, PassFinishes* finish = nullptr)
    {
        const auto start = Clock::now();
        frame.sample_index = s; // with the seed, the only parameters that change from pass to pass
        // Work-item row 0 is the band's first row (kernels/film/pixel.cl).
        auto launch = [&](DeviceRender& dr, cl::Kernel& kernel, cl::Event* event) {
            frame.first_row = dr.y0;
            const cl::NDRange global(round_up(options.width, dr.tile.x), round_up(dr.y1 - dr.y0, dr.tile.y));
            bind_kernel(kernel, dr.arrays, frame);
            dr.dev.queue.enqueueNDRangeKernel(kernel, cl::NullRange, global, cl::NDRange(dr.tile.x, dr.tile.y), nullptr,
                                              event);
        };
        for (auto& dr : devices)
            if (dr->y1 > dr->y0)
                launch(*dr, dr->camera_kernel, nullptr);
        if (batch == 0 && s < options.ray_log_samples)
            log_camera_rays(s, camera_rays);
        for (auto& dr : devices) {
            if (dr->y1 <= dr->y0)
                continue;
            done.emplace_back();
            if (dr->wavefront) {
                frame.first_row = dr->y0;
                dr->wavefront->enqueue(dr->dev.queue, dr->arrays, frame, (dr->y1 - dr->y0) * options.width,
                                       &done.back());
            } else {
                launch(*dr, dr->path_kernel, &done.back());
            }
            if (finish) { // timed: the callback is set before the flush, which may run the pass
                finish->push_back(std::make_shared<PassFinish>());
                finish->back()->start = start;
                // The callback's own reference, released by the callback.
                auto keep = std::make_unique<std::shared_ptr<PassFinish>>(finish->back());
                done.back().setCallback(
                    CL_COMPLETE,
                    [](cl_event, cl_int, void* data) {
                        std::unique_ptr<std::shared_ptr<PassFinish>> pf(
                            static_cast<std::shared_ptr<PassFinish>*>(data));
                        (*pf)->ns.store(
                            std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - (*pf)->start).count());
                    },
                    keep.get());
                keep.release(); // the callback owns it now
            }
            dr->dev.queue.flush(); // the device starts at once; the host waits on `done` later
        }
    }

    // Each device's rows per second over the pass just enqueued with `finish` (an entry
    // per device with rows, in device order, as `done` has its events).
    std::vector<double> measure_pass(std::vector<cl::Event>& done, const PassFinishes& finish)
    {
        for (cl::Event& e : done)
            e.wait(); // reports an error status as cl::Error
        // The callbacks may still be running when the waits return (OpenCL leaves that
        // open); one that never comes within a second leaves its device untimed (rate 0:
        // an empty band, which costs speed, not correctness).
        const auto deadline = Clock::now() + std::chrono::seconds(1);
        for (std::size_t e = 0; e < done.size(); ++e)
            while (finish[e]->ns.load() < 0 && Clock::now() < deadline)
                std::this_thread::yield();
        std::vector<double> rate(devices.size(), 0.0);
        std::size_t e = 0;
        for (std::size_t d = 0; d < devices.size(); ++d) {
            if (devices[d]->y1 <= devices[d]->y0)
                continue;
            const std::int64_t ns = finish[e++]->ns.load();
            if (ns >= 0)
                rate[d] = (devices[d]->y1 - devices[d]->y0) / std::max(1e-9 * static_cast<double>(ns), 1e-9);
        }
        return rate;
    }

    // A blocking read: renders that log rays are not for timing. Each pixel's ray is on the
    // device whose band holds its row.
    void log_camera_rays(std::uint32_t s, std::vector<CameraRayRecord>& camera_rays)
    {
        std::vector<std::vector<Ray>> rays(devices.size());
        for (std::size_t d = 0; d < devices.size(); ++d) {
            if (devices[d]->y1 <= devices[d]->y0)
                continue;
            rays[d].resize(pixels());
            devices[d]->dev.queue.enqueueReadBuffer(devices[d]->arrays.rays, CL_TRUE, 0, pixels() * sizeof(Ray),
                                                    rays[d].data());
        }
        for (std::uint32_t y : ray_log_axis(options.ray_log_grid, options.height))
            for (std::uint32_t x : ray_log_axis(options.ray_log_grid, options.width)) {
                std::size_t d = 0;
                while (d + 1 < devices.size() && !(y >= devices[d]->y0 && y < devices[d]->y1))
                    ++d;
                const Ray& r = rays[d][static_cast<std::size_t>(y) * options.width + x];
                camera_rays.push_back({render_to_world(render_origin, glm::dvec3(r.origin.x, r.origin.y, r.origin.z)),
                                       glm::vec3(r.direction.x, r.direction.y, r.direction.z), x, y, s});
            }
    }

    FilmSum read_films()
    {
        FilmSum sum(pixels());
        // Kept from batch to batch and render to render: a fresh 68 bytes a pixel would
        // be page-faulted in again by the read, on one thread.
        film_readback.resize(pixels());
        bad_readback.resize(pixels());
        for (auto& dr : devices) {
            dr->dev.queue.enqueueReadBuffer(dr->arrays.film, CL_TRUE, 0, pixels() * sizeof(FilmPixel),
                                            film_readback.data());
            dr->dev.queue.enqueueReadBuffer(dr->arrays.bad_samples, CL_TRUE, 0, pixels() * sizeof(pcl_uint),
                                            bad_readback.data());
            sum.add(film_readback, bad_readback);
        }
        return sum;
    }

    void upload_active(const std::vector<pcl_uint>& active)
    {
        for (auto& dr : devices)
            dr->dev.queue.enqueueWriteBuffer(dr->arrays.active, CL_TRUE, 0, pixels() * sizeof(pcl_uint), active.data());
    }

    // Adaptive sampling after a whole batch: a pixel stops when its estimated relMSE and
    // that of each of its 3 x 3 neighbours is at most the target (the neighbourhood keeps
    // a pixel whose few batch means happen to agree from stopping alone). Returns the
    // pixels still active.
    std::size_t update_active(const FilmAccumulator& acc, double target, std::vector<pcl_uint>& active)
    {
        const std::uint32_t w = options.width, h = options.height;
        std::vector<double> e(pixels());
        for (std::size_t i = 0; i < e.size(); ++i) {
            double v = acc.pixel_relmse_estimate(i);
            e[i] = v < 0.0 ? INFINITY : v;
        }
        std::size_t remaining = 0;
        for (std::uint32_t y = 0; y < h; ++y)
            for (std::uint32_t x = 0; x < w; ++x) {
                std::size_t i = static_cast<std::size_t>(y) * w + x;
                if (!active[i])
                    continue;
                double worst = 0.0;
                for (std::uint32_t ny = (y > 0 ? y - 1 : 0); ny <= std::min(y + 1, h - 1); ++ny)
                    for (std::uint32_t nx = (x > 0 ? x - 1 : 0); nx <= std::min(x + 1, w - 1); ++nx)
                        worst = std::max(worst, e[static_cast<std::size_t>(ny) * w + nx]);
                if (worst <= target)
                    active[i] = 0;
                else
                    ++remaining;
            }
        upload_active(active);
        return remaining;
    }

    // Everything a render's image depends on besides the scene and which of its samples
    // are taken: sample ranges of one render carry the same key (render/partial_renders.h).
    std::string render_key(const RenderRun& run, const RenderOptions& opt, const BatchPlan& plan) const
    {
        std::string key =
            "scene " + run.scene_key + "; size " + std::to_string(opt.width) + "x" + std::to_string(opt.height) +
            "; seed " + std::to_string(run.seed) + "; sampler " + sampler_name(opt.sampler) + "; strategy " +
            strategy_name(opt.strategy) + "; bounces " + std::to_string(opt.max_bounces) + "; stratified bounces " +
            std::to_string(opt.stratified_bounces) + "; batch spp " + std::to_string(plan.batch_spp) + "; spp " +
            std::to_string(plan.max_spp) + "; options " + std::to_string(opt.single_scattering) +
            std::to_string(opt.fast_math) + std::to_string(static_cast<int>(opt.specialization)) +
            std::to_string(opt.adaptive) + "; sample layout " + std::to_string(DIM_LAYOUT_VERSION);
        // Named only when not the default, so that the keys of earlier renders stay valid.
        // The integrators' images agree to rounding, not bit for bit: ranges of one do not
        // merge with ranges of the other.
        if (opt.integrator == Integrator::Wavefront)
            key += "; integrator wavefront";
        if (opt.light_sampler != LightSampler::Power)
            key += std::string("; light sampler ") + light_sampler_name(opt.light_sampler);
        if (compiled.features.has(FEATURE_SOLID_ANGLE_TRIANGLES)) // a scene without emissive triangles: no change
            key += "; triangle sampling solid-angle";
        return key;
    }

    // And what a checkpoint must match besides: the range and the devices.
    std::string checkpoint_key(const RenderRun& run, const RenderOptions& opt, const BatchPlan& plan) const
    {
        std::string key = render_key(run, opt, plan) + "; samples " + std::to_string(plan.first_spp) + " to " +
                          std::to_string(plan.end_spp) + "; devices";
        for (const auto& dr : devices)
            key += " " + dr->dev.info.name;
        return key;
    }

    RenderCheckpoint capture(const std::string& key, std::uint32_t batch, std::uint32_t pass, std::uint32_t spp_done,
                             double samples, const FilmAccumulator& acc, const std::vector<pcl_uint>& active)
    {
        RenderCheckpoint cp;
        cp.key = key;
        cp.batch = batch;
        cp.pass = pass;
        cp.spp_done = spp_done;
        cp.samples = samples;
        cp.film = acc.state();
        cp.active = active;
        // One film, each row from the device whose band holds it: a checkpoint does not
        // depend on how the rows were dealt.
        cp.device_films.emplace_back(pixels());
        cp.device_bad.emplace_back(pixels());
        for (auto& dr : devices) {
            const std::size_t first = std::size_t(dr->y0) * options.width;
            if (dr->y1 > dr->y0)
                read_film_rows(*dr, dr->y0, dr->y1, cp.device_films[0].data() + first, cp.device_bad[0].data() + first);
        }
        return cp;
    }

    // The film of the batch in progress as the checkpoint holds it, each device given the
    // rows of its band (the others stay cleared).
    void upload_films(const RenderCheckpoint& cp)
    {
        if (cp.device_films.size() != 1 || cp.device_films[0].size() != pixels() || cp.device_bad[0].size() != pixels())
            throw Error("the checkpoint's film does not match the image size");
        clear_films();
        for (auto& dr : devices) {
            const std::size_t first = std::size_t(dr->y0) * options.width;
            if (dr->y1 > dr->y0)
                write_film_rows(*dr, dr->y0, dr->y1, cp.device_films[0].data() + first,
                                cp.device_bad[0].data() + first);
        }
    }

    RenderResult render(const RenderRun& run)
    {
        // This render's options and layout: the Renderer's, with the run's overrides.
        RenderOptions opt = options;
        if (run.spp > 0)
            opt.spp = run.spp;
        if (run.target_error >= 0.0)
            opt.target_error = run.target_error;
        const BatchPlan plan = run.spp > 0 || run.target_error >= 0.0 ? plan_batches(opt) : default_plan;
        frame.spp = plan.batch_spp;
        const std::uint32_t seed = run.seed;
        const ProgressCallback& progress = run.progress;
        RenderResult result;
        RenderStats& stats = result.stats;
        stats = setup;
        FilmAccumulator acc(pixels(), plan.batch_spp);
        std::vector<pcl_uint> active;
        std::size_t active_pixels = pixels();
        StopReason reason = StopReason::Spp;
        bool stop = false;
        std::uint32_t spp_done = 0; // sample indices per pixel finished
        double samples = 0.0;       // camera samples finished
        double estimate = -1.0;     // after the last whole batch
        // Passes in flight (each on every device): two under a time budget (it ends within
        // one pass), else enough to keep every device busy while the host waits.
        const std::size_t window = opt.time_budget > 0.0 ? 2 : 8;
        const auto start = Clock::now();
        const bool checkpoints = static_cast<bool>(run.checkpoint);
        std::string key;
        if (checkpoints || run.resume)
            key = checkpoint_key(run, opt, plan);
        std::uint32_t first_batch = plan.first_batch(), first_pass = 0;
        if (plan.ranged && run.scene_key.empty())
            throw Error("internal error: a sample range needs the scene's key (RenderRun::scene_key)");
        if (run.resume) {
            const RenderCheckpoint& cp = *run.resume;
            if (cp.key != key)
                throw ParameterError("resume", "the checkpoint is of another render: " + key_difference(cp.key, key));
            check_checkpoint(cp, plan, pixels(), opt.adaptive);
            acc.restore(cp.film);
            first_batch = cp.batch;
            first_pass = cp.pass;
            spp_done = cp.spp_done;
            if (acc.batches() >= 2)
                estimate = acc.relmse_estimate();
        }
        const std::uint32_t spp_at_start = spp_done;

        auto report = [&]() {
            RenderProgress p;
            p.spp = spp_done;
            p.max_spp = plan.end_spp - plan.first_spp;
            p.batches = acc.batches();
            p.elapsed_seconds = seconds_since(start);
            p.samples_per_second = samples / std::max(p.elapsed_seconds, 1e-9);
            p.error_estimate = estimate;
            double pass_rate = (spp_done - spp_at_start) / std::max(p.elapsed_seconds, 1e-9);
            double to_go = p.max_spp - spp_done;
            if (opt.target_error > 0.0 && estimate > 0.0) // relMSE falls as 1 / spp
                to_go = std::min(to_go, std::max(0.0, spp_done * (estimate / opt.target_error - 1.0)));
            const bool awaiting_estimate = opt.target_error > 0.0 && estimate < 0.0;
            if (spp_done > 0 && !awaiting_estimate)
                p.eta_seconds = to_go / pass_rate;
            if (opt.time_budget > 0.0)
                p.eta_seconds = std::max(
                    0.0, std::min(p.eta_seconds < 0.0 ? INFINITY : p.eta_seconds, opt.time_budget - p.elapsed_seconds));
            return p;
        };
        // After each finished pass: the time budget, and the caller's wish to stop.
        auto after_pass = [&]() {
            ++spp_done;
            samples += static_cast<double>(active_pixels);
            if (opt.time_budget > 0.0 && seconds_since(start) >= opt.time_budget && !stop) {
                stop = true;
                reason = StopReason::Time;
            }
            if (progress && !progress(report()) && !stop) {
                stop = true;
                reason = StopReason::Interrupted;
            }
        };

        try {
            frame.adaptive = opt.adaptive ? 1u : 0u;
            if (opt.adaptive) {
                active.assign(pixels(), 1u);
                if (run.resume) {
                    active = run.resume->active;
                    active_pixels = static_cast<std::size_t>(std::count(active.begin(), active.end(), 1u));
                }
                upload_active(active);
            }
            set_bands(opt.device_weights, /*move_films=*/false);
            if (first_pass > 0)
                upload_films(*run.resume);
            else
                clear_films();
            // Passes in flight, each one event per device with rows.
            std::deque<std::vector<cl::Event>> in_flight;
            auto finish_oldest = [&]() {
                for (cl::Event& e : in_flight.front())
                    e.wait();
                in_flight.pop_front();
                after_pass();
            };
            auto drain = [&]() {
                while (!in_flight.empty())
                    finish_oldest();
            };
            // With several devices the render's second pass is timed alone (the first
            // also builds PoCL's work-group functions) and the rows dealt again in
            // proportion to each device's speed.
            std::uint32_t passes_enqueued = 0;
            const bool balance = devices.size() > 1;
            for (std::uint32_t b = first_batch; b < plan.batch_count() && !stop; ++b) {
                frame.seed = batch_seed(seed, b);
                const std::uint32_t passes = plan.batch_passes(b);
                std::uint32_t s = b == first_batch ? first_pass : 0;
                for (; s < passes && !stop; ++s) {
                    if (checkpoints && run.checkpoint_due && run.checkpoint_due()) {
                        drain();
                        run.checkpoint(capture(key, b, s, spp_done, samples, acc, active));
                        if (stop)
                            break;
                    }
                    if (balance && passes_enqueued == 1) {
                        drain();
                        std::vector<cl::Event> done;
                        PassFinishes finish;
                        enqueue_pass(b, s, done, result.camera_rays, &finish);
                        const std::vector<double> rates = measure_pass(done, finish);
                        after_pass();
                        set_bands(rates, /*move_films=*/true);
                        ++passes_enqueued;
                        continue;
                    }
                    in_flight.emplace_back();
                    enqueue_pass(b, s, in_flight.back(), result.camera_rays);
                    ++passes_enqueued;
                    while (in_flight.size() > window)
                        finish_oldest();
                }
                drain();
                auto film_start = Clock::now();
                FilmSum sum = read_films();
                stats.film_seconds += seconds_since(film_start);
                if (s < passes) {
                    if (checkpoints) // stopped early: the state to resume from
                        run.checkpoint(capture(key, b, s, spp_done, samples, acc, active));
                    film_start = Clock::now();
                    acc.add_partial_batch(sum);
                    stats.film_seconds += seconds_since(film_start);
                    break;
                }
                film_start = Clock::now();
                acc.add_batch(sum);
                stats.film_seconds += seconds_since(film_start);
                if (checkpoints && stop && b + 1 < plan.batch_count()) {
                    clear_films();
                    run.checkpoint(capture(key, b + 1, 0, spp_done, samples, acc, active));
                }
                if (b + 1 < plan.batch_count())
                    clear_films();
                if (acc.batches() >= 2)
                    estimate = acc.relmse_estimate();
                if (stop)
                    break;
                if (opt.target_error > 0.0 && spp_done >= plan.min_spp && estimate >= 0.0 &&
                    estimate <= opt.target_error) {
                    reason = StopReason::TargetError;
                    break;
                }
                if (opt.adaptive && acc.batches() >= kMinAdaptiveBatches && spp_done >= plan.min_spp) {
                    active_pixels = update_active(acc, opt.target_error, active);
                    if (active_pixels == 0) {
                        reason = StopReason::TargetError;
                        break;
                    }
                }
                if (progress && !progress(report())) {
                    reason = StopReason::Interrupted;
                    break;
                }
            }
        } catch (const cl::Error& e) {
            throw Error("rendering failed: " + cl_error_text(e));
        }
        stats.render_seconds = seconds_since(start);
        stats.samples_per_second = samples / std::max(stats.render_seconds, 1e-9);
        stats.spp = spp_done;
        stats.batch_spp = plan.batch_spp;
        stats.batches = acc.batches();
        stats.stop = reason;
        stats.bad_samples = acc.bad_samples();
        const ErrorEstimate error = estimate_error(acc, opt.sampler);
        stats.error_estimate = error.relmse;
        stats.error_is_bound = error.is_bound;
        result.image = acc.image(options.width, options.height, spp_done);
        if (opt.adaptive)
            result.image.samples = acc.pixel_samples();
        describe_render({reason, seed, opt.sampler, plan.batch_spp}, acc, error, result.image);
        if (plan.ranged) { // what `pathcl merge` needs
            store_film_state(acc.state(), result.image);
            auto& meta = result.image.metadata;
            meta["render_key"] = render_key(run, opt, plan);
            meta["sample_ranges"] = format_sample_ranges({{plan.first_spp, plan.end_spp - plan.first_spp}});
            meta["spp_total"] = std::to_string(plan.max_spp);
        }
        return result;
    }
};

Renderer::Renderer(const Scene& scene, const RenderOptions& options) : impl_(std::make_unique<Impl>(scene, options))
{}

Renderer::~Renderer()
{
    store_programs();
}

void Renderer::store_programs() noexcept
{
    for (auto& dr : impl_->devices)
        store_pending_program(dr->build);
}

std::uint32_t Renderer::spp() const
{
    return impl_->default_plan.max_spp;
}

const BatchPlan& Renderer::plan() const
{
    return impl_->default_plan;
}

const RenderStats& Renderer::setup_stats() const
{
    return impl_->setup;
}

const RenderOptions& Renderer::options() const
{
    return impl_->options;
}

RenderResult Renderer::render(const RenderRun& run)
{
    return impl_->render(run);
}

RenderResult Renderer::render(std::uint32_t seed, const ProgressCallback& progress)
{
    RenderRun run;
    run.seed = seed;
    run.progress = progress;
    return impl_->render(run);
}

RenderResult Renderer::render()
{
    return render(impl_->options.seed);
}

FrameParams frame_params(const CompiledScene& compiled, const RenderOptions& opt, std::uint32_t spp)
{
    FrameParams frame{};
    frame.width = opt.width;
    frame.height = opt.height;
    frame.seed = opt.seed;
    frame.max_bounces = opt.max_bounces;
    frame.light_count = static_cast<pcl_uint>(compiled.arrays.lights.size());
    frame.strategy = static_cast<pcl_uint>(opt.strategy);
    frame.sphere_count = static_cast<pcl_uint>(compiled.sphere_count);
    frame.environment = compiled.environment_light;
    frame.sampler = static_cast<pcl_uint>(opt.sampler);
    frame.spp = spp;
    // DIM_PATH_START + bounces * DIMS_PER_BOUNCE, saturated: "all bounces" is any number
    // at least max_bounces.
    std::uint64_t dims = DIM_PATH_START + static_cast<std::uint64_t>(opt.stratified_bounces) * DIMS_PER_BOUNCE;
    frame.stratified_dims = static_cast<pcl_uint>(std::min<std::uint64_t>(dims, 0xffffffffu));
    frame.infinite_pick = static_cast<float>(compiled.infinite_pick);
    frame.infinite_count = static_cast<pcl_uint>(compiled.arrays.light_tree_infinite.size());
    return frame;
}

RenderResult render(const Scene& scene, const RenderOptions& options)
{
    return Renderer(scene, options).render();
}

} // namespace pathcl
