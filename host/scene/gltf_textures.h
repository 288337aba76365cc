// The textures of glTF materials: a textureInfo (index, texCoord, KHR_texture_transform)
// with its texture's sampler and image becomes a SceneTexture; each image is decoded
// once, when the first texture reads it. Everything read is checked: a bad index, wrap
// mode, filter or transform, or an unreadable image, is a pathcl::Error naming the file.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
class Model;
class Value;
} // namespace tinygltf

namespace pathcl {

class TextureImporter {
public:
    // `source` names the file in errors; `base_dir` is where relative URIs resolved.
    TextureImporter(const tinygltf::Model& model, const std::string& source, const std::string& base_dir);

    // The slot with texture `index` read through TEXCOORD_`texcoord`, and the
    // KHR_texture_transform object `transform` (null if absent). `where` names the slot
    // in errors ("material 2 (brick) baseColorTexture").
    SceneTexture read(int index, int texcoord, const tinygltf::Value* transform, const std::string& where);

    // A textureInfo given as a JSON object (the KHR material extensions'): {"index": i,
    // "texCoord": n, "extensions": {"KHR_texture_transform": ...}}.
    SceneTexture read(const tinygltf::Value& texture_info, const std::string& where);

    // The images read so far, indexed by SceneTexture::image.
    std::vector<SceneImage> take_images() { return std::move(images_); }

    // The reasons the file-system callbacks gave for refusing files ("uri: reason"), so
    // that an image left unread says why; null if none were kept.
    void set_refusals(const std::vector<std::string>* refusals) { refusals_ = refusals; }

    // All decoded images together may hold at most this many bytes (4 GiB): a few small
    // PNGs of huge dimensions must not exhaust the host's memory.
    static constexpr std::size_t kMaxTotalImageBytes = std::size_t(4) << 30;

private:
    int image(int gltf_image, const std::string& where);

    const tinygltf::Model& model_;
    std::string source_, base_dir_;
    std::vector<int> scene_image_; // glTF image index -> index in images_, -1 until read
    std::vector<SceneImage> images_;
    std::size_t image_bytes_ = 0; // decoded so far
    const std::vector<std::string>* refusals_ = nullptr;
};

// KHR_texture_transform as the rows of the 2x3 matrix (u', v') = M (u, v, 1), the order
// the extension specifies (translation x rotation x scale), with the rotation sign of its
// example and of the reference viewers (docs/gltf.md, "Textures"):
//   u' =  sx cos(r) u + sy sin(r) v + ox,   v' = -sx sin(r) u + sy cos(r) v + oy.
void texture_transform_matrix(double offset_u, double offset_v, double rotation, double scale_u, double scale_v,
                              glm::vec3& row_u, glm::vec3& row_v);

} // namespace pathcl
