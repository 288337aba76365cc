#include "scene/scene.h"

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace pathcl {

std::size_t Scene::drawn_triangles() const
{
    std::size_t n = render_space_triangles();
    for (const SceneInstance& i : instances)
        n += meshes[i.mesh].count;
    return n;
}

void scene_bounds(const Scene& scene, glm::vec3& lo, glm::vec3& hi)
{
    lo = glm::vec3(std::numeric_limits<float>::infinity());
    hi = -lo;
    for (std::size_t t = 0; t < scene.render_space_triangles(); ++t)
        for (const glm::vec3& v : scene.triangles[t].v) {
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
    // An instance adds its mesh's box mapped to render space.
    std::vector<std::pair<glm::dvec3, glm::dvec3>> mesh_box(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        glm::dvec3 mlo(std::numeric_limits<double>::infinity()), mhi = -mlo;
        const SceneMesh& mesh = scene.meshes[m];
        for (std::size_t t = mesh.first; t < mesh.first + mesh.count; ++t)
            for (const glm::vec3& v : scene.triangles[t].v) {
                mlo = glm::min(mlo, glm::dvec3(v));
                mhi = glm::max(mhi, glm::dvec3(v));
            }
        mesh_box[m] = {mlo, mhi};
    }
    glm::dvec3 ilo(std::numeric_limits<double>::infinity()), ihi = -ilo;
    for (const SceneInstance& instance : scene.instances)
        add_mapped_box(instance.to_render, mesh_box[instance.mesh].first, mesh_box[instance.mesh].second, ilo, ihi);
    if (ilo.x <= ihi.x) { // (float rounding is monotonic: the rounded corners' min is the min's rounding)
        lo = glm::min(lo, glm::vec3(ilo));
        hi = glm::max(hi, glm::vec3(ihi));
    }
}

void add_mapped_box(const glm::dmat4& m, const glm::dvec3& box_lo, const glm::dvec3& box_hi, glm::dvec3& lo,
                    glm::dvec3& hi)
{
    if (!(box_lo.x <= box_hi.x))
        return;
    for (int corner = 0; corner < 8; ++corner) {
        glm::dvec3 c((corner & 1) ? box_hi.x : box_lo.x, (corner & 2) ? box_hi.y : box_lo.y,
                     (corner & 4) ? box_hi.z : box_lo.z);
        glm::dvec3 p(m * glm::dvec4(c, 1.0));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
}

std::vector<SceneTriangle> drawn_triangle_list(const Scene& scene)
{
    std::vector<SceneTriangle> out(
        scene.triangles.begin(), scene.triangles.begin() + static_cast<std::ptrdiff_t>(scene.render_space_triangles()));
    for (const SceneInstance& instance : scene.instances) {
        const SceneMesh& mesh = scene.meshes[instance.mesh];
        const glm::dmat3 m3(instance.to_render);
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(m3));
        const bool mirrored = glm::determinant(m3) < 0.0;
        for (std::size_t t = mesh.first; t < mesh.first + mesh.count; ++t) {
            SceneTriangle tri = scene.triangles[t];
            for (int k = 0; k < 3; ++k) {
                tri.v[k] = glm::vec3(instance.to_render * glm::dvec4(tri.v[k], 1.0));
                tri.n[k] = glm::vec3(glm::normalize(normal_matrix * glm::dvec3(tri.n[k])));
            }
            if (mirrored) {
                std::swap(tri.v[1], tri.v[2]);
                std::swap(tri.n[1], tri.n[2]);
            }
            out.push_back(tri);
        }
    }
    return out;
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
