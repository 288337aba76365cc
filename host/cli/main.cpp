// pathcl command line: `render`, `devices`, `compare`. Every error is one line on stderr
// ("pathcl: error: ...") and exit code 2; nothing is written unless the render succeeded.
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cl/cl_runtime.h"
#include "common/error.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"

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

int run_render(const std::string& scene_path, const std::string& output, const pathcl::RenderOptions& opt)
{
    pathcl::check_output_path(output); // fail before spending time on the render
    pathcl::Scene scene = pathcl::load_gltf(scene_path);
    pathcl::RenderResult r = pathcl::render(scene, opt);
    pathcl::write_image(output, r.image);
    const pathcl::RenderStats& s = r.stats;
    std::printf("%s: %zu triangles, %zu lights | BVH build %.1f ms | kernel build %.2f s%s | render %.3f s | "
                "%.3g samples/s | %llu NaN/Inf samples\n",
                output.c_str(), s.triangles, s.lights, s.bvh_build_seconds * 1e3, s.kernel_build_seconds,
                s.kernel_from_cache ? " (cached)" : "", s.render_seconds, s.samples_per_second,
                static_cast<unsigned long long>(s.bad_samples));
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
    std::string scene_path, output;
    pathcl::RenderOptions opt;
    int device = 0;
    render->add_option("scene", scene_path, "glTF 2.0 scene (.gltf or .glb)")->required();
    render->add_option("-o,--output", output, "output image (.exr: linear float + variance; .png: sRGB)")->required();
    render->add_option("--spp", opt.spp, "samples per pixel")->capture_default_str()->check(CLI::Range(1u, 1u << 30));
    render->add_option("--width", opt.width, "image width")->capture_default_str()->check(CLI::Range(1u, 32768u));
    render->add_option("--height", opt.height, "image height")->capture_default_str()->check(CLI::Range(1u, 32768u));
    render->add_option("--max-bounces", opt.max_bounces,
                       "scattering events per path (0: emission only, 1: direct light)")
        ->capture_default_str()
        ->check(CLI::Range(0u, 1u << 16));
    render->add_option("--seed", opt.seed, "random seed (same seed, scene, options: same image)")->capture_default_str();
    render->add_option("--device", device, "OpenCL device index (see 'pathcl devices')")->capture_default_str();

    app.add_subcommand("devices", "List every OpenCL platform and device with its index");

    CLI::App* compare = app.add_subcommand(
        "compare", "Statistically compare two EXR renders (per-pixel, tile and image z-tests); exit 1 if they differ");
    std::string cmp_a, cmp_b;
    pathcl::CompareOptions cmp;
    compare->add_option("a", cmp_a, "first EXR (with variance channels)")->required();
    compare->add_option("b", cmp_b, "second EXR")->required();
    compare->add_option("--alpha", cmp.alpha, "family-wise significance level")->capture_default_str();
    compare->add_option("--max-fail-fraction", cmp.max_fail_fraction, "tolerated failing fraction per scale")
        ->capture_default_str();

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }

    try {
        if (render->parsed()) {
            opt.devices = {device};
            return run_render(scene_path, output, opt);
        }
        if (compare->parsed())
            return run_compare(cmp_a, cmp_b, cmp);
        return run_devices();
    } catch (const pathcl::Error& e) {
        std::cerr << "pathcl: error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "pathcl: error: " << e.what() << '\n';
        return 2;
    }
}
