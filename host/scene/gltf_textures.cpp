#include "scene/gltf_textures.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <tiny_gltf.h>

#include "common/error.h"
#include "common/memory_limits.h"
#include "scene/gltf_images.h"

namespace pathcl {
namespace {

// glTF sampler enums.
constexpr int kNearest = 9728, kLinear = 9729;
constexpr int kRepeat = 10497, kClampToEdge = 33071, kMirroredRepeat = 33648;
// Highest TEXCOORD_n read (no file needs more; it bounds what a bad index allocates).
constexpr int kMaxTexcoordSet = 255;

// A JSON number, `fallback` if the key is absent; anything else is an error.
double number(const tinygltf::Value& obj, const char* key, double fallback, const std::string& where)
{
    if (!obj.Has(key))
        return fallback;
    const tinygltf::Value& v = obj.Get(key);
    if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()))
        throw Error(where + ": " + quote(key) + " must be a finite number");
    return v.GetNumberAsDouble();
}

// A JSON array of two finite numbers, `fallback` if the key is absent.
void pair(const tinygltf::Value& obj, const char* key, double fallback, double& a, double& b, const std::string& where)
{
    a = b = fallback;
    if (!obj.Has(key))
        return;
    const tinygltf::Value& v = obj.Get(key);
    bool ok = v.IsArray() && v.ArrayLen() == 2 && v.Get(0).IsNumber() && v.Get(1).IsNumber();
    if (ok) {
        a = v.Get(0).GetNumberAsDouble();
        b = v.Get(1).GetNumberAsDouble();
    }
    if (!ok || !std::isfinite(a) || !std::isfinite(b))
        throw Error(where + ": " + quote(key) + " must be an array of two finite numbers");
}

TextureWrap wrap_mode(int mode, const std::string& where)
{
    switch (mode) {
    case kRepeat:
        return TextureWrap::Repeat;
    case kClampToEdge:
        return TextureWrap::ClampToEdge;
    case kMirroredRepeat:
        return TextureWrap::MirroredRepeat;
    default:
        throw Error(where + ": unknown wrap mode " + std::to_string(mode));
    }
}

} // namespace

void texture_transform_matrix(double offset_u, double offset_v, double rotation, double scale_u, double scale_v,
                              glm::vec3& row_u, glm::vec3& row_v)
{
    double c = std::cos(rotation), s = std::sin(rotation);
    row_u = glm::vec3(glm::dvec3(scale_u * c, scale_v * s, offset_u));
    row_v = glm::vec3(glm::dvec3(-scale_u * s, scale_v * c, offset_v));
}

TextureImporter::TextureImporter(const tinygltf::Model& model, const std::string& source, const std::string& base_dir)
    : model_(model), source_(source), base_dir_(base_dir), scene_image_(model.images.size(), -1)
{}

SceneTexture TextureImporter::read(int index, int texcoord, const tinygltf::Value* transform, const std::string& where)
{
    const std::string at = source_ + ": " + where;
    if (index < 0 || index >= static_cast<int>(model_.textures.size()))
        throw Error(at + ": texture index " + std::to_string(index) + " does not exist (" +
                    std::to_string(model_.textures.size()) + " textures)");
    const tinygltf::Texture& texture = model_.textures[static_cast<std::size_t>(index)];
    const std::string tex_where = where + ": texture " + std::to_string(index);
    SceneTexture out;
    if (texture.source < 0)
        throw Error(source_ + ": " + tex_where + ": has no PNG or JPEG source image");
    out.image = image(texture.source, tex_where);
    if (texture.sampler >= static_cast<int>(model_.samplers.size()))
        throw Error(source_ + ": " + tex_where + ": sampler index " + std::to_string(texture.sampler) +
                    " does not exist (" + std::to_string(model_.samplers.size()) + " samplers)");
    if (texture.sampler >= 0) {
        const tinygltf::Sampler& s = model_.samplers[static_cast<std::size_t>(texture.sampler)];
        const std::string s_where = source_ + ": " + tex_where + ": sampler " + std::to_string(texture.sampler);
        out.wrap_s = wrap_mode(s.wrapS, s_where + " wrapS");
        out.wrap_t = wrap_mode(s.wrapT, s_where + " wrapT");
        if (s.magFilter != -1 && s.magFilter != kNearest && s.magFilter != kLinear)
            throw Error(s_where + ": unknown magFilter " + std::to_string(s.magFilter));
        out.nearest = s.magFilter == kNearest; // minFilter: no mipmaps, so it has no use
    }
    out.texcoord = texcoord;
    if (transform) {
        const std::string t_where = at + ": KHR_texture_transform";
        if (!transform->IsObject())
            throw Error(t_where + " must be an object");
        double ou, ov, su, sv;
        pair(*transform, "offset", 0.0, ou, ov, t_where);
        pair(*transform, "scale", 1.0, su, sv, t_where);
        double rotation = number(*transform, "rotation", 0.0, t_where);
        texture_transform_matrix(ou, ov, rotation, su, sv, out.transform_u, out.transform_v);
        double override_set = number(*transform, "texCoord", texcoord, t_where);
        if (override_set != std::floor(override_set))
            throw Error(t_where + ": \"texCoord\" must be an integer");
        out.texcoord = static_cast<int>(std::min(override_set, 1e6));
    }
    if (out.texcoord < 0 || out.texcoord > kMaxTexcoordSet)
        throw Error(at + ": texCoord " + std::to_string(out.texcoord) + " is out of range (0 to " +
                    std::to_string(kMaxTexcoordSet) + ")");
    return out;
}

SceneTexture TextureImporter::read(const tinygltf::Value& info, const std::string& where)
{
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsNumber())
        throw Error(source_ + ": " + where + ": a textureInfo needs a numeric \"index\"");
    double index = info.Get("index").GetNumberAsDouble();
    double texcoord = number(info, "texCoord", 0.0, source_ + ": " + where);
    if (index != std::floor(index) || texcoord != std::floor(texcoord))
        throw Error(source_ + ": " + where + ": \"index\" and \"texCoord\" must be integers");
    const tinygltf::Value* transform = nullptr;
    if (info.Has("extensions") && info.Get("extensions").Has("KHR_texture_transform"))
        transform = &info.Get("extensions").Get("KHR_texture_transform");
    return read(static_cast<int>(std::clamp(index, -1.0, 1e9)), static_cast<int>(std::clamp(texcoord, -1.0, 1e6)),
                transform, where);
}

int TextureImporter::image(int gltf_image, const std::string& where)
{
    if (gltf_image >= static_cast<int>(model_.images.size()))
        throw Error(source_ + ": " + where + ": image index " + std::to_string(gltf_image) + " does not exist (" +
                    std::to_string(model_.images.size()) + " images)");
    int& cached = scene_image_[static_cast<std::size_t>(gltf_image)];
    if (cached >= 0)
        return cached;
    const tinygltf::Image& im = model_.images[static_cast<std::size_t>(gltf_image)];
    std::string what = "image " + std::to_string(gltf_image);
    if (!im.uri.empty())
        what += " " + quote(im.uri);
    else if (!im.name.empty())
        what += " (" + im.name + ")";
    SceneImage decoded;
    // The decoder's copy and the RGBA image are held together while it decodes: both
    // count against the images' budget and against the memory the process may take.
    auto admit = [&](std::size_t peak) {
        if (peak > kMaxTotalImageBytes - image_bytes_)
            throw Error(what + ": decoding it takes " + gib(static_cast<double>(peak)) + " more than the " +
                        std::to_string(kMaxTotalImageBytes >> 20) + " MiB the decoded images may have in all (" +
                        std::to_string(image_bytes_ >> 20) + " MiB taken)");
        check_memory_for(static_cast<double>(peak), what + ": decoding it");
    };
    try {
        if (im.bufferView >= 0) {
            // tinygltf hands bufferView bytes over without checking the view's bounds.
            if (im.bufferView >= static_cast<int>(model_.bufferViews.size()))
                throw Error(what + ": bufferView " + std::to_string(im.bufferView) + " does not exist");
            const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(im.bufferView)];
            if (view.buffer < 0 || view.buffer >= static_cast<int>(model_.buffers.size()))
                throw Error(what + ": its bufferView has no valid buffer");
            const std::vector<unsigned char>& data = model_.buffers[static_cast<std::size_t>(view.buffer)].data;
            if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
                throw Error(what + ": its bufferView lies outside its buffer");
            decoded = decode_image(data.data() + view.byteOffset, view.byteLength, what, admit);
        } else {
            if (!im.uri.empty())
                check_image_uri(im.uri, what);
            if (im.image.empty()) {
                for (const std::string& r : refusals_ ? *refusals_ : std::vector<std::string>{})
                    if (r.rfind(im.uri + ":", 0) == 0)
                        throw Error(what + r.substr(im.uri.size()));
                std::string file = (std::filesystem::path(base_dir_.empty() ? "." : base_dir_) / im.uri).string();
                throw Error(what + (im.uri.empty() ? ": has no image data" : ": cannot read the file " + quote(file)));
            }
            // bits 0: the encoded bytes keep_encoded_image kept; else pixels a program set.
            decoded = im.bits == 0 ? decode_image(im.image.data(), im.image.size(), what, admit)
                                   : image_from_pixels(im, what, admit);
        }
        std::size_t bytes = decoded.rgba8.size() + 2 * decoded.rgba16.size();
        if (bytes > kMaxTotalImageBytes - image_bytes_)
            throw Error(what + ": the decoded images would exceed the limit of " +
                        std::to_string(kMaxTotalImageBytes >> 20) + " MiB");
        image_bytes_ += bytes;
    } catch (const Error& e) {
        throw Error(source_ + ": " + where + ": " + e.what());
    }
    cached = static_cast<int>(images_.size());
    images_.push_back(std::move(decoded));
    return cached;
}

} // namespace pathcl
