#include "scene/scene.h"

#include <cmath>
#include <limits>

namespace pathcl {

std::string SceneFeatures::build_defines() const
{
    std::string d;
    if (area_lights)
        d += " -DPATHCL_HAS_AREA_LIGHTS";
    if (point_lights)
        d += " -DPATHCL_HAS_POINT_LIGHTS";
    if (spot_lights)
        d += " -DPATHCL_HAS_SPOT_LIGHTS";
    if (directional_lights)
        d += " -DPATHCL_HAS_DIRECTIONAL_LIGHTS";
    if (sphere_lights)
        d += " -DPATHCL_HAS_SPHERE_LIGHTS";
    if (environment)
        d += " -DPATHCL_HAS_ENVIRONMENT";
    if (glossy)
        d += " -DPATHCL_HAS_GLOSSY";
    if (transmission)
        d += " -DPATHCL_HAS_TRANSMISSION";
    if (textures)
        d += " -DPATHCL_HAS_TEXTURES";
    if (normal_maps)
        d += " -DPATHCL_HAS_NORMAL_MAPS";
    if (vertex_colors)
        d += " -DPATHCL_HAS_VERTEX_COLORS";
    if (thin_lens)
        d += " -DPATHCL_HAS_THIN_LENS";
    return d;
}

SceneFeatures scene_features(const Scene& scene)
{
    SceneFeatures f;
    for (const SceneTriangle& t : scene.triangles) {
        const SceneMaterial& m = scene.materials[static_cast<std::size_t>(t.material)];
        f.area_lights = f.area_lights || m.emits();
        // Exactly Lambertian: no metal, no specular layer (specularFactor 0), no transmission.
        f.glossy = f.glossy || m.metallic > 0.0f || m.specular > 0.0f;
        f.transmission = f.transmission || m.transmission > 0.0f;
        f.textures = f.textures || m.has_textures();
        f.normal_maps = f.normal_maps || m.normal_texture.present();
    }
    f.vertex_colors = !scene.colors.empty();
    for (const SceneLight& l : scene.lights) {
        f.point_lights = f.point_lights || l.type == SceneLight::Type::Point;
        f.spot_lights = f.spot_lights || l.type == SceneLight::Type::Spot || l.type == SceneLight::Type::RectSpot;
        f.directional_lights = f.directional_lights || l.type == SceneLight::Type::Directional;
        f.sphere_lights = f.sphere_lights || l.type == SceneLight::Type::Sphere;
    }
    f.environment = scene.environment.present;
    f.thin_lens = scene.camera.aperture > 0.0;
    return f;
}

void scene_bounds(const Scene& scene, glm::vec3& lo, glm::vec3& hi)
{
    lo = glm::vec3(std::numeric_limits<float>::infinity());
    hi = -lo;
    for (const SceneTriangle& t : scene.triangles)
        for (const glm::vec3& v : t.v) {
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
}

SceneCamera framing_camera(const Scene& scene, double yfov)
{
    glm::vec3 lo, hi;
    scene_bounds(scene, lo, hi);
    SceneCamera cam;
    cam.yfov = yfov;
    if (scene.triangles.empty())
        return cam;
    glm::dvec3 centre = 0.5 * (glm::dvec3(lo) + glm::dvec3(hi));
    double radius = 0.5 * glm::length(glm::dvec3(hi) - glm::dvec3(lo));
    double distance = radius / std::sin(0.5 * yfov);
    cam.position = centre + glm::dvec3(0.0, 0.0, distance > 0.0 ? distance : 1.0);
    return cam;
}

} // namespace pathcl
