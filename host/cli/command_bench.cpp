// `pathcl bench`: times repeated renders of one scene with one Renderer (compiled, built
// and uploaded once), after one warm-up render, and prints min / median / max.
#include <algorithm>
#include <cstdio>

#include "bench/kernel_bench.h"
#include "cl/cl_runtime.h"
#include "cli/commands.h"
#include "cli/help_format.h"
#include "cli/options.h"
#include "image/image_module.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"

namespace pathcl::cli {
namespace {

struct BenchRequest {
    std::string scene_path;
    RenderOptions options;
    std::string device = "0"; // --device: an index, a list or all
    int runs = 5;
    bool kernels = false;
    bool copy_instances = false; // --copy-instances
};

int run_kernel_bench(const Scene& scene, const BenchRequest& rq)
{
    std::printf("scene %s, %ux%u, %u bounces, sampler %s, device %s; %d runs (min / median / max)\n",
                rq.scene_path.c_str(), rq.options.width, rq.options.height, rq.options.max_bounces,
                sampler_name(rq.options.sampler).c_str(), rq.device.c_str(), rq.runs);
    for (const KernelFigure& f : bench_kernels(scene, rq.options, rq.runs))
        std::printf("  %-36s %9.4g / %9.4g / %9.4g %s\n", f.stage.c_str(), f.min, f.median, f.max, f.unit.c_str());
    return 0;
}

int run_bench(BenchRequest rq)
{
    set_image_module_prelude(load_opencl_platforms); // the OpenCL implementations before OpenImageIO
    Scene scene = load_gltf(rq.scene_path, {-1, "", rq.copy_instances});
    rq.options.devices = parse_devices(rq.device);
    if (rq.kernels)
        return run_kernel_bench(scene, rq);
    Renderer renderer(scene, rq.options);
    const RenderStats& setup = renderer.setup_stats();
    std::printf("scene %s: %zu triangles, %zu BVH nodes | BVH build %.2f ms | kernel build %.2f s%s",
                rq.scene_path.c_str(), setup.triangles, setup.bvh_nodes, setup.bvh_build_seconds * 1e3,
                setup.kernel_build_seconds, setup.kernel_from_cache ? " (from cache)" : " (compiled)");
    if (setup.texel_bytes > 0)
        std::printf(" | texels %.1f KiB", static_cast<double>(setup.texel_bytes) / 1024.0);
    if (setup.light_tree_nodes > 0)
        std::printf(" | light tree of %zu lights: %zu nodes, %u levels, %.1f KiB (%.0f bytes a light), built in "
                    "%.2f ms (%.2f Mlights/s)",
                    setup.lights, setup.light_tree_nodes, setup.light_tree_depth,
                    static_cast<double>(setup.light_tree_bytes) / 1024.0,
                    static_cast<double>(setup.light_tree_bytes) /
                        static_cast<double>(std::max<std::size_t>(1, setup.lights)),
                    setup.light_tree_build_seconds * 1e3,
                    static_cast<double>(setup.lights) / std::max(1e-9, setup.light_tree_build_seconds) * 1e-6);
    std::printf("\n");
    renderer.render(0); // warm-up: the driver's first launch compiles the kernels' machine code
    std::vector<double> rates, seconds, film_seconds;
    for (int i = 0; i < rq.runs; ++i) {
        RenderResult r = renderer.render(static_cast<std::uint32_t>(i));
        rates.push_back(r.stats.samples_per_second);
        seconds.push_back(r.stats.render_seconds);
        film_seconds.push_back(r.stats.film_seconds);
    }
    std::sort(rates.begin(), rates.end());
    std::sort(seconds.begin(), seconds.end());
    std::sort(film_seconds.begin(), film_seconds.end());
    std::size_t mid = rates.size() / 2;
    std::printf("%ux%u, %u spp, max bounces %u, %d runs: samples/s min %.4g median %.4g max %.4g | "
                "render s min %.3f median %.3f max %.3f | of which film readback and sums s min %.3f median "
                "%.3f max %.3f\n",
                rq.options.width, rq.options.height, renderer.spp(), rq.options.max_bounces, rq.runs, rates.front(),
                rates[mid], rates.back(), seconds.front(), seconds[mid], seconds.back(), film_seconds.front(),
                film_seconds[mid], film_seconds.back());
    return 0;
}

} // namespace

Command add_bench_command(CLI::App& app)
{
    auto rq = std::make_shared<BenchRequest>();
    rq->options.width = rq->options.height = 256;
    rq->options.spp = 16;
    CLI::App* bench = app.add_subcommand("bench", "Time repeated renders of a scene (min/median/max samples/s)");
    bench->add_option("scene", rq->scene_path, "glTF 2.0 scene")->required();
    add_render_options(bench, rq->options, rq->device);
    add_program_options(bench, rq->options);
    bench->add_option("--runs", rq->runs, "timed runs after one warm-up")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    add_copy_instances_option(bench, rq->copy_instances);
    bench->add_flag("--kernels", rq->kernels,
                    "time each stage on its own instead: camera rays, closest and any-hit traversal (primary, "
                    "diffuse, shadow rays), path samples, film accumulation, BVH build, program build");
    describe_command(
        bench,
        {{kSamplingGroup, {}},
         {kSceneGroup, {}},
         {kDeviceGroup, {}},
         {kKernelGroup, {}},
         {"Benchmark", {"--runs", "--kernels"}}},
        {{"pathcl bench scenes/cornell-box.gltf", "five timed renders at 256x256 and 16 spp after a warm-up"},
         {"pathcl bench scenes/cornell-box.gltf --integrator wavefront", "the same with the wavefront integrator"},
         {"pathcl bench scenes/cornell-box.gltf --kernels", "each stage on its own: camera rays, traversal, "
                                                            "path samples, film, BVH and program builds"}});
    return {bench, [rq] { return run_bench(*rq); }};
}

} // namespace pathcl::cli
