#include "scene/scene.h"

#include <cmath>
#include <limits>

namespace pathcl {

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
