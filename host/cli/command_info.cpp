// `pathcl info`: what a scene uses (geometry, lights by type, materials by lobe,
// textures, environment, camera) and the kernel variant it compiles: the features, the
// cold compile time of that variant on the device, and its key in the program cache.
#include <cstdio>

#include "cl/cl_runtime.h"
#include "cli/commands.h"
#include "cli/help_format.h"
#include "cli/options.h"
#include "common/error.h"
#include "compile/kernel_features.h"
#include "image/image_module.h"
#include "scene/gltf_loader.h"
#include "scene/scene_summary.h"

namespace pathcl::cli {
namespace {

struct InfoRequest {
    std::string scene_path;
    std::string variant;         // --variant NAME
    bool copy_instances = false; // --copy-instances
    RenderOptions options;
    int device = 0;
};

std::string join(const std::vector<std::string>& items)
{
    std::string out;
    for (const std::string& s : items)
        out += (out.empty() ? "" : ", ") + s;
    return out.empty() ? "none" : out;
}

int run_info(const InfoRequest& rq)
{
    set_image_module_prelude(load_opencl_platforms); // the OpenCL implementations before OpenImageIO
    Scene scene = load_gltf(rq.scene_path, {-1, rq.variant, rq.copy_instances});
    SceneSummary s = summarize_scene(scene);
    std::printf("scene        %s\n", rq.scene_path.c_str());
    std::printf("triangles    %zu (%zu degenerate dropped at load)\n", s.triangles, s.dropped_degenerate);
    if (s.instances > 0)
        std::printf("instances    %zu of %zu mesh%s stored once (%zu triangles stored)\n", s.instances,
                    s.instanced_meshes, s.instanced_meshes == 1 ? "" : "es", s.stored_triangles);
    std::printf("lights       %zu emissive triangles, %zu point, %zu spot, %zu rectangular spot, %zu directional, "
                "%zu sphere\n",
                s.emissive_triangles, s.point_lights, s.spot_lights, s.rect_spot_lights, s.directional_lights,
                s.sphere_lights);
    std::printf("materials    %zu used: diffuse %zu, metal %zu, specular layer %zu, transmission %zu, emissive %zu; "
                "textured %zu, normal-mapped %zu\n",
                s.materials, s.diffuse, s.metal, s.specular_layer, s.transmission, s.emissive, s.textured,
                s.normal_mapped);
    std::printf("textures     %zu images, %.3g Mtexels%s\n", s.images, static_cast<double>(s.texels) / 1e6,
                s.vertex_colors ? "; vertex colours" : "");
    std::printf("environment  %s\n", s.environment.c_str());
    if (!scene.material_variants.empty()) {
        std::vector<std::string> names;
        for (const std::string& v : scene.material_variants)
            names.push_back(quote(v));
        std::printf("variants     %s; materials of %s\n", join(names).c_str(),
                    scene.variant.empty() ? "the default" : (quote(scene.variant)).c_str());
    }
    std::printf("camera       %s\n", s.camera.c_str());

    KernelFeatures features = kernel_features(scene, rq.options);
    std::printf("features     %s (mask %u of %u)\n", join(feature_names(features.mask)).c_str(), features.mask,
                FEATURE_ALL);
    ClDevice dev = open_device(rq.device);
    ProgramSource source;
    source.use_cache = false; // the cold compile time
    ProgramBuild pb = build_program(dev, program_build_options(features, rq.options), source);
    std::printf("program      compiled cold in %.2f s on %s (%s); cache key %s\n", pb.seconds, dev.info.name.c_str(),
                dev.info.platform.c_str(), pb.cache_key.c_str());
    return 0;
}

} // namespace

Command add_info_command(CLI::App& app)
{
    auto rq = std::make_shared<InfoRequest>();
    CLI::App* info = app.add_subcommand("info", "What a scene uses and the kernel variant it compiles");
    info->add_option("scene", rq->scene_path, "glTF 2.0 scene (.gltf or .glb)")->required();
    add_program_options(info, rq->options);
    add_variant_option(info, rq->variant);
    add_copy_instances_option(info, rq->copy_instances);
    info->add_option("--device", rq->device, "OpenCL device index (see 'pathcl devices')")->capture_default_str();
    describe_command(info, {{kSceneGroup, {}}, {kDeviceGroup, {"--device"}}, {kKernelGroup, {}}},
                     {{"pathcl info scenes/textured.gltf",
                       "what the scene uses, the kernel features it compiles and how long a cold build takes"},
                      {"pathcl info scenes/cornell-box.gltf --specialization all",
                       "the same for the program with every feature compiled in"}});
    return {info, [rq] { return run_info(*rq); }};
}

} // namespace pathcl::cli
