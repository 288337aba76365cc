// The camera for the device, for one image size.
#include <cmath>

#include "compile/compile_scene.h"

namespace pathcl {

Camera compile_camera(const SceneCamera& cam, std::uint32_t width, std::uint32_t height)
{
    // The image's aspect ratio wins over the file's: the vertical extent (yfov, or ymag)
    // is kept and the horizontal one follows the image.
    double half_height = cam.orthographic ? cam.ymag : std::tan(0.5 * cam.yfov);
    double aspect = static_cast<double>(width) / static_cast<double>(height);
    Camera c{};
    c.type = cam.orthographic ? CAMERA_ORTHOGRAPHIC : CAMERA_PERSPECTIVE;
    c.position = to_float4(cam.position);
    c.forward = to_float4(glm::normalize(cam.forward));
    c.right = to_float4(glm::normalize(cam.right) * (half_height * aspect));
    c.up = to_float4(glm::normalize(cam.up) * half_height);
    if (cam.aperture > 0.0) {
        c.lens_radius = static_cast<float>(cam.aperture);
        c.focus_distance = static_cast<float>(cam.focus_distance);
    }
    return c;
}

} // namespace pathcl
