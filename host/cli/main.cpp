// pathcl command line: `render`, `devices`, `compare`. Every error is one line on stderr
// ("pathcl: error: ...") and exit code 2; nothing is written unless the render succeeded.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cl/cl_runtime.h"
#include "common/error.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "shared_types.h"

namespace {

int run_devices()
{
    std::vector<pathcl::DeviceInfo> devices = pathcl::list_devices();
    if (devices.empty()) {
        std::cout << "no OpenCL devices found\n";
        return 1;
    }
    for (const pathcl::DeviceInfo& d : devices)
        std::printf("%d: %s | %s | %s | %u compute units | %.1f GiB | %s%s\n", d.index, d.platform.c_str(),
                    d.name.c_str(), d.type.c_str(), d.compute_units,
                    static_cast<double>(d.global_memory) / (1024.0 * 1024.0 * 1024.0), d.version.c_str(),
                    d.fp64 ? " | fp64" : "");
    return 0;
}

struct EnvironmentOverride {
    std::string file;
    float strength; // < 0: keep the scene's
    double rotation_degrees;
    std::vector<float> background; // empty or R, G, B
};

void apply_environment_flags(pathcl::Scene& scene, const EnvironmentOverride& o)
{
    pathcl::SceneEnvironment& env = scene.environment;
    if (!o.background.empty()) {
        for (float c : o.background)
            if (!(c >= 0.0f) || !std::isfinite(c))
                throw pathcl::Error("--background: components must be finite and non-negative");
        env = pathcl::SceneEnvironment{};
        env.present = true;
        env.constant = glm::vec3(o.background[0], o.background[1], o.background[2]);
    }
    if (!o.file.empty()) {
        env.present = true;
        env.path = o.file;
        env.strength = 1.0f;
    }
    if (o.strength >= 0.0f)
        env.strength = o.strength;
    env.rotation_degrees = o.rotation_degrees;
}

int run_render(const std::string& scene_path, const std::vector<std::string>& outputs,
               const pathcl::RenderOptions& opt, const EnvironmentOverride& env)
{
    for (const std::string& output : outputs)
        pathcl::check_output_path(output); // fail before spending time on the render
    pathcl::Scene scene = pathcl::load_gltf(scene_path);
    apply_environment_flags(scene, env);
    pathcl::RenderResult r = pathcl::render(scene, opt);
    for (const std::string& output : outputs)
        pathcl::write_image(output, r.image);
    const pathcl::RenderStats& s = r.stats;
    std::string names;
    for (const std::string& output : outputs)
        names += (names.empty() ? "" : ", ") + output;
    std::printf("%s: %zu triangles, %zu lights | BVH build %.1f ms | kernel build %.2f s%s | render %.3f s | "
                "%.3g samples/s | %llu NaN/Inf samples\n",
                names.c_str(), s.triangles, s.lights, s.bvh_build_seconds * 1e3, s.kernel_build_seconds,
                s.kernel_from_cache ? " (cached)" : "", s.render_seconds, s.samples_per_second,
                static_cast<unsigned long long>(s.bad_samples));
    return 0;
}

// Times renders of one scene: the first render's kernel build (time to first pixel
// includes it), one warm-up render, then `runs` timed renders; prints min/median/max.
int run_bench(const std::string& scene_path, pathcl::RenderOptions opt, int runs)
{
    pathcl::Scene scene = pathcl::load_gltf(scene_path);
    pathcl::RenderOptions warm = opt;
    warm.spp = 1;
    pathcl::RenderResult first = pathcl::render(scene, warm);
    std::printf("scene %s: %zu triangles, %zu BVH nodes | BVH build %.2f ms | kernel build %.2f s%s",
                scene_path.c_str(), first.stats.triangles, first.stats.bvh_nodes, first.stats.bvh_build_seconds * 1e3,
                first.stats.kernel_build_seconds, first.stats.kernel_from_cache ? " (from cache)" : " (compiled)");
    if (first.stats.texel_bytes > 0)
        std::printf(" | texels %.1f KiB", static_cast<double>(first.stats.texel_bytes) / 1024.0);
    std::printf("\n");
    std::vector<double> rates, seconds;
    for (int i = 0; i < runs; ++i) {
        opt.seed = static_cast<std::uint32_t>(i);
        pathcl::RenderResult r = pathcl::render(scene, opt);
        rates.push_back(r.stats.samples_per_second);
        seconds.push_back(r.stats.render_seconds);
    }
    std::sort(rates.begin(), rates.end());
    std::sort(seconds.begin(), seconds.end());
    std::size_t mid = rates.size() / 2;
    std::printf("%ux%u, %u spp, max bounces %u, %d runs: samples/s min %.4g median %.4g max %.4g | "
                "render s min %.3f median %.3f max %.3f\n",
                opt.width, opt.height, opt.spp, opt.max_bounces, runs, rates.front(), rates[mid], rates.back(),
                seconds.front(), seconds[mid], seconds.back());
    return 0;
}

int run_compare(const std::string& a, const std::string& b, const pathcl::CompareOptions& opt)
{
    pathcl::CompareReport r = pathcl::compare_images(pathcl::read_image(a), pathcl::read_image(b), opt);
    std::cout << r.summary();
    return r.passed ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"pathcl: a physically based OpenCL path tracer for glTF 2.0 scenes"};
    app.require_subcommand(1);

    CLI::App* render = app.add_subcommand("render", "Render a glTF scene to an EXR or PNG image");
    std::string scene_path;
    std::vector<std::string> outputs;
    pathcl::RenderOptions opt;
    int device = 0;
    render->add_option("scene", scene_path, "glTF 2.0 scene (.gltf or .glb)")->required();
    render->add_option("-o,--output", outputs,
                       "output image, repeatable (.exr: linear float + variance; .png: sRGB, clamped)")
        ->required()
        ->allow_extra_args(false);
    render->add_option("--spp", opt.spp, "samples per pixel")->capture_default_str()->check(CLI::Range(1u, 1u << 30));
    render->add_option("--width", opt.width, "image width")->capture_default_str()->check(CLI::Range(1u, 32768u));
    render->add_option("--height", opt.height, "image height")->capture_default_str()->check(CLI::Range(1u, 32768u));
    render->add_option("--max-bounces", opt.max_bounces,
                       "scattering events per path (0: emission only, 1: direct light)")
        ->capture_default_str()
        ->check(CLI::Range(0u, 1u << 16));
    render->add_option("--seed", opt.seed, "random seed (same seed, scene, options: same image)")->capture_default_str();
    render->add_option("--device", device, "OpenCL device index (see 'pathcl devices')")->capture_default_str();
    std::string env_file;
    float env_strength = -1.0f;
    double env_rotation = 0.0;
    std::vector<float> background;
    render->add_option("--env", env_file, "equirectangular environment map (EXR/HDR), overrides the scene's")
        ->check(CLI::ExistingFile);
    render->add_option("--env-strength", env_strength, "environment radiance scale (default: the scene's, else 1)");
    render->add_option("--env-rotation", env_rotation, "rotate the environment about +Y, degrees");
    render->add_option("--background", background, "constant environment radiance R,G,B")
        ->delimiter(',')
        ->expected(3);
    const std::map<std::string, std::uint32_t> strategies = {{"bsdf", STRATEGY_BSDF},
                                                             {"nee", STRATEGY_NEE},
                                                             {"one-sample", STRATEGY_ONE_SAMPLE},
                                                             {"mis", STRATEGY_MIS}};
    render->add_option("--strategy", opt.strategy, "light sampling: bsdf, nee, one-sample or mis")
        ->transform(CLI::CheckedTransformer(strategies, CLI::ignore_case))
        ->default_str("mis");

    bool single_scattering = false;
    render->add_flag("--single-scattering", single_scattering,
                     "rough microfacets without multiple-scattering energy compensation (as pbrt and Mitsuba "
                     "render them; for cross-checks)");

    app.add_subcommand("devices", "List every OpenCL platform and device with its index");

    CLI::App* bench = app.add_subcommand("bench", "Time repeated renders of a scene (min/median/max samples/s)");
    std::string bench_scene;
    pathcl::RenderOptions bench_opt;
    bench_opt.width = bench_opt.height = 256;
    bench_opt.spp = 16;
    int bench_runs = 5, bench_device = 0;
    bench->add_option("scene", bench_scene, "glTF 2.0 scene")->required();
    bench->add_option("--spp", bench_opt.spp, "samples per pixel per run")->capture_default_str();
    bench->add_option("--width", bench_opt.width, "image width")->capture_default_str();
    bench->add_option("--height", bench_opt.height, "image height")->capture_default_str();
    bench->add_option("--max-bounces", bench_opt.max_bounces, "scattering events per path")->capture_default_str();
    bench->add_option("--runs", bench_runs, "timed runs after one warm-up")->capture_default_str()->check(CLI::Range(1, 1000));
    bench->add_option("--device", bench_device, "OpenCL device index")->capture_default_str();
    bench->add_option("--strategy", bench_opt.strategy, "light sampling: bsdf, nee, one-sample or mis")
        ->transform(CLI::CheckedTransformer(strategies, CLI::ignore_case))
        ->default_str("mis");

    CLI::App* compare = app.add_subcommand(
        "compare", "Statistically compare two EXR renders (per-pixel, tile and image z-tests); exit 1 if they differ");
    std::string cmp_a, cmp_b;
    pathcl::CompareOptions cmp;
    compare->add_option("a", cmp_a, "first EXR (with variance channels)")->required();
    compare->add_option("b", cmp_b, "second EXR")->required();
    compare->add_option("--alpha", cmp.alpha, "family-wise significance level")->capture_default_str();
    compare->add_option("--max-fail-fraction", cmp.max_fail_fraction, "tolerated failing fraction per scale")
        ->capture_default_str();
    bool welch = false;
    compare->add_flag("--welch", welch,
                      "separate variances, for renders by different estimators (default: pooled, for a render "
                      "against a reference made by the same estimator)");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }

    try {
        if (render->parsed()) {
            opt.devices = {device};
            if (single_scattering)
                opt.extra_build_options += " -DPATHCL_SINGLE_SCATTERING";
            EnvironmentOverride env{env_file, env_strength, env_rotation, background};
            return run_render(scene_path, outputs, opt, env);
        }
        if (bench->parsed()) {
            bench_opt.devices = {bench_device};
            return run_bench(bench_scene, bench_opt, bench_runs);
        }
        if (compare->parsed()) {
            cmp.pooled_variance = !welch;
            return run_compare(cmp_a, cmp_b, cmp);
        }
        return run_devices();
    } catch (const pathcl::Error& e) {
        std::cerr << "pathcl: error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "pathcl: error: " << e.what() << '\n';
        return 2;
    }
}
