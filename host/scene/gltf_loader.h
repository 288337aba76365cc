// glTF 2.0 (.gltf / .glb) to the flat Scene, following docs/gltf.md: default
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

// What a file offers a choice of.
struct SceneChoice {
    // The camera node (perspective or orthographic) by its place among the default
    // scene's camera nodes in depth-first node order, counted from 0 (--camera N); -1
    // takes the first one if there is any, else a camera framing the scene.
    int camera = -1;
    // The KHR_materials_variants variant by name (--variant NAME); "" the default
    // materials.
    std::string variant;
    // Copy a mesh into render space for every node or instance that draws it, instead of
    // storing it once and drawing instances of it (--copy-instances).
    bool copy_instances = false;
};

// Loads a file; throws pathcl::Error("FILE: what is wrong") on any problem, and
// ParameterError("camera" or "variant", ...) for a choice the file does not offer.
Scene load_gltf(const std::string& path, const SceneChoice& choice = {});

// Imports an already parsed model; `source` names it in error messages; `base_dir` is
// where relative URIs (the environment map in scene extras) resolve, if anywhere.
Scene import_gltf(const tinygltf::Model& model, const std::string& source, const std::string& base_dir = "",
                  const SceneChoice& choice = {});

} // namespace pathcl
