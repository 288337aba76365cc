// move_to_render_space: the origin, then the triangles rounded to float relative to it
// (the zero-area test is made on the rounded positions the device will see), the lights
// and the camera.
#include "scene/render_space.h"

#include <cmath>
#include <limits>

namespace pathcl {
namespace {

// The camera position when the file gives the camera, else the centre of the geometry's
// bounds (the world origin for an empty scene).
glm::dvec3 render_origin(const PendingGeometry& geometry, bool have_camera, const SceneCamera& camera)
{
    glm::dvec3 origin(0.0);
    if (have_camera) {
        origin = camera.position;
    } else if (!geometry.triangles.empty()) {
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (const PendingTriangle& t : geometry.triangles)
            for (const glm::dvec3& v : t.v) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
        origin = 0.5 * (lo + hi);
    }
    return origin;
}

// Converts the double-precision world triangles to float, relative to `origin`.
void finish_triangles(PendingGeometry& geometry, const glm::dvec3& origin, Scene& scene)
{
    scene.triangles.reserve(geometry.triangles.size());
    scene.texcoords.resize(geometry.texcoord_used.size());
    if (!geometry.colors.empty())
        geometry.colors.resize(geometry.triangles.size(), kWhiteTriangleColor);
    for (std::size_t index = 0; index < geometry.triangles.size(); ++index) {
        const PendingTriangle& pt = geometry.triangles[index];
        SceneTriangle tri;
        tri.material = pt.material;
        for (int k = 0; k < 3; ++k)
            tri.v[k] = glm::vec3(world_to_render(origin, pt.v[k]));
        // Degenerate (zero area in the float positions the device will see): drop.
        glm::vec3 c = glm::cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0]);
        float len = glm::length(c);
        if (!(len > 0.0f) || !std::isfinite(len)) {
            ++scene.dropped_degenerate;
            continue;
        }
        glm::vec3 ng = c / len;
        for (int k = 0; k < 3; ++k) {
            glm::vec3 sn = ng;
            if (pt.has_normals) {
                double l = glm::length(pt.n[k]);
                if (l > 0.0 && std::isfinite(l))
                    sn = glm::vec3(pt.n[k] / l);
                else
                    ++scene.repaired_normals;
            }
            tri.n[k] = sn;
        }
        scene.triangles.push_back(tri);
        for (std::size_t set = 0; set < geometry.texcoord_used.size(); ++set)
            if (geometry.texcoord_used[set])
                scene.texcoords[set].push_back(geometry.texcoords[set][index]);
        if (geometry.tangents_used) {
            TriangleTangent t;
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::dvec4& wt = geometry.tangents[index][k];
                double tl = glm::length(glm::dvec3(wt));
                t[k] = (tl > 0.0 && std::isfinite(tl)) ? glm::vec4(glm::dvec3(wt) / tl, wt.w) : glm::vec4(0.0f);
            }
            scene.tangents.push_back(t);
        }
        if (!geometry.colors.empty())
            scene.colors.push_back(geometry.colors[index]);
    }
    geometry.triangles.clear();
}

} // namespace

void move_to_render_space(PendingGeometry& geometry, bool have_camera, Scene& scene)
{
    const glm::dvec3 origin = render_origin(geometry, have_camera, scene.camera);
    finish_triangles(geometry, origin, scene);
    for (SceneLight& l : scene.lights)
        l.position = world_to_render(origin, l.position);
    scene.render_origin = origin;
    if (have_camera)
        scene.camera.position = world_to_render(origin, scene.camera.position);
    else
        scene.camera = framing_camera(scene, 0.8);
}

} // namespace pathcl
