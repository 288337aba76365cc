// Lights for the device: one Light record per light with its per-type data, in the order
// CompiledScene documents, and the power that sets how often each is picked (luminance,
// W; compile/light_distribution.h). Also marks every emissive triangle's shading record
// with its light.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "compile/compile_scene.h"
#include "compile/environment.h"
#include "compile/luminance.h"
#include "compile/texture_lookup.h"

namespace pathcl {
namespace {

// Luminance with a floor, so that every light keeps a (tiny) power.
double power_luminance(const glm::vec3& c)
{
    return std::max(luminance(c), 1e-12);
}

// Radius of the scene's bounding sphere: directional lights and the environment deliver
// their power through its disk (pbrt's convention).
double scene_radius(const Scene& scene)
{
    glm::vec3 lo, hi;
    scene_bounds(scene, lo, hi);
    return scene.triangles.empty() ? 1.0 : 0.5 * glm::length(glm::dvec3(hi) - glm::dvec3(lo));
}

// Solid angle a cone spot lights, weighted by the glTF falloff t^2:
// 2 pi * integral over cos(theta) in [cos outer, 1] of t(cos)^2.
double spot_weighted_solid_angle(double cos_inner, double cos_outer)
{
    const int steps = 4096;
    double sum = 0.0, h = (1.0 - cos_outer) / steps;
    for (int i = 0; i < steps; ++i) {
        double c = cos_outer + (i + 0.5) * h;
        double t = std::clamp((c - cos_outer) / std::max(0.001, cos_inner - cos_outer), 0.0, 1.0);
        sum += t * t * h;
    }
    return 2.0 * std::numbers::pi * sum;
}

void add_sphere_lights(const Scene& scene, std::vector<Light>& lights, std::vector<double>& power)
{
    for (const SceneLight& sl : scene.lights) {
        if (sl.type != SceneLight::Type::Sphere)
            continue;
        Light l{};
        l.type = LIGHT_SPHERE;
        l.data.sphere.centre = to_float4(sl.position);
        l.data.sphere.radius = static_cast<float>(sl.radius);
        // Uniform outward radiance with the point light's total power 4 pi I.
        l.radiance = to_float4(sl.intensity / static_cast<float>(std::numbers::pi * sl.radius * sl.radius));
        lights.push_back(l);
        power.push_back(4.0 * std::numbers::pi * power_luminance(sl.intensity));
    }
}

void add_triangle_lights(const Scene& scene, const std::vector<std::uint32_t>& leaf_order, CompiledScene& out,
                         std::vector<double>& power)
{
    SceneArrays& a = out.arrays;
    for (std::size_t i = 0; i < leaf_order.size(); ++i) {
        const SceneTriangle& t = scene.triangles[leaf_order[i]];
        const SceneMaterial& m = scene.materials[static_cast<std::size_t>(t.material)];
        if (!m.emits())
            continue;
        double area = 0.5 * glm::length(glm::cross(glm::dvec3(t.v[1]) - glm::dvec3(t.v[0]),
                                                   glm::dvec3(t.v[2]) - glm::dvec3(t.v[0])));
        Light light{};
        light.type = LIGHT_TRIANGLE;
        TriangleLight& tl = light.data.triangle;
        tl.v0 = to_float4(t.v[0]);
        tl.v1 = to_float4(t.v[1]);
        tl.v2 = to_float4(t.v[2]);
        tl.area = static_cast<float>(area);
        tl.triangle = static_cast<pcl_int>(i);
        light.leaf_node = out.triangle_leaves[i].node;
        light.leaf_block = out.triangle_leaves[i].block;
        tl.texture = a.materials[static_cast<std::size_t>(t.material)].textures[TEXTURE_SLOT_EMISSIVE];
        light.radiance = to_float4(m.emission);
        a.shading[i].emitter = static_cast<pcl_int>(a.lights.size());
        a.lights.push_back(light);
        // Emitted power of a one-sided Lambertian emitter: pi * area * radiance; with an
        // emissive texture, radiance = factor x the texture's mean over the triangle (an
        // estimate: it only sets how often the light is picked; the floor keeps every
        // emitter pickable, so the estimator stays unbiased).
        glm::dvec3 radiance(m.emission);
        const SceneTexture& emissive = m.textures[TEXTURE_SLOT_EMISSIVE];
        if (emissive.present()) {
            const SceneImage& img = scene.images[static_cast<std::size_t>(emissive.image)];
            const TriangleUv& uv = scene.texcoords[static_cast<std::size_t>(emissive.texcoord)][leaf_order[i]];
            radiance *= texture_mean_over_triangle(img, emissive, true, uv);
        }
        power.push_back(std::numbers::pi * area * power_luminance(glm::vec3(radiance)));
    }
}

void add_punctual_lights(const Scene& scene, std::vector<Light>& lights, std::vector<double>& power)
{
    const double radius = scene_radius(scene);
    for (const SceneLight& sl : scene.lights) {
        Light l{};
        l.radiance = to_float4(sl.intensity);
        double lum = power_luminance(sl.intensity);
        switch (sl.type) {
        case SceneLight::Type::Point:
            l.type = LIGHT_POINT;
            l.data.point.position = to_float4(sl.position);
            power.push_back(4.0 * std::numbers::pi * lum);
            break;
        case SceneLight::Type::Spot:
            l.type = LIGHT_SPOT;
            l.data.spot.position = to_float4(sl.position);
            l.data.spot.axis = to_float4(sl.direction);
            l.data.spot.cos_outer = static_cast<float>(sl.cos_outer);
            l.data.spot.cos_inner = static_cast<float>(sl.cos_inner);
            power.push_back(lum * spot_weighted_solid_angle(sl.cos_inner, sl.cos_outer));
            break;
        case SceneLight::Type::RectSpot:
            l.type = LIGHT_RECT_SPOT;
            l.data.rect_spot.position = to_float4(sl.position);
            l.data.rect_spot.axis = to_float4(sl.direction);
            l.data.rect_spot.right = to_float4(sl.right);
            l.data.rect_spot.tan_half_h = static_cast<float>(sl.tan_half_h);
            l.data.rect_spot.tan_half_v = static_cast<float>(sl.tan_half_v);
            // Solid angle of a rectangular frustum with half-angles a, b: 4 asin(sin a sin b).
            power.push_back(lum * 4.0 *
                            std::asin(std::sin(std::atan(sl.tan_half_h)) * std::sin(std::atan(sl.tan_half_v))));
            break;
        case SceneLight::Type::Directional:
            l.type = LIGHT_DIRECTIONAL;
            l.data.directional.direction = to_float4(sl.direction);
            power.push_back(lum * std::numbers::pi * radius * radius);
            break;
        case SceneLight::Type::Sphere:
            continue; // added first, by add_sphere_lights
        }
        lights.push_back(l);
    }
}

void add_environment_light(const Scene& scene, CompiledScene& out, std::vector<double>& power)
{
    EnvironmentMap map = build_environment_map(scene.environment);
    double rot = scene.environment.rotation_degrees * std::numbers::pi / 180.0;
    Light l{};
    l.type = LIGHT_ENVIRONMENT;
    l.data.environment = {map.width, map.height, static_cast<float>(std::cos(rot)), static_cast<float>(std::sin(rot))};
    out.environment_light = static_cast<int>(out.arrays.lights.size());
    out.arrays.lights.push_back(l);
    // Power through the scene's bounding disk: pi r^2 times the radiance integrated over
    // the sphere (4 pi times its mean); an all-black map is never picked.
    double r = scene_radius(scene);
    power.push_back(std::numbers::pi * r * r * 4.0 * std::numbers::pi * map.average_radiance);
    out.arrays.env_texels = std::move(map.texels);
    out.arrays.env_marginal = std::move(map.marginal_cdf);
    out.arrays.env_conditional = std::move(map.conditional_cdf);
}

} // namespace

std::vector<double> compile_lights(const Scene& scene, const std::vector<std::uint32_t>& leaf_order, CompiledScene& out)
{
    std::vector<double> power;
    add_sphere_lights(scene, out.arrays.lights, power);
    out.sphere_count = out.arrays.lights.size();
    add_triangle_lights(scene, leaf_order, out, power);
    add_punctual_lights(scene, out.arrays.lights, power);
    if (scene.environment.present)
        add_environment_light(scene, out, power);
    return power;
}

} // namespace pathcl
