#include "render/device_scene.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <numbers>

#include "render/layer_albedo.h"

namespace pathcl {
namespace {

pcl_float4 f4(const glm::vec3& v, float w = 0.0f)
{
    return {v.x, v.y, v.z, w};
}

pcl_float4 f4(const glm::dvec3& v, float w = 0.0f)
{
    return f4(glm::vec3(v), w);
}

} // namespace

void build_light_alias_table(std::vector<Light>& lights, const std::vector<double>& power)
{
    // Vose's alias method, in double so that tiny lights keep their probability.
    std::size_t n = lights.size();
    if (n == 0)
        return;
    double total = 0.0;
    for (double p : power)
        total += p;
    std::vector<double> scaled(n);
    std::vector<std::size_t> small, large;
    for (std::size_t i = 0; i < n; ++i) {
        double pmf = total > 0.0 ? power[i] / total : 1.0 / static_cast<double>(n);
        scaled[i] = pmf * static_cast<double>(n);
        lights[i].alias = static_cast<pcl_int>(i);
        (scaled[i] < 1.0 ? small : large).push_back(i);
    }
    // Thresholds on the kernel's coin grid (light_pick); a light that has a slot of its
    // own keeps at least one grid step of it, so even a powerless light stays pickable.
    const double grid = static_cast<double>(LIGHT_PICK_GRID);
    std::vector<std::uint32_t> threshold(n, LIGHT_PICK_GRID); // leftovers: always keep
    while (!small.empty() && !large.empty()) {
        std::size_t s = small.back(), l = large.back();
        small.pop_back();
        threshold[s] = static_cast<std::uint32_t>(std::clamp(std::llround(scaled[s] * grid), 1LL,
                                                             static_cast<long long>(LIGHT_PICK_GRID)));
        lights[s].alias = static_cast<pcl_int>(l);
        scaled[l] = (scaled[l] + scaled[s]) - 1.0;
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Each light's pmf as the kernel realizes it: slot j comes up for the grid steps k
    // with (k n) >> 24 == j, and keeps its light for `threshold` of the coin's steps.
    std::vector<double> pmf(n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
        auto first_step = [&](std::uint64_t slot) { return (slot * LIGHT_PICK_GRID + n - 1) / n; };
        double slot = static_cast<double>(first_step(j + 1) - first_step(j)) / grid;
        double keep = static_cast<double>(threshold[j]) / grid;
        pmf[j] += slot * keep;
        pmf[static_cast<std::size_t>(lights[j].alias)] += slot * (1.0 - keep);
        lights[j].alias_threshold = threshold[j];
    }
    for (std::size_t i = 0; i < n; ++i)
        lights[i].radiance.w = static_cast<float>(pmf[i]);
}

namespace {

double luminance(const glm::vec3& c)
{
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
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

void add_punctual_lights(const Scene& scene, std::vector<Light>& lights, std::vector<double>& power)
{
    glm::vec3 lo, hi;
    scene_bounds(scene, lo, hi);
    double radius = scene.triangles.empty() ? 1.0 : 0.5 * glm::length(glm::dvec3(hi) - glm::dvec3(lo));
    for (const SceneLight& sl : scene.lights) {
        Light l{};
        l.p0 = f4(sl.position);
        l.p1 = f4(sl.direction);
        l.radiance = f4(sl.intensity);
        double lum = std::max(luminance(sl.intensity), 1e-12);
        switch (sl.type) {
        case SceneLight::Type::Point:
            l.type = LIGHT_POINT;
            power.push_back(4.0 * std::numbers::pi * lum);
            break;
        case SceneLight::Type::Spot:
            l.type = LIGHT_SPOT;
            l.p2 = {static_cast<float>(sl.cos_outer), static_cast<float>(sl.cos_inner), 0.0f, 0.0f};
            power.push_back(lum * spot_weighted_solid_angle(sl.cos_inner, sl.cos_outer));
            break;
        case SceneLight::Type::RectSpot:
            l.type = LIGHT_RECT_SPOT;
            l.p1.w = static_cast<float>(sl.tan_half_v);
            l.p2 = f4(sl.right, static_cast<float>(sl.tan_half_h));
            // Solid angle of a rectangular frustum with half-angles a, b: 4 asin(sin a sin b).
            power.push_back(lum * 4.0 *
                            std::asin(std::sin(std::atan(sl.tan_half_h)) * std::sin(std::atan(sl.tan_half_v))));
            break;
        case SceneLight::Type::Directional:
            l.type = LIGHT_DIRECTIONAL;
            // Power through the scene's bounding disk (pbrt's convention).
            power.push_back(lum * std::numbers::pi * radius * radius);
            break;
        case SceneLight::Type::Sphere:
            continue; // added first, by make_device_scene
        }
        lights.push_back(l);
    }
}

} // namespace

DeviceScene make_device_scene(const Scene& scene)
{
    DeviceScene ds;
    ds.features = scene_features(scene);
    auto start = std::chrono::steady_clock::now();
    BvhBuildInput input;
    std::size_t n = scene.triangles.size();
    input.box_min.resize(n);
    input.box_max.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const SceneTriangle& t = scene.triangles[i];
        input.box_min[i] = glm::min(t.v[0], glm::min(t.v[1], t.v[2]));
        input.box_max[i] = glm::max(t.v[0], glm::max(t.v[1], t.v[2]));
    }
    Bvh bvh = build_bvh(input);
    ds.bvh_build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ds.nodes = std::move(bvh.nodes);
    ds.bvh_stats = bvh;

    for (const SceneMaterial& m : scene.materials) {
        Material dm{};
        dm.base_color = f4(m.base_color);
        dm.emission = f4(m.emission);
        dm.specular_color = f4(m.specular_color, m.specular);
        dm.metallic = m.metallic;
        dm.roughness = m.roughness;
        dm.transmission = m.transmission;
        dm.ior = m.ior;
        dm.flags = (m.double_sided ? MATERIAL_DOUBLE_SIDED : 0u) | (m.thin_walled ? MATERIAL_THIN_WALLED : 0u);
        dm.base_color_texture = dm.metallic_roughness_texture = dm.emissive_texture = TEXTURE_NONE;
        dm.normal_texture = dm.specular_texture = dm.specular_color_texture = TEXTURE_NONE;
        dm.transmission_texture = TEXTURE_NONE;
        dm.smooth_layer_average = static_cast<float>(smooth_layer_average(m.ior));
        dm.normal_scale = m.normal_scale;
        ds.materials.push_back(dm);
    }
    if (ds.features.textures)
        ds.textures = pack_textures(scene, bvh.triangle_order, ds.materials);
    if (ds.features.normal_maps) {
        ds.tangents.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const TriangleTangent& t = scene.tangents[bvh.triangle_order[i]];
            ds.tangents[i] = {{t[0].x, t[0].y, t[0].z, t[0].w}, {t[1].x, t[1].y, t[1].z, t[1].w},
                              {t[2].x, t[2].y, t[2].z, t[2].w}};
        }
    }
    if (ds.features.vertex_colors) {
        ds.colors.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const TriangleColor& c = scene.colors[bvh.triangle_order[i]];
            ds.colors[i] = {f4(c[0]), f4(c[1]), f4(c[2])};
        }
    }

    if (ds.features.glossy || ds.features.transmission)
        ds.layer_albedo = layer_albedo_table();

    ds.triangles.resize(n);
    ds.shading.resize(n);
    std::vector<double> power;
    // Sphere lights first: the kernels test lights[0 .. sphere_count) against every ray.
    for (const SceneLight& sl : scene.lights) {
        if (sl.type != SceneLight::Type::Sphere)
            continue;
        Light l{};
        l.type = LIGHT_SPHERE;
        l.p0 = f4(sl.position, static_cast<float>(sl.radius));
        // Uniform outward radiance with the point light's total power 4 pi I.
        l.radiance = f4(sl.intensity / static_cast<float>(std::numbers::pi * sl.radius * sl.radius));
        ds.lights.push_back(l);
        power.push_back(4.0 * std::numbers::pi * std::max(luminance(sl.intensity), 1e-12));
    }
    ds.sphere_count = ds.lights.size();
    for (std::size_t i = 0; i < n; ++i) {
        const SceneTriangle& t = scene.triangles[bvh.triangle_order[i]];
        ds.triangles[i] = Triangle{f4(t.v[0]), f4(t.v[1]), f4(t.v[2])};
        TriangleShading& sh = ds.shading[i];
        sh = TriangleShading{f4(t.n[0]), f4(t.n[1]), f4(t.n[2]), t.material, -1, 0, 0};
        const SceneMaterial& m = scene.materials[static_cast<std::size_t>(t.material)];
        if (!m.emits())
            continue;
        double area = 0.5 * glm::length(glm::cross(glm::dvec3(t.v[1]) - glm::dvec3(t.v[0]),
                                                   glm::dvec3(t.v[2]) - glm::dvec3(t.v[0])));
        Light light{};
        light.type = LIGHT_TRIANGLE;
        light.p0 = f4(t.v[0], static_cast<float>(area));
        light.p1 = f4(t.v[1], std::bit_cast<float>(static_cast<pcl_int>(i)));
        light.p2 = f4(t.v[2]);
        light.radiance = f4(m.emission);
        light.texture = ds.materials[static_cast<std::size_t>(t.material)].emissive_texture;
        sh.emitter = static_cast<pcl_int>(ds.lights.size());
        ds.lights.push_back(light);
        // Emitted power of a one-sided Lambertian emitter: pi * area * radiance (luminance-
        // weighted); with an emissive texture, radiance = factor x the texture's mean over
        // the triangle (an estimate: it only sets how often the light is picked; the floor
        // keeps every emitter pickable, so the estimator stays unbiased).
        glm::dvec3 radiance(m.emission);
        if (m.emissive_texture.present()) {
            const SceneImage& img = scene.images[static_cast<std::size_t>(m.emissive_texture.image)];
            const TriangleUv& uv =
                scene.texcoords[static_cast<std::size_t>(m.emissive_texture.texcoord)][bvh.triangle_order[i]];
            radiance *= texture_mean_over_triangle(img, m.emissive_texture, true, uv);
        }
        power.push_back(std::numbers::pi * area * std::max(luminance(glm::vec3(radiance)), 1e-12));
    }
    add_punctual_lights(scene, ds.lights, power);
    if (scene.environment.present) {
        ds.environment = load_environment(scene.environment);
        double rot = scene.environment.rotation_degrees * std::numbers::pi / 180.0;
        Light l{};
        l.type = LIGHT_ENVIRONMENT;
        l.p0 = {static_cast<float>(ds.environment.width), static_cast<float>(ds.environment.height),
                static_cast<float>(std::cos(rot)), static_cast<float>(std::sin(rot))};
        ds.environment_light = static_cast<int>(ds.lights.size());
        ds.lights.push_back(l);
        // Power through the scene's bounding disk: pi r^2 times the radiance integrated
        // over the sphere (4 pi times its mean); an all-black map is never picked.
        glm::vec3 lo, hi;
        scene_bounds(scene, lo, hi);
        double r = scene.triangles.empty() ? 1.0 : 0.5 * glm::length(glm::dvec3(hi) - glm::dvec3(lo));
        power.push_back(std::numbers::pi * r * r * 4.0 * std::numbers::pi * ds.environment.average_radiance);
    }
    build_light_alias_table(ds.lights, power);
    return ds;
}

Camera make_device_camera(const SceneCamera& cam, std::uint32_t width, std::uint32_t height)
{
    // The image's aspect ratio wins over the file's: the vertical extent (yfov, or ymag)
    // is kept and the horizontal one follows the image.
    double half_height = cam.orthographic ? cam.ymag : std::tan(0.5 * cam.yfov);
    double aspect = static_cast<double>(width) / static_cast<double>(height);
    Camera c{};
    c.type = cam.orthographic ? CAMERA_ORTHOGRAPHIC : CAMERA_PERSPECTIVE;
    c.position = f4(cam.position);
    c.forward = f4(glm::normalize(cam.forward));
    c.right = f4(glm::normalize(cam.right) * (half_height * aspect));
    c.up = f4(glm::normalize(cam.up) * half_height);
    if (cam.aperture > 0.0) {
        c.lens_radius = static_cast<float>(cam.aperture);
        c.focus_distance = static_cast<float>(cam.focus_distance);
    }
    return c;
}

} // namespace pathcl
