#include "render/renderer.h"

#include <algorithm>
#include <chrono>

#include "cl/cl_runtime.h"
#include "common/error.h"
#include "render/compile_scene.h"
#include "render/device_arrays.h"
#include "render/film.h"
#include "render/kernel_features.h"
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

// Everything one device holds for a render.
struct DeviceRender {
    ClDevice dev;
    cl::Program program;
    cl::Kernel camera_kernel, path_kernel, clear_kernel;
    DeviceArrays arrays;
    Tile tile{8, 8};
    std::uint32_t clear_items = 64;
    std::uint32_t passes = 0; // enqueued so far (the queue is flushed every 16)
};

void check_options(const RenderOptions& opt)
{
    if (opt.width == 0 || opt.height == 0)
        throw Error("image size must be at least 1x1");
    if (opt.spp == 0)
        throw ParameterError("spp", "must be at least 1");
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
    std::uint32_t spp = 0;
    glm::dvec3 render_origin{0.0};
    CompiledScene compiled;
    RenderStats setup;
    FrameParams frame{};
    std::vector<std::unique_ptr<DeviceRender>> devices;

    Impl(const Scene& scene, const RenderOptions& opt) : options(opt)
    {
        check_options(opt);
        spp = sampler_spp(opt.sampler, opt.spp); // throws for an unknown sampler
        render_origin = scene.render_origin;
        compiled = compile_scene(scene, kernel_features(scene, opt));
        compiled.arrays.camera = {compile_camera(scene.camera, opt.width, opt.height)};
        setup.triangles = compiled.arrays.triangles.size();
        setup.lights = compiled.arrays.lights.size();
        setup.bvh_nodes = compiled.arrays.nodes.size();
        setup.bvh_build_seconds = compiled.bvh_build_seconds;
        setup.texel_bytes = compiled.texel_bytes();
        setup.kernel_from_cache = true;
        for (int index : opt.devices)
            devices.push_back(open(index));

        frame = frame_params(compiled, opt, spp);
    }

    std::unique_ptr<DeviceRender> open(int index)
    {
        auto dr = std::make_unique<DeviceRender>();
        dr->dev = open_device(index);
        ProgramSource source;
        source.patches = options.kernel_patches;
        ProgramBuild pb = build_program(dr->dev, compiled.features.define(), source);
        setup.kernel_build_seconds += pb.seconds;
        setup.kernel_from_cache = setup.kernel_from_cache && pb.from_cache;
        try {
            dr->program = pb.program;
            dr->camera_kernel = cl::Kernel(dr->program, "generate_camera_rays");
            dr->path_kernel = cl::Kernel(dr->program, "trace_paths");
            dr->clear_kernel = cl::Kernel(dr->program, "clear_film");
            dr->arrays = upload_arrays(dr->dev, compiled.arrays, pixels());
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

    // Enqueues the camera and path passes of sample indices [0, spp); logs camera rays.
    void run_passes(std::vector<CameraRayRecord>& camera_rays)
    {
        std::vector<std::uint32_t> log_xs, log_ys;
        std::vector<Ray> logged;
        if (options.ray_log_samples > 0) {
            log_xs = ray_log_axis(options.ray_log_grid, options.width);
            log_ys = ray_log_axis(options.ray_log_grid, options.height);
            logged.resize(pixels());
        }
        for (std::uint32_t s = 0; s < spp; ++s) {
            DeviceRender& dr = *devices[s % devices.size()];
            frame.sample_index = s; // the only parameter that changes from pass to pass
            const cl::NDRange global(round_up(options.width, dr.tile.x), round_up(options.height, dr.tile.y));
            const cl::NDRange local(dr.tile.x, dr.tile.y);
            bind_kernel(dr.camera_kernel, dr.arrays, frame);
            dr.dev.queue.enqueueNDRangeKernel(dr.camera_kernel, cl::NullRange, global, local);
            if (s < options.ray_log_samples) {
                // A blocking read: renders that log rays are not for timing.
                dr.dev.queue.enqueueReadBuffer(dr.arrays.rays, CL_TRUE, 0, pixels() * sizeof(Ray), logged.data());
                for (std::uint32_t y : log_ys)
                    for (std::uint32_t x : log_xs) {
                        const Ray& r = logged[static_cast<std::size_t>(y) * options.width + x];
                        camera_rays.push_back(
                            {render_to_world(render_origin, glm::dvec3(r.origin.x, r.origin.y, r.origin.z)),
                             glm::vec3(r.direction.x, r.direction.y, r.direction.z), x, y, s});
                    }
            }
            bind_kernel(dr.path_kernel, dr.arrays, frame);
            dr.dev.queue.enqueueNDRangeKernel(dr.path_kernel, cl::NullRange, global, local);
            if (++dr.passes % 16 == 0) // each device's queue starts working early
                dr.dev.queue.flush();
        }
        for (auto& dr : devices)
            dr->dev.queue.finish();
    }

    FilmSum read_films()
    {
        FilmSum sum(pixels());
        std::vector<FilmPixel> film(pixels());
        std::vector<pcl_uint> bad(pixels());
        for (auto& dr : devices) {
            dr->dev.queue.enqueueReadBuffer(dr->arrays.film, CL_TRUE, 0, pixels() * sizeof(FilmPixel), film.data());
            dr->dev.queue.enqueueReadBuffer(dr->arrays.bad_samples, CL_TRUE, 0, pixels() * sizeof(pcl_uint),
                                            bad.data());
            sum.add(film, bad);
        }
        return sum;
    }

    RenderResult render(std::uint32_t seed)
    {
        RenderResult result;
        result.stats = setup;
        frame.seed = seed;
        auto start = std::chrono::steady_clock::now();
        try {
            clear_films();
            run_passes(result.camera_rays);
        } catch (const cl::Error& e) {
            throw Error("rendering failed: " + cl_error_text(e));
        }
        FilmSum sum(0);
        try {
            sum = read_films();
        } catch (const cl::Error& e) {
            throw Error("reading the film failed: " + cl_error_text(e));
        }
        RenderStats& stats = result.stats;
        stats.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats.samples_per_second = static_cast<double>(pixels()) * spp / std::max(stats.render_seconds, 1e-9);
        stats.spp = spp;
        stats.bad_samples = sum.bad_samples();
        result.image = sum.image(options.width, options.height, spp);
        return result;
    }
};

Renderer::Renderer(const Scene& scene, const RenderOptions& options) : impl_(std::make_unique<Impl>(scene, options))
{}

Renderer::~Renderer() = default;

std::uint32_t Renderer::spp() const
{
    return impl_->spp;
}

const RenderStats& Renderer::setup_stats() const
{
    return impl_->setup;
}

RenderResult Renderer::render(std::uint32_t seed)
{
    return impl_->render(seed);
}

RenderResult Renderer::render()
{
    return impl_->render(impl_->options.seed);
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
    return frame;
}

RenderResult render(const Scene& scene, const RenderOptions& options)
{
    return Renderer(scene, options).render();
}

} // namespace pathcl
