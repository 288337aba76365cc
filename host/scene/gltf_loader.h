// glTF 2.0 (.gltf / .glb) to the flat Scene, following ../shared/CONVENTIONS.md: default
// scene, node hierarchy composed in double precision, triangles (strips and fans
// converted), shading normals, metallic-roughness materials with emissive strength, and
// one perspective or orthographic camera (with an optional thin lens).
#pragma once

#include <string>

#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace pathcl {

// Loads a file; throws pathcl::Error("FILE: what is wrong") on any problem. `camera`
// picks the camera node (perspective or orthographic) by its place among the default
// scene's camera nodes in depth-first node order, counted from 0 (--camera N); -1 takes
// the first one if there is any, else a camera framing the scene.
Scene load_gltf(const std::string& path, int camera = -1);

// Imports an already parsed model; `source` names it in error messages; `base_dir` is
// where relative URIs (the environment map in scene extras) resolve, if anywhere.
Scene import_gltf(const tinygltf::Model& model, const std::string& source, const std::string& base_dir = "",
                  int camera = -1);

} // namespace pathcl
