#include "scene/camera_overrides.h"

#include <cmath>
#include <numbers>

#include "common/error.h"
#include "scene/render_space.h"

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
            throw ParameterError("fov", "the selected camera is orthographic (its view size is the file's ymag)");
        if (!(*o.fov_degrees > 0.0 && *o.fov_degrees < 180.0))
            throw ParameterError("fov", "must be in (0, 180) degrees");
        c.yfov = *o.fov_degrees * std::numbers::pi / 180.0;
    }
    if (o.look_from || o.look_at || o.up) {
        for (const auto& [v, name] : {std::pair{&o.look_from, "look_from"}, {&o.look_at, "look_at"}, {&o.up, "up"}})
            if (*v && !finite(**v))
                throw ParameterError(name, "needs finite numbers");
        glm::dvec3 position = o.look_from ? world_to_render(scene.render_origin, *o.look_from) : c.position;
        glm::dvec3 forward = c.forward;
        if (o.look_at) {
            glm::dvec3 to = world_to_render(scene.render_origin, *o.look_at) - position;
            if (!(glm::length(to) > 0.0))
                throw ParameterError("look_at", "must differ from the camera position");
            forward = glm::normalize(to);
        }
        glm::dvec3 up_hint = o.up ? *o.up : c.up;
        glm::dvec3 right = glm::cross(forward, up_hint);
        if (!(glm::length(right) > 1e-9 * glm::length(up_hint)))
            throw ParameterError("up", "must not be parallel to the viewing direction (or zero)");
        c.position = position;
        c.forward = forward;
        c.right = glm::normalize(right);
        c.up = glm::cross(c.right, c.forward);
    }
    if (o.focus_distance) {
        if (!(*o.focus_distance > 0.0 && std::isfinite(*o.focus_distance)))
            throw ParameterError("focus_distance", "must be positive");
        c.focus_distance = *o.focus_distance;
    }
    if (o.aperture) {
        if (!(*o.aperture >= 0.0 && std::isfinite(*o.aperture)))
            throw ParameterError("aperture", "must be >= 0");
        c.aperture = *o.aperture;
    }
    if (c.aperture > 0.0 && !(c.focus_distance > 0.0))
        throw ParameterError("aperture", "needs {focus_distance} (or the camera node's extras.focusDistance)");
}

} // namespace pathcl
