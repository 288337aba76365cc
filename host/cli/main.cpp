// pathcl command line: `render`, `devices`, `bench`, `compare`, `samples`. Every error is
// one line on stderr ("pathcl: error: ...") and exit code 2; nothing is written unless
// the command succeeded.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cl/cl_runtime.h"
#include "common/error.h"
#include "common/staged_files.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "render/ray_log.h"
#include "render/renderer.h"
#include "sampling/sample_plot.h"
#include "sampling/samplers.h"
#include "scene/camera_overrides.h"
#include "scene/gltf_loader.h"
#include "types.h"

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

struct RenderRequest {
    std::string scene_path;
    std::vector<std::string> outputs;
    pathcl::RenderOptions options;
    EnvironmentOverride env;
    int camera = -1; // --camera N; -1: the first camera node
    pathcl::CameraOverrides camera_overrides;
    std::string ray_log; // --ray-log FILE.ply
};

int run_render(RenderRequest rq)
{
    for (const std::string& output : rq.outputs)
        pathcl::check_output_path(output); // fail before spending time on the render
    if (!rq.ray_log.empty())
        pathcl::check_ray_log_path(rq.ray_log);
    if (rq.camera < -1)
        throw pathcl::Error("--camera must be >= 0");
    pathcl::Scene scene = pathcl::load_gltf(rq.scene_path, rq.camera);
    apply_environment_flags(scene, rq.env);
    pathcl::apply_camera_overrides(scene, rq.camera_overrides);
    pathcl::RenderOptions& opt = rq.options;
    if (!rq.ray_log.empty())
        opt.ray_log_samples = 16; // 16 samples of each of up to 16 x 16 pixels
    pathcl::RenderResult r = pathcl::render(scene, opt);
    // Every output complete before any replaces what the user has.
    pathcl::StagedFiles staged;
    for (const std::string& output : rq.outputs)
        pathcl::write_image_file(staged.stage(output), output, r.image);
    if (!rq.ray_log.empty())
        pathcl::write_ray_log_file(staged.stage(rq.ray_log), rq.ray_log, r.camera_rays);
    staged.commit();
    const pathcl::RenderStats& s = r.stats;
    std::string names;
    for (const std::string& output : rq.outputs)
        names += (names.empty() ? "" : ", ") + output;
    if (!rq.ray_log.empty())
        names += ", " + rq.ray_log + " (" + std::to_string(r.camera_rays.size()) + " rays)";
    std::string spp = std::to_string(s.spp) + " spp " + pathcl::sampler_name(opt.sampler);
    if (s.spp != opt.spp)
        spp += " (rounded up from " + std::to_string(opt.spp) + ")";
    std::printf("%s: %zu triangles, %zu lights | %s | BVH build %.1f ms | kernel build %.2f s%s | render %.3f s | "
                "%.3g samples/s | %llu NaN/Inf samples\n",
                names.c_str(), s.triangles, s.lights, spp.c_str(), s.bvh_build_seconds * 1e3, s.kernel_build_seconds,
                s.kernel_from_cache ? " (cached)" : "", s.render_seconds, s.samples_per_second,
                static_cast<unsigned long long>(s.bad_samples));
    return 0;
}

struct SamplesRequest {
    std::string output;
    std::uint32_t sampler = 0, spp = 16, seed = 0, width = 512;
    std::vector<std::uint32_t> pixel{0, 0}, dims{0, 1};
    bool spectrum = false;
    int device = 0;
};

// `pathcl samples`: draws one pixel's point set (and the averaged power spectrum).
int run_samples(const SamplesRequest& rq)
{
    pathcl::check_output_path(rq.output);
    std::string ext = std::filesystem::path(rq.output).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext != ".png")
        throw pathcl::Error(rq.output + ": the sample plot must be a .png");
    if (rq.pixel[0] >= rq.width)
        throw pathcl::Error("--pixel: x must be less than --width (" + std::to_string(rq.width) + ")");
    pathcl::SamplePlotRequest plot;
    plot.sampler = rq.sampler;
    plot.spp = pathcl::sampler_spp(rq.sampler, rq.spp);
    plot.seed = rq.seed;
    plot.dim0 = rq.dims[0];
    plot.dim1 = rq.dims[1];
    plot.pixel = rq.pixel[1] * rq.width + rq.pixel[0];
    plot.pixel_label = "(" + std::to_string(rq.pixel[0]) + ", " + std::to_string(rq.pixel[1]) + ")";
    plot.spectrum = rq.spectrum;
    if (plot.dim0 == plot.dim1)
        throw pathcl::Error("--dims: the two dimensions must differ");
    if (plot.spectrum && plot.spp > pathcl::kSpectrumMaxSpp)
        throw pathcl::Error("--spectrum needs --spp at most " + std::to_string(pathcl::kSpectrumMaxSpp));
    pathcl::ClDevice dev = pathcl::open_device(rq.device);
    pathcl::ProgramBuild pb = pathcl::build_program(dev, "");
    std::string note;
    pathcl::Image img = pathcl::draw_sample_plot(dev, pb.program, plot, &note);
    pathcl::write_image(rq.output, img);
    std::string spp = std::to_string(plot.spp) + " spp";
    if (plot.spp != rq.spp)
        spp += " (rounded up from " + std::to_string(rq.spp) + ")";
    std::printf("%s: %s, %s, pixel %s, dims %u,%u%s%s\n", rq.output.c_str(), pathcl::sampler_name(rq.sampler).c_str(),
                spp.c_str(), plot.pixel_label.c_str(), plot.dim0, plot.dim1, note.empty() ? "" : " | ", note.c_str());
    return 0;
}

// Times renders of one scene: the first render's kernel build (time to first pixel
// includes it), one warm-up render, then `runs` timed renders; prints min/median/max.
int run_bench(const std::string& scene_path, pathcl::RenderOptions opt, int runs)
{
    pathcl::Scene scene = pathcl::load_gltf(scene_path);
    pathcl::Renderer renderer(scene, opt); // compiled, built and uploaded once for every run
    const pathcl::RenderStats& setup = renderer.setup_stats();
    std::printf("scene %s: %zu triangles, %zu BVH nodes | BVH build %.2f ms | kernel build %.2f s%s",
                scene_path.c_str(), setup.triangles, setup.bvh_nodes, setup.bvh_build_seconds * 1e3,
                setup.kernel_build_seconds, setup.kernel_from_cache ? " (from cache)" : " (compiled)");
    if (setup.texel_bytes > 0)
        std::printf(" | texels %.1f KiB", static_cast<double>(setup.texel_bytes) / 1024.0);
    std::printf("\n");
    renderer.render(0); // warm-up: the driver's first launch compiles the kernels' machine code
    std::vector<double> rates, seconds;
    for (int i = 0; i < runs; ++i) {
        pathcl::RenderResult r = renderer.render(static_cast<std::uint32_t>(i));
        rates.push_back(r.stats.samples_per_second);
        seconds.push_back(r.stats.render_seconds);
    }
    std::sort(rates.begin(), rates.end());
    std::sort(seconds.begin(), seconds.end());
    std::size_t mid = rates.size() / 2;
    std::printf("%ux%u, %u spp, max bounces %u, %d runs: samples/s min %.4g median %.4g max %.4g | "
                "render s min %.3f median %.3f max %.3f\n",
                opt.width, opt.height, renderer.spp(), opt.max_bounces, runs, rates.front(), rates[mid], rates.back(),
                seconds.front(), seconds[mid], seconds.back());
    return 0;
}

int run_compare(const std::string& a, const std::string& b, const pathcl::CompareOptions& opt, bool bitwise)
{
    if (bitwise) {
        pathcl::BitwiseReport r = pathcl::compare_bitwise(pathcl::read_image(a), pathcl::read_image(b));
        std::cout << r.summary();
        return r.identical() ? 0 : 1;
    }
    pathcl::CompareReport r = pathcl::compare_images(pathcl::read_image(a), pathcl::read_image(b), opt);
    std::cout << r.summary();
    return r.passed ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"pathcl: a physically based OpenCL path tracer for glTF 2.0 scenes"};
    app.require_subcommand(1);
    // Usage errors follow the same contract as every other error: one line, exit code 2.
    // (Set before the subcommands are added: they inherit it.)
    app.failure_message([](const CLI::App*, const CLI::Error& e) {
        std::string what = e.what();
        std::replace(what.begin(), what.end(), '\n', ' ');
        return "pathcl: error: " + what + "\n";
    });

    CLI::App* render = app.add_subcommand("render", "Render a glTF scene to an EXR or PNG image");
    std::string scene_path;
    std::vector<std::string> outputs;
    pathcl::RenderOptions opt;
    // Owen-scrambled Sobol by default: on the Cornell box at 64 spp it has a quarter of
    // the independent sampler's RMSE for about 1.2 times the time per sample (README).
    opt.sampler = SAMPLER_SOBOL;
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
    // --sampler NAME: a readable message for a bad name (CheckedTransformer's lists the
    // numeric values too).
    const CLI::Validator sampler_check(
        [](std::string& value) {
            std::string lower = value;
            std::transform(lower.begin(), lower.end(), lower.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            auto it = pathcl::sampler_names().find(lower);
            if (it == pathcl::sampler_names().end())
                return "unknown sampler '" + value +
                       "' (independent, jittered, multi-jittered, n-rooks, sobol, halton, hammersley)";
            value = std::to_string(it->second);
            return std::string();
        },
        "SAMPLER");
    const std::string sampler_help =
        "sampler: independent, jittered, multi-jittered, n-rooks, sobol, halton or hammersley "
        "(jittered and multi-jittered round --spp up to a square, hammersley to a power of two)";
    render->add_option("--sampler", opt.sampler, sampler_help)
        ->transform(sampler_check)
        ->type_name("NAME")
        ->default_str("sobol");
    RenderRequest rr;
    std::vector<double> look_from, look_at, up;
    double fov = 0.0, aperture = 0.0, focus_distance = 0.0;
    render->add_option("--camera", rr.camera,
                       "camera node to render from: N-th camera node (perspective or orthographic) in depth-first "
                       "node order, from 0 (default: the first)");
    CLI::Option* fov_opt = render->add_option("--fov", fov, "vertical field of view in degrees (perspective camera)");
    render->add_option("--look-from", look_from, "camera position X,Y,Z (world space)")->delimiter(',')->expected(3);
    render->add_option("--look-at", look_at, "point the camera looks at X,Y,Z (world space)")
        ->delimiter(',')
        ->expected(3);
    render->add_option("--up", up, "up direction X,Y,Z for --look-at (default: the camera's up)")
        ->delimiter(',')
        ->expected(3);
    CLI::Option* aperture_opt =
        render->add_option("--aperture", aperture, "thin-lens radius in world units (0: pinhole)");
    CLI::Option* focus_opt =
        render->add_option("--focus-distance", focus_distance, "distance of the plane of focus along the view");
    render->add_option("--ray-log", rr.ray_log,
                       "write camera rays (16 samples of up to 16x16 pixels) to a .ply point cloud: origins, with "
                       "directions as normals");

    bool single_scattering = false;
    render->add_flag("--single-scattering", single_scattering,
                     "rough microfacets without multiple-scattering energy compensation (as pbrt and Mitsuba "
                     "render them; for cross-checks)");

    app.add_subcommand("devices", "List every OpenCL platform and device with its index");

    CLI::App* bench = app.add_subcommand("bench", "Time repeated renders of a scene (min/median/max samples/s)");
    std::string bench_scene;
    pathcl::RenderOptions bench_opt;
    bench_opt.sampler = SAMPLER_SOBOL;
    bench_opt.width = bench_opt.height = 256;
    bench_opt.spp = 16;
    int bench_runs = 5, bench_device = 0;
    bench->add_option("scene", bench_scene, "glTF 2.0 scene")->required();
    bench->add_option("--spp", bench_opt.spp, "samples per pixel per run")->capture_default_str()->check(CLI::Range(1u, 1u << 30));
    bench->add_option("--width", bench_opt.width, "image width")->capture_default_str()->check(CLI::Range(1u, 32768u));
    bench->add_option("--height", bench_opt.height, "image height")->capture_default_str()->check(CLI::Range(1u, 32768u));
    bench->add_option("--max-bounces", bench_opt.max_bounces, "scattering events per path")
        ->capture_default_str()
        ->check(CLI::Range(0u, 1u << 16));
    bench->add_option("--runs", bench_runs, "timed runs after one warm-up")->capture_default_str()->check(CLI::Range(1, 1000));
    bench->add_option("--device", bench_device, "OpenCL device index")->capture_default_str();
    bench->add_option("--strategy", bench_opt.strategy, "light sampling: bsdf, nee, one-sample or mis")
        ->transform(CLI::CheckedTransformer(strategies, CLI::ignore_case))
        ->default_str("mis");
    bench->add_option("--sampler", bench_opt.sampler, sampler_help)
        ->transform(sampler_check)
        ->type_name("NAME")
        ->default_str("sobol");

    CLI::App* samples = app.add_subcommand(
        "samples", "Draw one pixel's sample points for a dimension pair (and their power spectrum) to a PNG");
    SamplesRequest sq;
    samples->add_option("-o,--output", sq.output, "output PNG")->required();
    samples->add_option("--sampler", sq.sampler, sampler_help)
        ->transform(sampler_check)
        ->type_name("NAME")
        ->default_str("independent");
    samples->add_option("--spp", sq.spp, "samples per pixel")->capture_default_str()->check(CLI::Range(1u, 1u << 20));
    samples->add_option("--pixel", sq.pixel, "pixel X,Y (default 0,0)")->delimiter(',')->expected(2);
    samples->add_option("--width", sq.width, "image width the pixel index y * width + x refers to")
        ->capture_default_str()
        ->check(CLI::Range(1u, 32768u));
    samples->add_option("--dims", sq.dims,
                        "dimensions D0,D1 (default 0,1: the film position); D1 = D0 + 1 is the 2D decision at D0, "
                        "other pairs are two 1D decisions")
        ->delimiter(',')
        ->expected(2);
    samples->add_option("--seed", sq.seed, "random seed")->capture_default_str();
    samples->add_flag("--spectrum", sq.spectrum, "add the power spectrum averaged over many pixels");
    samples->add_option("--device", sq.device, "OpenCL device index")->capture_default_str();

    CLI::App* compare = app.add_subcommand(
        "compare", "Statistically compare two EXR renders (per-pixel, tile and image z-tests); exit 1 if they differ");
    std::string cmp_a, cmp_b;
    pathcl::CompareOptions cmp;
    compare->add_option("a", cmp_a, "first EXR (with variance channels)")->required();
    compare->add_option("b", cmp_b, "second EXR")->required();
    compare->add_option("--alpha", cmp.alpha, "family-wise significance level")->capture_default_str();
    compare->add_option("--max-fail-fraction", cmp.max_fail_fraction, "tolerated failing fraction per scale")
        ->capture_default_str();
    bool welch = false, bitwise = false;
    compare->add_flag("--welch", welch,
                      "separate variances, for renders by different estimators (default: pooled, for a render "
                      "against a reference made by the same estimator)");
    compare->add_flag("--bitwise", bitwise,
                      "instead: are the pixel data (means, variances, spp) identical bit for bit? (reproducibility, "
                      "refactors)");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }

    try {
        if (render->parsed()) {
            opt.devices = {device};
            opt.single_scattering = single_scattering;
            rr.scene_path = scene_path;
            rr.outputs = outputs;
            rr.options = opt;
            rr.env = EnvironmentOverride{env_file, env_strength, env_rotation, background};
            pathcl::CameraOverrides& co = rr.camera_overrides;
            auto vec = [](const std::vector<double>& v) { return glm::dvec3(v[0], v[1], v[2]); };
            if (fov_opt->count())
                co.fov_degrees = fov;
            if (!look_from.empty())
                co.look_from = vec(look_from);
            if (!look_at.empty())
                co.look_at = vec(look_at);
            if (!up.empty())
                co.up = vec(up);
            if (aperture_opt->count())
                co.aperture = aperture;
            if (focus_opt->count())
                co.focus_distance = focus_distance;
            return run_render(rr);
        }
        if (samples->parsed())
            return run_samples(sq);
        if (bench->parsed()) {
            bench_opt.devices = {bench_device};
            return run_bench(bench_scene, bench_opt, bench_runs);
        }
        if (compare->parsed()) {
            cmp.pooled_variance = !welch;
            return run_compare(cmp_a, cmp_b, cmp, bitwise);
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
