#include "render/renderer.h"

#include <chrono>
#include <memory>

#include "cl/cl_runtime.h"
#include "common/error.h"
#include "render/device_scene.h"
#include "sampling/samplers.h"
#include "shared_types.h"

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
constexpr cl_uint kPathFrameArg = 12; // trace_paths' FrameParams argument (the texture buffers follow it)

std::uint32_t round_up(std::uint32_t v, std::uint32_t m)
{
    return (v + m - 1) / m * m;
}

// Everything one device needs for a render.
struct DeviceRender {
    ClDevice dev;
    cl::Program program;
    cl::Kernel camera_kernel, path_kernel, clear_kernel;
    cl::Buffer nodes, triangles, shading, materials, lights, env_texels, env_marginal, env_conditional, layer_albedo,
        rays, film, bad;
    cl::Buffer texels, texture_images, texture_views, texcoords, tangents, colors; // dummies when unused
    std::size_t pixels = 0;
    Tile tile{8, 8};
    std::uint32_t passes = 0; // enqueued so far (the queue is flushed every 16)

    template <typename T>
    cl::Buffer make(const std::vector<T>& data)
    {
        std::size_t bytes = std::max<std::size_t>(sizeof(T), data.size() * sizeof(T));
        cl::Buffer b(dev.context, CL_MEM_READ_ONLY, bytes);
        if (!data.empty())
            dev.queue.enqueueWriteBuffer(b, CL_TRUE, 0, data.size() * sizeof(T), data.data());
        return b;
    }
};

std::string cl_error_text(const cl::Error& e)
{
    return std::string(e.what()) + " (OpenCL error " + std::to_string(e.err()) + ")";
}

} // namespace

RenderResult render(const Scene& scene, const RenderOptions& opt)
{
    if (opt.width == 0 || opt.height == 0)
        throw Error("image size must be at least 1x1");
    if (opt.spp == 0)
        throw Error("--spp must be at least 1");
    if (opt.devices.empty())
        throw Error("no device selected");
    if (opt.strategy > STRATEGY_MIS)
        throw Error("unknown light-sampling strategy " + std::to_string(opt.strategy));
    const std::uint32_t spp = sampler_spp(opt.sampler, opt.spp); // throws for an unknown sampler

    RenderResult result;
    RenderStats& stats = result.stats;
    DeviceScene ds = make_device_scene(scene);
    stats.triangles = ds.triangles.size();
    stats.lights = ds.lights.size();
    stats.bvh_nodes = ds.nodes.size();
    stats.bvh_build_seconds = ds.bvh_build_seconds;
    stats.texel_bytes = ds.textures.texel_bytes();

    const std::size_t pixels = static_cast<std::size_t>(opt.width) * opt.height;
    Camera camera = make_device_camera(scene.camera, opt.width, opt.height);
    std::string defines = ds.features.build_defines() + " " + opt.extra_build_options;

    std::vector<std::unique_ptr<DeviceRender>> devices;
    stats.kernel_from_cache = true;
    for (int index : opt.devices) {
        auto dr = std::make_unique<DeviceRender>();
        dr->dev = open_device(index);
        ProgramBuild pb = build_program(dr->dev, defines);
        stats.kernel_build_seconds += pb.seconds;
        stats.kernel_from_cache = stats.kernel_from_cache && pb.from_cache;
        try {
            dr->program = pb.program;
            dr->camera_kernel = cl::Kernel(dr->program, "generate_camera_rays");
            dr->path_kernel = cl::Kernel(dr->program, "trace_paths");
            dr->clear_kernel = cl::Kernel(dr->program, "clear_film");
            dr->nodes = dr->make(ds.nodes);
            dr->triangles = dr->make(ds.triangles);
            dr->shading = dr->make(ds.shading);
            dr->materials = dr->make(ds.materials);
            dr->lights = dr->make(ds.lights);
            dr->env_texels = dr->make(ds.environment.texels);
            dr->env_marginal = dr->make(ds.environment.marginal_cdf);
            dr->env_conditional = dr->make(ds.environment.conditional_cdf);
            dr->layer_albedo = dr->make(ds.layer_albedo);
            dr->texels = dr->make(ds.textures.texels);
            dr->texture_images = dr->make(ds.textures.images);
            dr->texture_views = dr->make(ds.textures.views);
            dr->texcoords = dr->make(ds.textures.texcoords);
            dr->tangents = dr->make(ds.tangents);
            dr->colors = dr->make(ds.colors);
            dr->pixels = pixels;
            dr->rays = cl::Buffer(dr->dev.context, CL_MEM_READ_WRITE, pixels * sizeof(Ray));
            dr->film = cl::Buffer(dr->dev.context, CL_MEM_READ_WRITE, pixels * sizeof(FilmPixel));
            dr->bad = cl::Buffer(dr->dev.context, CL_MEM_READ_WRITE, pixels * sizeof(cl_uint));
            auto max_items = [&](const cl::Kernel& k) {
                return k.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(dr->dev.device);
            };
            dr->tile = work_group_tile(std::min(max_items(dr->camera_kernel), max_items(dr->path_kernel)));
            std::uint32_t clear_items = static_cast<std::uint32_t>(std::min<std::size_t>(64, max_items(dr->clear_kernel)));
            dr->clear_kernel.setArg(0, dr->film);
            dr->clear_kernel.setArg(1, dr->bad);
            dr->clear_kernel.setArg(2, static_cast<cl_uint>(pixels));
            dr->dev.queue.enqueueNDRangeKernel(dr->clear_kernel, cl::NullRange,
                                               cl::NDRange(round_up(static_cast<std::uint32_t>(pixels), clear_items)),
                                               cl::NDRange(clear_items));
            dr->camera_kernel.setArg(0, dr->rays);
            dr->camera_kernel.setArg(1, camera);
            int a = 0;
            dr->path_kernel.setArg(a++, dr->rays);
            dr->path_kernel.setArg(a++, dr->nodes);
            dr->path_kernel.setArg(a++, dr->triangles);
            dr->path_kernel.setArg(a++, dr->shading);
            dr->path_kernel.setArg(a++, dr->materials);
            dr->path_kernel.setArg(a++, dr->lights);
            dr->path_kernel.setArg(a++, dr->env_texels);
            dr->path_kernel.setArg(a++, dr->env_marginal);
            dr->path_kernel.setArg(a++, dr->env_conditional);
            dr->path_kernel.setArg(a++, dr->layer_albedo);
            dr->path_kernel.setArg(a++, dr->film);
            dr->path_kernel.setArg(a++, dr->bad);
            a = kPathFrameArg + 1;
            dr->path_kernel.setArg(a++, dr->texels);
            dr->path_kernel.setArg(a++, dr->texture_images);
            dr->path_kernel.setArg(a++, dr->texture_views);
            dr->path_kernel.setArg(a++, dr->texcoords);
            dr->path_kernel.setArg(a++, dr->tangents);
            dr->path_kernel.setArg(a++, dr->colors);
            dr->dev.queue.finish();
        } catch (const cl::Error& e) {
            throw Error("device " + std::to_string(index) + ": setting up the render failed: " +
                        cl_error_text(e));
        }
        devices.push_back(std::move(dr));
    }

    // Camera-ray log: pixels on an evenly spaced grid, whose rays are read back after the
    // camera pass of each logged sample index (a blocking read: renders that log rays
    // are not for timing).
    std::vector<std::uint32_t> log_xs, log_ys;
    if (opt.ray_log_samples > 0) {
        auto axis = [&](std::uint32_t size) {
            std::uint32_t n = std::min(std::max(opt.ray_log_grid, 1u), size);
            std::vector<std::uint32_t> v;
            for (std::uint32_t i = 0; i < n; ++i)
                v.push_back(static_cast<std::uint32_t>((2ull * i + 1) * size / (2ull * n)));
            return v;
        };
        log_xs = axis(opt.width);
        log_ys = axis(opt.height);
    }
    std::vector<Ray> logged(opt.ray_log_samples > 0 ? pixels : 0);
    // The pass parameters: only the sample index changes from pass to pass.
    FrameParams frame{};
    frame.width = opt.width;
    frame.height = opt.height;
    frame.seed = opt.seed;
    frame.max_bounces = opt.max_bounces;
    frame.light_count = static_cast<pcl_uint>(ds.lights.size());
    frame.strategy = opt.strategy;
    frame.sphere_count = static_cast<pcl_uint>(ds.sphere_count);
    frame.environment = ds.environment_light;
    frame.sampler = opt.sampler;
    frame.spp = spp;
    auto start = std::chrono::steady_clock::now();
    try {
        for (std::uint32_t s = 0; s < spp; ++s) {
            DeviceRender& dr = *devices[s % devices.size()];
            frame.sample_index = s;
            dr.camera_kernel.setArg(2, frame);
            dr.path_kernel.setArg(kPathFrameArg, frame);
            const cl::NDRange global(round_up(opt.width, dr.tile.x), round_up(opt.height, dr.tile.y));
            const cl::NDRange local(dr.tile.x, dr.tile.y);
            dr.dev.queue.enqueueNDRangeKernel(dr.camera_kernel, cl::NullRange, global, local);
            if (s < opt.ray_log_samples) {
                dr.dev.queue.enqueueReadBuffer(dr.rays, CL_TRUE, 0, pixels * sizeof(Ray), logged.data());
                for (std::uint32_t y : log_ys)
                    for (std::uint32_t x : log_xs) {
                        const Ray& r = logged[static_cast<std::size_t>(y) * opt.width + x];
                        result.camera_rays.push_back(
                            {glm::dvec3(r.origin.x, r.origin.y, r.origin.z) + scene.render_origin,
                             glm::vec3(r.direction.x, r.direction.y, r.direction.z), x, y, s});
                    }
            }
            dr.dev.queue.enqueueNDRangeKernel(dr.path_kernel, cl::NullRange, global, local);
            if (++dr.passes % 16 == 0) // each device's queue starts working early
                dr.dev.queue.flush();
        }
        for (auto& dr : devices)
            dr->dev.queue.finish();
    } catch (const cl::Error& e) {
        throw Error("rendering failed: " + cl_error_text(e));
    }

    // Sum the devices' films in double, then form means and per-sample variances.
    std::vector<double> sum(pixels * 4, 0.0), sum_sq(pixels * 4, 0.0);
    std::vector<FilmPixel> film(pixels);
    std::vector<cl_uint> bad(pixels);
    try {
        for (auto& dr : devices) {
            dr->dev.queue.enqueueReadBuffer(dr->film, CL_TRUE, 0, pixels * sizeof(FilmPixel), film.data());
            dr->dev.queue.enqueueReadBuffer(dr->bad, CL_TRUE, 0, pixels * sizeof(cl_uint), bad.data());
            for (std::size_t i = 0; i < pixels; ++i) {
                const FilmPixel& f = film[i];
                const float* s = &f.sum.x;
                const float* sc = &f.sum_compensation.x;
                const float* q = &f.sum_sq.x;
                const float* qc = &f.sum_sq_compensation.x;
                for (int c = 0; c < 4; ++c) {
                    sum[i * 4 + c] += static_cast<double>(s[c]) + static_cast<double>(sc[c]);
                    sum_sq[i * 4 + c] += static_cast<double>(q[c]) + static_cast<double>(qc[c]);
                }
                stats.bad_samples += bad[i];
            }
        }
    } catch (const cl::Error& e) {
        throw Error("reading the film failed: " + cl_error_text(e));
    }
    stats.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats.samples_per_second = static_cast<double>(pixels) * spp / std::max(stats.render_seconds, 1e-9);
    stats.spp = spp;

    Image& img = result.image;
    img.width = opt.width;
    img.height = opt.height;
    img.spp = spp;
    img.rgb.resize(pixels * 3);
    img.variance.resize(pixels * 3);
    for (std::size_t i = 0; i < pixels; ++i) {
        double n = sum[i * 4 + 3]; // samples actually accumulated (bad ones excluded)
        for (int c = 0; c < 3; ++c) {
            double s = sum[i * 4 + c], q = sum_sq[i * 4 + c];
            double mean = n > 0.0 ? s / n : 0.0;
            double var = n > 1.0 ? std::max(0.0, (q - s * mean) / (n - 1.0)) : 0.0;
            img.rgb[i * 3 + c] = static_cast<float>(mean);
            img.variance[i * 3 + c] = static_cast<float>(var);
        }
    }
    return result;
}

} // namespace pathcl
