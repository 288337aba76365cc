#include "bench/kernel_bench.h"

#include "compile/light_tree.h"

#include <algorithm>
#include <chrono>
#include <functional>

#include "cl/cl_runtime.h"
#include "common/elapsed.h"
#include "common/error.h"
#include "compile/compile_scene.h"
#include "compile/device_arrays.h"
#include "compile/kernel_features.h"
#include "render/renderer.h"
#include "sampling/samplers.h"

namespace pathcl {
namespace {

using Clock = std::chrono::steady_clock;

KernelFigure figure(const std::string& stage, const std::string& unit, std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return {stage, unit, values.front(), values[values.size() / 2], values.back()};
}

} // namespace

std::vector<KernelFigure> bench_kernels(const Scene& scene, const RenderOptions& opt, int runs, int passes)
{
    if (runs < 1 || passes < 1)
        throw ParameterError("runs", "must be at least 1");
    std::vector<KernelFigure> out;
    const std::uint32_t spp = sampler_spp(opt.sampler, opt.spp);

    // Setup: the scene compiled (its BVH build timed), the program built cold (pathcl's
    // cache bypassed; a driver's own cache, such as PoCL's, may still serve it) and warm.
    std::vector<double> bvh;
    CompiledScene compiled;
    for (int i = 0; i < runs; ++i) {
        compiled = compile_scene(scene, kernel_features(scene, opt), resolve_light_sampler(scene, opt));
        bvh.push_back(static_cast<double>(scene.triangles.size()) / 1e6 / std::max(compiled.bvh_build_seconds, 1e-9));
    }
    out.push_back(figure("BVH build", "Mtris/s", bvh));
    compiled.arrays.camera = {compile_camera(scene.camera, opt.width, opt.height)};
    ClDevice dev = open_device(opt.devices.empty() ? 0 : opt.devices[0]);
    ProgramSource source;
    source.root = "bench.cl";
    source.use_cache = false;
    const std::string build_options = program_build_options(compiled.features, opt);
    ProgramBuild cold = build_program(dev, build_options, source);
    // What storing that program in pathcl's cache costs on top (PoCL compiles again to
    // hand out a binary); a render spends it after its image (CacheStore::Deferred).
    double fetch_seconds = 0.0;
    try {
        auto start = std::chrono::steady_clock::now();
        cold.program.getInfo<CL_PROGRAM_BINARIES>();
        fetch_seconds = seconds_since(start);
    } catch (const cl::Error&) {
        fetch_seconds = -1.0; // the driver hands out no binary
    }
    source.use_cache = true;
    build_program(dev, build_options, source); // stores it
    ProgramBuild warm = build_program(dev, build_options, source);
    out.push_back(figure("program build, cold", "s", {cold.seconds}));
    out.push_back(figure("program binary for the cache, cold", "s", {fetch_seconds}));
    out.push_back(
        figure(std::string("program build, ") + (warm.from_cache ? "cached" : "not cached"), "s", {warm.seconds}));

    const std::size_t pixels = static_cast<std::size_t>(opt.width) * opt.height;
    DeviceArrays arrays = upload_arrays(dev, compiled.arrays, pixels);
    FrameParams frame = frame_params(compiled, opt, spp);

    cl::Kernel camera(warm.program, "generate_camera_rays"), paths(warm.program, "trace_paths"),
        clear(warm.program, "clear_film"), closest(warm.program, "bench_closest_hit"),
        any_hit(warm.program, "bench_any_hit"), bounce(warm.program, "bench_bounce_rays"),
        film(warm.program, "bench_film");
    const cl::NDRange global((opt.width + 7) / 8 * 8, (opt.height + 7) / 8 * 8), local(8, 8);
    auto launch = [&](cl::Kernel& k) {
        bind_kernel(k, arrays, frame);
        dev.queue.enqueueNDRangeKernel(k, cl::NullRange, global, local);
    };
    // `runs` timings (after a warm-up) of `passes` launches of `body`, each a rate of
    // `per_pass` items.
    auto rate = [&](const std::string& stage, const std::string& unit, const std::function<void()>& prepare,
                    const std::function<void()>& body, double per_pass) {
        std::vector<double> rates;
        for (int i = 0; i <= runs; ++i) {
            prepare();
            dev.queue.finish();
            auto t = Clock::now();
            for (int p = 0; p < passes; ++p)
                body();
            dev.queue.finish();
            if (i > 0)
                rates.push_back(per_pass * passes / seconds_since(t) / 1e6);
        }
        out.push_back(figure(stage, unit, rates));
    };
    // clear_film indexes pixels in one dimension (as the renderer launches it), so it gets
    // a range of its own, not the image's two.
    auto clear_film = [&] {
        bind_kernel(clear, arrays, frame);
        dev.queue.enqueueNDRangeKernel(clear, cl::NullRange, cl::NDRange(pixels), cl::NullRange);
    };
    auto nothing = [] {};
    auto camera_rays = [&] {
        frame.sample_index = 0;
        launch(camera);
    };
    auto bounce_rays = [&](cl_uint diffuse) {
        camera_rays();
        bind_kernel(bounce, arrays, frame, diffuse);
        dev.queue.enqueueNDRangeKernel(bounce, cl::NullRange, global, local);
    };
    const double n = static_cast<double>(pixels);
    try {
        rate(
            "camera rays", "Mrays/s", nothing, [&] { launch(camera); }, n);
        rate(
            "closest hit, primary rays", "Mrays/s", camera_rays, [&] { launch(closest); }, n);
        rate(
            "any hit, primary rays", "Mrays/s", camera_rays, [&] { launch(any_hit); }, n);
        rate(
            "closest hit, diffuse bounce rays", "Mrays/s", [&] { bounce_rays(1); }, [&] { launch(closest); }, n);
        rate(
            "any hit, diffuse bounce rays", "Mrays/s", [&] { bounce_rays(1); }, [&] { launch(any_hit); }, n);
        if (frame.light_count > 0)
            rate(
                "any hit, shadow rays", "Mrays/s", [&] { bounce_rays(0); }, [&] { launch(any_hit); }, n);
        rate(
            "path samples (camera and paths)", "Msamples/s", clear_film,
            [&] {
                launch(camera);
                launch(paths);
                ++frame.sample_index;
            },
            n);
        rate(
            "film accumulation", "Msamples/s", clear_film, [&] { launch(film); }, n);
    } catch (const cl::Error& e) {
        throw Error(std::string("kernel benchmark failed: ") + e.what() + " (OpenCL error " + std::to_string(e.err()) +
                    ")");
    }
    return out;
}

} // namespace pathcl
