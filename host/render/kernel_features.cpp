#include "render/kernel_features.h"

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
        set(FEATURE_TEXTURES, m.has_textures());
        set(FEATURE_NORMAL_MAPS, m.textures[TEXTURE_SLOT_NORMAL].present());
    }
    set(FEATURE_VERTEX_COLORS, !scene.colors.empty());
    for (const SceneLight& l : scene.lights) {
        set(FEATURE_POINT_LIGHTS, l.type == SceneLight::Type::Point);
        set(FEATURE_SPOT_LIGHTS, l.type == SceneLight::Type::Spot || l.type == SceneLight::Type::RectSpot);
        set(FEATURE_DIRECTIONAL_LIGHTS, l.type == SceneLight::Type::Directional);
        set(FEATURE_SPHERE_LIGHTS, l.type == SceneLight::Type::Sphere);
    }
    set(FEATURE_ENVIRONMENT, scene.environment.present);
    set(FEATURE_THIN_LENS, scene.camera.aperture > 0.0);
    set(FEATURE_SINGLE_SCATTERING, options.single_scattering);
    return f;
}

} // namespace pathcl
