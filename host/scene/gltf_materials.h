// glTF materials to SceneMaterials: metallic-roughness with its textures and the KHR
// material extensions the renderer supports, each range-checked here so that a bad
// factor is an error naming the material, not NaN or negative energy in the kernels.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace pathcl {

class TextureImporter;

// The model's materials, in order, their textures read through `textures`. Throws
// pathcl::Error("SOURCE: material N (name): what is wrong").
std::vector<SceneMaterial> import_materials(const tinygltf::Model& model, TextureImporter& textures,
                                            const std::string& source);

} // namespace pathcl
