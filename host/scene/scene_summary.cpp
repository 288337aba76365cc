#include "scene/scene_summary.h"

#include <cmath>
#include <cstdio>

namespace pathcl {

SceneSummary summarize_scene(const Scene& scene)
{
    SceneSummary s;
    s.triangles = scene.drawn_triangles();
    s.stored_triangles = scene.triangles.size();
    s.instances = scene.instances.size();
    s.instanced_meshes = scene.meshes.size();
    s.dropped_degenerate = scene.dropped_degenerate;
    std::vector<bool> used(scene.materials.size(), false);
    for (const SceneTriangle& t : scene.triangles) {
        const SceneMaterial& m = scene.materials[static_cast<std::size_t>(t.material)];
        s.emissive_triangles += m.emits() ? 1 : 0;
        used[static_cast<std::size_t>(t.material)] = true;
    }
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (!used[i])
            continue;
        const SceneMaterial& m = scene.materials[i];
        ++s.materials;
        s.diffuse += m.metallic < 1.0f && m.transmission < 1.0f ? 1 : 0;
        s.metal += m.metallic > 0.0f ? 1 : 0;
        s.specular_layer += m.metallic < 1.0f && m.specular > 0.0f ? 1 : 0;
        s.transmission += m.transmission > 0.0f ? 1 : 0;
        s.emissive += m.emits() ? 1 : 0;
        s.textured += m.has_textures() ? 1 : 0;
        s.normal_mapped += m.textures[TEXTURE_SLOT_NORMAL].present() ? 1 : 0;
    }
    for (const SceneLight& l : scene.lights) {
        switch (l.type) {
        case SceneLight::Type::Point:
            ++s.point_lights;
            break;
        case SceneLight::Type::Spot:
            ++s.spot_lights;
            break;
        case SceneLight::Type::RectSpot:
            ++s.rect_spot_lights;
            break;
        case SceneLight::Type::Directional:
            ++s.directional_lights;
            break;
        case SceneLight::Type::Sphere:
            ++s.sphere_lights;
            break;
        }
    }
    s.images = scene.images.size();
    for (const SceneImage& img : scene.images)
        s.texels += static_cast<std::size_t>(img.width) * img.height;
    s.vertex_colors = !scene.colors.empty();

    char buf[256];
    const SceneEnvironment& env = scene.environment;
    if (!env.present)
        s.environment = "none";
    else if (env.path.empty()) {
        std::snprintf(buf, sizeof buf, "constant (%g, %g, %g) x %g", env.constant.x, env.constant.y, env.constant.z,
                      env.strength);
        s.environment = buf;
    } else {
        std::snprintf(buf, sizeof buf, "image %u x %u (%s) x %g", env.width, env.height, env.path.c_str(),
                      env.strength);
        s.environment = buf;
    }
    const SceneCamera& cam = scene.camera;
    if (cam.orthographic)
        std::snprintf(buf, sizeof buf, "orthographic, view height %g", 2.0 * cam.ymag);
    else
        std::snprintf(buf, sizeof buf, "perspective, vertical FOV %.1f degrees", cam.yfov * 180.0 / M_PI);
    s.camera = buf;
    if (cam.aperture > 0.0) {
        std::snprintf(buf, sizeof buf, ", thin lens (aperture radius %g, focus distance %g)", cam.aperture,
                      cam.focus_distance);
        s.camera += buf;
    } else if (!cam.orthographic) {
        s.camera += ", pinhole";
    }
    if (!cam.from_file)
        s.camera += " (default camera: the scene has none)";
    return s;
}

} // namespace pathcl
