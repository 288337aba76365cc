#include "compile/kernel_features.h"

#include <algorithm>

#include "compile/light_tree.h"
#include "compile/near_emitters.h"
#include "render/wavefront.h"
#include "scene/alpha_cutouts.h"

namespace pathcl {

std::string KernelFeatures::define() const
{
    return "-DPATHCL_FEATURES=" + std::to_string(mask) + "u";
}

KernelFeatures kernel_features(const Scene& scene, const RenderOptions& options)
{
    KernelFeatures f;
    auto set = [&](std::uint32_t feature, bool on) {
        if (on)
            f.mask |= feature;
    };
    for (const SceneTriangle& t : scene.triangles) {
        const SceneMaterial& m = scene.materials[static_cast<std::size_t>(t.material)];
        set(FEATURE_AREA_LIGHTS, m.emits());
        // Exactly Lambertian: no metal, no specular layer (specularFactor 0), no transmission.
        set(FEATURE_GLOSSY, m.metallic > 0.0f || m.specular > 0.0f);
        set(FEATURE_TRANSMISSION, m.transmission > 0.0f);
        set(FEATURE_VOLUME_ABSORPTION, m.absorbs());
        set(FEATURE_SCHLICK_LAYER, m.ior == 0.0f);
        set(FEATURE_UNLIT, m.unlit);
        set(FEATURE_CLEARCOAT, m.clearcoat > 0.0f);
        set(FEATURE_SHEEN, m.has_sheen());
        set(FEATURE_ANISOTROPY, m.has_anisotropy());
        set(FEATURE_TEXTURES, m.has_textures());
        set(FEATURE_NORMAL_MAPS, m.textures[TEXTURE_SLOT_NORMAL].present() ||
                                     (m.clearcoat > 0.0f && m.textures[TEXTURE_SLOT_CLEARCOAT_NORMAL].present()));
    }
    set(FEATURE_VERTEX_COLORS, !scene.colors.empty());
    std::vector<bool> alpha_tested = alpha_tested_triangles(scene);
    set(FEATURE_ALPHA, std::find(alpha_tested.begin(), alpha_tested.end(), true) != alpha_tested.end());
    for (const SceneLight& l : scene.lights) {
        set(FEATURE_POINT_LIGHTS, l.type == SceneLight::Type::Point);
        set(FEATURE_SPOT_LIGHTS, l.type == SceneLight::Type::Spot || l.type == SceneLight::Type::RectSpot);
        set(FEATURE_DIRECTIONAL_LIGHTS, l.type == SceneLight::Type::Directional);
        set(FEATURE_SPHERE_LIGHTS, l.type == SceneLight::Type::Sphere);
    }
    set(FEATURE_ENVIRONMENT, scene.environment.present);
    set(FEATURE_THIN_LENS, scene.camera.aperture > 0.0);
    set(FEATURE_INSTANCES, !scene.instances.empty());
    if (options.specialization == Specialization::All)
        f.mask |= FEATURE_ALL & ~(FEATURE_SINGLE_SCATTERING | FEATURE_LIGHT_TREE |
                                  FEATURE_SOLID_ANGLE_TRIANGLES); // model options, not scene features
    set(FEATURE_SINGLE_SCATTERING, options.single_scattering);
    set(FEATURE_LIGHT_TREE, resolve_light_sampler(scene, options) == LightSampler::Tree);
    set(FEATURE_SOLID_ANGLE_TRIANGLES,
        f.has(FEATURE_AREA_LIGHTS) && resolve_triangle_sampling(scene, options) == TriangleSampling::SolidAngle);
    return f;
}

std::string program_build_options(const KernelFeatures& features, const RenderOptions& options)
{
    // -cl-fast-relaxed-math less -cl-finite-math-only: the traversal's slab test and empty
    // hit records are infinities by design, and with finite math assumed PoCL 3.1 rendered
    // the glass-and-mirror box 50x slower (same image).
    return features.define() + (options.fast_math ? std::string(" ") + kUnsafeMathOption : std::string()) +
           (options.integrator == Integrator::Wavefront ? std::string(" ") + wavefront_build_option() : std::string());
}

std::vector<std::string> feature_names(std::uint32_t mask)
{
    static const char* const names[] = {"area-lights",
                                        "point-lights",
                                        "spot-lights",
                                        "directional-lights",
                                        "sphere-lights",
                                        "environment",
                                        "glossy",
                                        "transmission",
                                        "textures",
                                        "normal-maps",
                                        "vertex-colors",
                                        "thin-lens",
                                        "single-scattering",
                                        "alpha",
                                        "volume-absorption",
                                        "schlick-layer",
                                        "unlit",
                                        "clearcoat",
                                        "instances",
                                        "sheen",
                                        "anisotropy",
                                        "light-tree",
                                        "solid-angle-triangles"};
    static_assert(sizeof(names) / sizeof(names[0]) == 23 && FEATURE_ALL == (1u << 23) - 1u);
    std::vector<std::string> out;
    for (std::uint32_t b = 0; b < sizeof(names) / sizeof(names[0]); ++b)
        if (mask & (1u << b))
            out.push_back(names[b]);
    return out;
}

} // namespace pathcl
