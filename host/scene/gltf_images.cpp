#include "scene/gltf_images.h"

#include <cctype>
#include <cstring>
#include <filesystem>
#include <memory>

#include <tiny_gltf.h>

#include "common/error.h"
#include "image/image_io.h"
#include "image/image_module.h"

namespace pathcl {
namespace {

// Largest image accepted: 2^27 texels (16384 x 8192; 512 MiB as RGBA8), beyond any glTF
// texture; checked from the header, before anything is decoded.
constexpr std::size_t kMaxTexels = std::size_t(1) << 27;

// The format plugin for the bytes' signature: glTF 2.0 images are PNG or JPEG.
const char* image_format(const unsigned char* b, std::size_t size)
{
    const char* format = image_format_of(b, size);
    return format && (std::strcmp(format, "png") == 0 || std::strcmp(format, "jpeg") == 0) ? format : nullptr;
}

void check_size(std::size_t width, std::size_t height, const std::string& what)
{
    if (width == 0 || height == 0 || width > kMaxTexels / height)
        throw Error(what + ": unsupported image size " + std::to_string(width) + "x" + std::to_string(height));
}

// Expands `channels` interleaved values per texel to RGBA: grey to (g, g, g), grey-alpha
// to (g, g, g, a), missing alpha to opaque (`one`).
template <typename T>
std::vector<T> expand_to_rgba(const T* src, std::size_t texels, int channels, T one)
{
    std::vector<T> rgba(texels * 4);
    for (std::size_t i = 0; i < texels; ++i) {
        const T* s = src + i * static_cast<std::size_t>(channels);
        T* d = &rgba[i * 4];
        if (channels <= 2) {
            d[0] = d[1] = d[2] = s[0];
            d[3] = channels == 2 ? s[1] : one;
        } else {
            d[0] = s[0];
            d[1] = s[1];
            d[2] = s[2];
            d[3] = channels == 4 ? s[3] : one;
        }
    }
    return rgba;
}

} // namespace

SceneImage decode_image(const unsigned char* bytes, std::size_t size, const std::string& what,
                        const AdmitImageBytes& admit)
{
    const char* format = image_format(bytes, size);
    if (!format)
        throw Error(what + ": not a PNG or JPEG image (the formats glTF 2.0 allows)");
    SceneImage img;
    img.name = what;
    DecodedShape shape;
    std::vector<std::uint8_t> raw8;
    std::vector<std::uint16_t> raw16;
    const std::string why = image_module().decode(
        bytes, size, format,
        [&](const DecodedShape& s) {
            if (s.channels < 1 || s.channels > 4)
                throw Error(what + ": has " + std::to_string(s.channels) + " channels (1 to 4 are supported)");
            const std::size_t w = static_cast<std::size_t>(std::max(s.width, 0));
            const std::size_t h = static_cast<std::size_t>(std::max(s.height, 0));
            check_size(w, h, what);
            if (admit)
                admit((w * h * static_cast<std::size_t>(s.channels) + w * h * 4) *
                      static_cast<std::size_t>(s.bits / 8));
        },
        shape, raw8, raw16);
    if (!why.empty())
        throw Error(what + ": " + one_line(why));
    img.width = static_cast<std::uint32_t>(shape.width);
    img.height = static_cast<std::uint32_t>(shape.height);
    img.bits = shape.bits;
    const std::size_t texels = static_cast<std::size_t>(img.width) * img.height;
    if (img.bits == 16)
        img.rgba16 = expand_to_rgba<std::uint16_t>(raw16.data(), texels, shape.channels, 65535);
    else
        img.rgba8 = expand_to_rgba<std::uint8_t>(raw8.data(), texels, shape.channels, 255);
    return img;
}

SceneImage image_from_pixels(const tinygltf::Image& image, const std::string& what, const AdmitImageBytes& admit)
{
    int channels = image.component;
    if (channels < 1 || channels > 4 || (image.bits != 8 && image.bits != 16))
        throw Error(what + ": decoded pixels must have 1 to 4 channels of 8 or 16 bits");
    std::size_t w = static_cast<std::size_t>(std::max(image.width, 0));
    std::size_t h = static_cast<std::size_t>(std::max(image.height, 0));
    check_size(w, h, what);
    std::size_t values = w * h * static_cast<std::size_t>(channels);
    if (image.image.size() != values * static_cast<std::size_t>(image.bits / 8))
        throw Error(what + ": holds " + std::to_string(image.image.size()) + " bytes of pixels, not " +
                    std::to_string(values * static_cast<std::size_t>(image.bits / 8)));
    if (admit)
        admit((values + w * h * 4) * static_cast<std::size_t>(image.bits / 8));
    SceneImage img;
    img.name = what;
    img.width = static_cast<std::uint32_t>(w);
    img.height = static_cast<std::uint32_t>(h);
    img.bits = image.bits;
    if (image.bits == 16) {
        std::vector<std::uint16_t> raw(values);
        std::memcpy(raw.data(), image.image.data(), values * 2);
        img.rgba16 = expand_to_rgba<std::uint16_t>(raw.data(), w * h, channels, 65535);
    } else {
        img.rgba8 = expand_to_rgba<std::uint8_t>(image.image.data(), w * h, channels, 255);
    }
    return img;
}

void check_image_uri(const std::string& uri, const std::string& what)
{
    // A URI scheme is a letter followed by letters, digits, '+', '-' or '.', then ':'.
    std::size_t colon = uri.find(':');
    bool has_scheme = colon != std::string::npos && colon > 0 && std::isalpha(static_cast<unsigned char>(uri[0]));
    for (std::size_t i = 0; has_scheme && i < colon; ++i) {
        unsigned char c = static_cast<unsigned char>(uri[i]);
        has_scheme = std::isalnum(c) || c == '+' || c == '-' || c == '.';
    }
    if (has_scheme) {
        std::string scheme = uri.substr(0, colon);
        if (scheme == "data")
            throw Error(what + ": a data: URI with a media type other than image/png or image/jpeg");
        throw Error(what + ": the URI scheme '" + scheme + ":' is not read (only relative paths and data: URIs)");
    }
    if (!uri.empty() && (uri[0] == '/' || uri[0] == '\\' || std::filesystem::path(uri).is_absolute()))
        throw Error(what + ": the image path " + quote(uri) +
                    " is absolute (image URIs are relative to the glTF file)");
}

bool keep_encoded_image(tinygltf::Image* image, int index, std::string* err, std::string*, int, int,
                        const unsigned char* bytes, int size, void*)
{
    if (image->bufferView >= 0)
        return true; // decoded by the importer, which checks the view against its buffer first
    // The glTF library sets the media type of a data: URI (it accepts image/gif and
    // image/bmp too); glTF allows PNG and JPEG.
    if (!image->mimeType.empty() && image->mimeType != "image/png" && image->mimeType != "image/jpeg") {
        if (err != nullptr)
            *err += "image " + std::to_string(index) + ": a data: URI of type " + image->mimeType +
                    " (glTF images are image/png or image/jpeg)";
        return false;
    }
    image->image.assign(bytes, bytes + std::max(size, 0));
    image->bits = 0; // encoded bytes, not pixels
    image->component = 0;
    return true;
}

} // namespace pathcl
