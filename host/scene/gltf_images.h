// Images of a glTF file: PNG and JPEG bytes (from files, data: URIs and bufferViews)
// decoded by OpenImageIO (image/image_module.h) into RGBA SceneImages, and the rule for which image URIs are
// read. tinygltf decodes nothing itself: load_gltf installs keep_encoded_image as its
// image loader, and the importer decodes the images textures use with decode_image.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "scene/scene.h"

namespace tinygltf {
struct Image;
}

namespace pathcl {

// Called with the bytes an image's decoding will hold at its peak (the decoder's copy
// and the RGBA image) before they are allocated; throws to refuse them.
using AdmitImageBytes = std::function<void(std::size_t)>;

// Decodes a PNG or JPEG image held in memory to RGBA with 8 or 16 bits per channel (16
// for 16-bit PNGs), alpha kept unassociated (colours are not premultiplied). Throws
// pathcl::Error("what: ...") for any other format or for undecodable bytes.
SceneImage decode_image(const unsigned char* bytes, std::size_t size, const std::string& what,
                        const AdmitImageBytes& admit = {});

// The pixels tinygltf holds for an image (as a program filled them in): width x height x component (1 to 4) channels of
// `bits` (8 or 16), expanded to RGBA. Throws pathcl::Error("what: ...") when they are inconsistent.
SceneImage image_from_pixels(const tinygltf::Image& image, const std::string& what, const AdmitImageBytes& admit = {});

// Image URIs are relative paths (resolved against the glTF file's directory) or data:
// URIs. Throws pathcl::Error("what: ...") for an absolute path or any other scheme.
void check_image_uri(const std::string& uri, const std::string& what);

// tinygltf's image loader callback (TinyGLTF::SetImageLoader): keeps the bytes of a uri
// or data: image undecoded in image->image and marks them so with bits 0; the importer
// decodes an image only when a texture uses it, so an unused image costs no memory.
// bufferView images are left alone (the importer reads them after checking the view's
// bounds, which tinygltf does not). Never fails.
bool keep_encoded_image(tinygltf::Image* image, int index, std::string* err, std::string* warn, int req_width,
                        int req_height, const unsigned char* bytes, int size, void* user_data);

} // namespace pathcl
