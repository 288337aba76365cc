// KHR_lights_punctual lights to SceneLights, with this renderer's extras: a point light
// with extras.radius becomes a sphere light, a spot light with extras hfov and vfov a
// rectangular spot. Positions stay in world space until the render-space origin is known.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace tinygltf {
class Model;
class Value;
} // namespace tinygltf

namespace pathcl {

// The light whose index the node's KHR_lights_punctual object gives (`index_value`), on
// a node with world transform `world`; `what` names the node in errors. Throws
// pathcl::Error("SOURCE: WHAT: light N: what is wrong") for a bad light.
SceneLight import_light(const tinygltf::Model& model, const tinygltf::Value& index_value, const glm::dmat4& world,
                        const std::string& what, const std::string& source);

} // namespace pathcl
