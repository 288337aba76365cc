// import_camera: the projection's checks, the frame (node scale does not change the
// projection), then the thin-lens extras, in world units.
#include "scene/gltf_camera.h"

#include <cmath>
#include <numbers>

#include <tiny_gltf.h>

#include "common/error.h"

namespace pathcl {

SceneCamera import_camera(const tinygltf::Camera& cam, const tinygltf::Value& extras, const glm::dmat4& world,
                          const std::string& what, const std::string& source)
{
    SceneCamera c;
    if (cam.type == "perspective") {
        double yfov = cam.perspective.yfov;
        if (!(yfov > 0.0 && yfov < std::numbers::pi))
            throw Error(source + ": " + what + ": perspective yfov must be in (0, pi)");
        c.yfov = yfov;
        c.orthographic = false;
    } else if (cam.type == "orthographic") {
        double ymag = cam.orthographic.ymag;
        if (!(ymag > 0.0 && std::isfinite(ymag)))
            throw Error(source + ": " + what + ": orthographic ymag must be positive");
        c.ymag = ymag;
        c.orthographic = true;
    } else {
        throw Error(source + ": " + what + ": unknown camera type " + quote(cam.type));
    }
    glm::dmat3 m3(world);
    glm::dvec3 forward = m3 * glm::dvec3(0.0, 0.0, -1.0);
    glm::dvec3 up = m3 * glm::dvec3(0.0, 1.0, 0.0);
    glm::dvec3 right = glm::cross(forward, up);
    if (!(glm::length(forward) > 0.0) || !(glm::length(right) > 0.0))
        throw Error(source + ": " + what + ": the camera transform is degenerate");
    c.position = glm::dvec3(world[3]);
    c.forward = glm::normalize(forward); // node scale does not change the projection
    c.right = glm::normalize(right);
    c.up = glm::cross(c.right, c.forward);
    c.from_file = true;
    // Thin lens, in world units (node scale does not change them).
    auto number = [&](const char* key) {
        const tinygltf::Value& v = extras.Get(key);
        if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()))
            throw Error(source + ": " + what + ": extras." + key + " must be a number");
        return v.GetNumberAsDouble();
    };
    if (extras.IsObject() && extras.Has("aperture")) {
        c.aperture = number("aperture");
        if (c.aperture < 0.0)
            throw Error(source + ": " + what + ": extras.aperture must be >= 0");
        if (c.aperture > 0.0 && !extras.Has("focusDistance"))
            throw Error(source + ": " + what + ": extras.aperture needs extras.focusDistance");
    }
    if (extras.IsObject() && extras.Has("focusDistance")) {
        c.focus_distance = number("focusDistance");
        if (!(c.focus_distance > 0.0))
            throw Error(source + ": " + what + ": extras.focusDistance must be positive");
    }
    return c;
}

} // namespace pathcl
