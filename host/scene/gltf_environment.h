// The environment map of this renderer's scene extras, {"environment": {"uri": "sky.exr",
// "strength": s}}: the uri is relative to the glTF file and must stay inside its
// directory, so that a scene cannot make the renderer read files elsewhere.
#pragma once

#include <string>

#include "scene/scene.h"

namespace tinygltf {
class Value;
}

namespace pathcl {

// The environment that the scene's `extras` give (none when they give none); relative
// uris resolve against `base_dir`. Throws pathcl::Error("SOURCE: what is wrong").
SceneEnvironment import_environment(const tinygltf::Value& extras, const std::string& base_dir,
                                    const std::string& source);

} // namespace pathcl
