// move_to_render_space: the origin, then the triangles rounded to float relative to it
// (the zero-area test is made on the rounded positions the device will see), the lights
// and the camera.
#include "scene/render_space.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "common/error.h"

namespace pathcl {
namespace {

// The end of mesh k's triangles among the pending ones.
std::size_t mesh_end(const PendingGeometry& geometry, std::size_t k)
{
    return k + 1 < geometry.mesh_starts.size() ? geometry.mesh_starts[k + 1] : geometry.triangles.size();
}

// The camera position when the file gives the camera, else the centre of the geometry's
// bounds, instances included (the world origin for an empty scene).
glm::dvec3 render_origin(const PendingGeometry& geometry, bool have_camera, const SceneCamera& camera)
{
    glm::dvec3 origin(0.0);
    if (have_camera) {
        origin = camera.position;
    } else if (!geometry.triangles.empty()) {
        const double inf = std::numeric_limits<double>::infinity();
        glm::dvec3 lo(inf), hi(-inf);
        const std::size_t world_end =
            geometry.mesh_starts.empty() ? geometry.triangles.size() : geometry.mesh_starts[0];
        for (std::size_t t = 0; t < world_end; ++t)
            for (const glm::dvec3& v : geometry.triangles[t].v) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
        std::vector<std::pair<glm::dvec3, glm::dvec3>> mesh_box(geometry.mesh_starts.size(),
                                                                {glm::dvec3(inf), glm::dvec3(-inf)});
        for (std::size_t k = 0; k < geometry.mesh_starts.size(); ++k)
            for (std::size_t t = geometry.mesh_starts[k]; t < mesh_end(geometry, k); ++t)
                for (const glm::dvec3& v : geometry.triangles[t].v) {
                    mesh_box[k].first = glm::min(mesh_box[k].first, v);
                    mesh_box[k].second = glm::max(mesh_box[k].second, v);
                }
        for (const PendingInstance& instance : geometry.instances)
            add_mapped_box(instance.world, mesh_box[instance.mesh].first, mesh_box[instance.mesh].second, lo, hi);
        if (lo.x <= hi.x)
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
    // Each instanced mesh keeps its own space; its triangles follow those drawn once.
    std::size_t next_mesh = 0;
    bool in_mesh = false;
    for (std::size_t index = 0; index < geometry.triangles.size(); ++index) {
        while (next_mesh < geometry.mesh_starts.size() && geometry.mesh_starts[next_mesh] == index) {
            scene.meshes.push_back(SceneMesh{scene.triangles.size(), 0});
            ++next_mesh;
            in_mesh = true;
        }
        const PendingTriangle& pt = geometry.triangles[index];
        SceneTriangle tri;
        tri.material = pt.material;
        for (int k = 0; k < 3; ++k)
            tri.v[k] = glm::vec3(in_mesh ? pt.v[k] : world_to_render(origin, pt.v[k]));
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
        if (in_mesh)
            ++scene.meshes.back().count;
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
    while (next_mesh++ < geometry.mesh_starts.size()) // meshes at the very end with no triangles
        scene.meshes.push_back(SceneMesh{scene.triangles.size(), 0});
    geometry.triangles.clear();
}

// The instances in render space, those of meshes left without triangles (all degenerate)
// dropped, and such meshes with them.
void finish_instances(const PendingGeometry& geometry, const glm::dvec3& origin, Scene& scene)
{
    std::vector<std::uint32_t> renumbered(scene.meshes.size(), UINT32_MAX);
    std::vector<SceneMesh> kept;
    for (std::size_t k = 0; k < scene.meshes.size(); ++k)
        if (scene.meshes[k].count > 0) {
            renumbered[k] = static_cast<std::uint32_t>(kept.size());
            kept.push_back(scene.meshes[k]);
        }
    scene.meshes = std::move(kept);
    const glm::dmat4 to_render = glm::translate(glm::dmat4(1.0), -origin);
    for (const PendingInstance& instance : geometry.instances)
        if (renumbered[instance.mesh] != UINT32_MAX)
            scene.instances.push_back(SceneInstance{renumbered[instance.mesh], to_render * instance.world});
}

// Render-space positions are floats, and so is all arithmetic on them: the BVH's box
// centres, extents and areas, a ray's distances. Within this distance of the origin the
// builder's box areas (the square of an extent, twice this) stay finite; a scene beyond
// it (a transform of 1e38) would make infinite boxes and NaN bin indices.
constexpr double kMaxRenderSpaceDistance = 1e18;

void check_render_space_bounds(const Scene& scene)
{
    glm::vec3 lo, hi;
    scene_bounds(scene, lo, hi);
    double reach = 0.0;
    if (lo.x <= hi.x)
        for (int a = 0; a < 3; ++a)
            reach = std::max({reach, std::fabs(static_cast<double>(lo[a])), std::fabs(static_cast<double>(hi[a]))});
    for (const SceneLight& l : scene.lights)
        for (int a = 0; a < 3 && l.type != SceneLight::Type::Directional; ++a)
            reach = std::max(reach, std::fabs(l.position[a]));
    if (!(reach <= kMaxRenderSpaceDistance)) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "the scene reaches %.3g from its centre (its camera, or the middle of its geometry), beyond "
                      "the %.0e a float render can hold: a transform or a position is too large",
                      reach, kMaxRenderSpaceDistance);
        throw Error(text);
    }
}

} // namespace

void move_to_render_space(PendingGeometry& geometry, bool have_camera, Scene& scene)
{
    const glm::dvec3 origin = render_origin(geometry, have_camera, scene.camera);
    finish_triangles(geometry, origin, scene);
    finish_instances(geometry, origin, scene);
    for (SceneLight& l : scene.lights)
        l.position = world_to_render(origin, l.position);
    scene.render_origin = origin;
    check_render_space_bounds(scene);
    if (have_camera)
        scene.camera.position = world_to_render(origin, scene.camera.position);
    else
        scene.camera = framing_camera(scene, 0.8);
}

} // namespace pathcl
