// The glTF camera on a node to a SceneCamera: perspective or orthographic projection, the
// frame from the node's world transform, and the thin lens of this renderer's node extras
// {"aperture": R, "focusDistance": D}. The position stays in world space until the
// render-space origin is known.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace tinygltf {
struct Camera;
class Value;
} // namespace tinygltf

namespace pathcl {

// `cam` on a node with world transform `world` and extras `extras`; `what` names the node
// in errors. Throws pathcl::Error("SOURCE: WHAT: what is wrong").
SceneCamera import_camera(const tinygltf::Camera& cam, const tinygltf::Value& extras, const glm::dmat4& world,
                          const std::string& what, const std::string& source);

} // namespace pathcl
