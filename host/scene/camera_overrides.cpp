#include "scene/camera_overrides.h"

#include <cmath>
#include <numbers>

#include "common/error.h"

namespace pathcl {
namespace {

bool finite(const glm::dvec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

void apply_camera_overrides(Scene& scene, const CameraOverrides& o)
{
    SceneCamera& c = scene.camera;
    if (o.fov_degrees) {
        if (c.orthographic)
            throw Error("--fov: the selected camera is orthographic (its view size is the file's ymag)");
        if (!(*o.fov_degrees > 0.0 && *o.fov_degrees < 180.0))
            throw Error("--fov must be in (0, 180) degrees");
        c.yfov = *o.fov_degrees * std::numbers::pi / 180.0;
    }
    if (o.look_from || o.look_at || o.up) {
        for (const auto* v : {&o.look_from, &o.look_at, &o.up})
            if (*v && !finite(**v))
                throw Error("--look-from, --look-at and --up need finite numbers");
        // Render space is world space minus render_origin (see scene.h).
        glm::dvec3 position = o.look_from ? *o.look_from - scene.render_origin : c.position;
        glm::dvec3 forward = c.forward;
        if (o.look_at) {
            glm::dvec3 to = *o.look_at - scene.render_origin - position;
            if (!(glm::length(to) > 0.0))
                throw Error("--look-at must differ from the camera position");
            forward = glm::normalize(to);
        }
        glm::dvec3 up_hint = o.up ? *o.up : c.up;
        glm::dvec3 right = glm::cross(forward, up_hint);
        if (!(glm::length(right) > 1e-9 * glm::length(up_hint)))
            throw Error("--up must not be parallel to the viewing direction (or zero)");
        c.position = position;
        c.forward = forward;
        c.right = glm::normalize(right);
        c.up = glm::cross(c.right, c.forward);
    }
    if (o.focus_distance) {
        if (!(*o.focus_distance > 0.0 && std::isfinite(*o.focus_distance)))
            throw Error("--focus-distance must be positive");
        c.focus_distance = *o.focus_distance;
    }
    if (o.aperture) {
        if (!(*o.aperture >= 0.0 && std::isfinite(*o.aperture)))
            throw Error("--aperture must be >= 0");
        c.aperture = *o.aperture;
    }
    if (c.aperture > 0.0 && !(c.focus_distance > 0.0))
        throw Error("--aperture needs --focus-distance (or the camera node's extras.focusDistance)");
}

} // namespace pathcl
