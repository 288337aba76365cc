// Fixtures for the glTF texture tests: sampler constants, hand-made PNGs, a unit quad
// with two texture coordinate sets to hang textures on, and the round trip through a
// written .gltf or .glb file in a temporary directory (for URIs and buffer views).
#pragma once

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <ios>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "support/gltf_builder.h"

namespace pathcl::test {

// glTF sampler filters and wrap modes.
inline constexpr int kNearest = 9728, kLinear = 9729;
inline constexpr int kRepeat = 10497, kClamp = 33071, kMirror = 33648;

// Hand-made PNGs (Python zlib), so decoding is not checked against OpenImageIO's own writer.
// 2 x 1 RGBA8 (200, 100, 50, 128), (10, 20, 30, 0)
inline const std::vector<unsigned char> kPngRgba8 = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00,
    0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0xf4, 0x22, 0x7f, 0x8a, 0x00, 0x00, 0x00, 0x11, 0x49,
    0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x38, 0x91, 0x62, 0xd4, 0xc0, 0x25, 0x22, 0xc7, 0x00, 0x00, 0x0d, 0x51, 0x02,
    0x1b, 0xcf, 0xa8, 0xbc, 0x2b, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
// 2 x 1 RGBA16 (1000, 20000, 40000, 65535), (65535, 1, 32768, 300)
inline const std::vector<unsigned char> kPngRgba16 = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00,
    0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x10, 0x06, 0x00, 0x00, 0x00, 0xa4, 0xb2, 0xa3, 0xc9, 0x00,
    0x00, 0x00, 0x18, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x60, 0x7e, 0xe1, 0xa7, 0x30, 0xc7, 0xe1,
    0x3f, 0x10, 0x30, 0x30, 0x36, 0x30, 0x30, 0xea, 0x00, 0x00, 0x41, 0xde, 0x06, 0xe0, 0x39, 0xfc, 0xad,
    0x41, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
// 2 x 1 grey 8-bit: 7, 250
inline const std::vector<unsigned char> kPngGrey8 = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00,
    0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00, 0x00, 0xd1, 0x49, 0x20, 0x56, 0x00,
    0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x60, 0xff, 0x05, 0x00, 0x01, 0x0b, 0x01,
    0x02, 0x54, 0xf9, 0x8c, 0xc4, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
// 1 x 1 grey-alpha 8-bit: (90, 33)
inline const std::vector<unsigned char> kPngGreyAlpha8 = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00,
    0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x04, 0x00, 0x00, 0x00, 0xb5, 0x1c, 0x0c, 0x02, 0x00,
    0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x88, 0x52, 0x04, 0x00, 0x00, 0xd8, 0x00,
    0x7c, 0x70, 0x39, 0x52, 0x6d, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};

// A unit quad (two triangles) in the z = 0 plane facing +z, with normals, TEXCOORD_0 =
// (x, 1 - y) and TEXCOORD_1 = (y, x); one material (index `material`), one mesh.
struct Quad {
    GltfBuilder b;
    int material = 0, mesh = 0;
    tinygltf::Material& mat() { return b.material(material); }
    tinygltf::Primitive& prim() { return b.model.meshes[static_cast<std::size_t>(mesh)].primitives[0]; }
};

inline Quad quad(bool with_texcoord1 = true)
{
    Quad q;
    std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    int pos = q.b.add_positions(p);
    int nrm = q.b.add_normals({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    int idx = q.b.add_indices({0, 1, 2, 0, 2, 3}, kU16);
    q.material = q.b.add_material(glm::vec3(1.0f));
    q.mesh = q.b.add_mesh(pos, idx, q.material, 4, nrm);
    std::vector<glm::vec2> uv0, uv1;
    for (const glm::vec3& v : p) {
        uv0.push_back({v.x, 1.0f - v.y});
        uv1.push_back({v.y, v.x});
    }
    q.b.set_attribute(q.mesh, "TEXCOORD_0", q.b.add_texcoords(uv0));
    if (with_texcoord1)
        q.b.set_attribute(q.mesh, "TEXCOORD_1", q.b.add_texcoords(uv1));
    q.b.add_root(q.b.add_node(q.mesh));
    return q;
}

inline int white_texture(GltfBuilder& b, int sampler = -1)
{
    return b.add_texture(b.add_png_image(1, 1, {255, 255, 255, 255}), sampler);
}

// A directory removed at the end of the test.
class TempDir {
public:
    TempDir()
    {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        root_ =
            std::filesystem::temp_directory_path() / ("pathcl-tex-" + std::to_string(::getpid()) + "-" + info->name());
        std::filesystem::remove_all(root_);
        std::filesystem::create_directories(root_);
    }
    ~TempDir() { std::filesystem::remove_all(root_); }
    const std::filesystem::path& path() const { return root_; }

private:
    std::filesystem::path root_;
};

// Writes `b`'s model as a .gltf (buffers embedded as data: URIs; images keep their uri,
// nothing is written for them) and loads it with load_gltf.
inline Scene write_and_load(const GltfBuilder& b, const std::filesystem::path& file, bool binary = false)
{
    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(
        [](const std::string*, const std::string*, const tinygltf::Image*, bool, std::string*, void*) { return false; },
        nullptr);
    if (!writer.WriteGltfSceneToFile(&b.model, file.string(), false, true, false, binary))
        throw std::runtime_error("cannot write " + file.string());
    return load_gltf(file.string());
}

inline void write_bytes(const std::filesystem::path& p, const std::vector<unsigned char>& bytes)
{
    std::ofstream out(p, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// The quad with its base colour read from image `image` (set up by the caller).
inline Quad quad_with_image(const tinygltf::Image& image)
{
    Quad q = quad(false);
    q.b.model.images.push_back(image);
    q.mat().pbrMetallicRoughness.baseColorTexture.index =
        q.b.add_texture(static_cast<int>(q.b.model.images.size()) - 1);
    return q;
}

} // namespace pathcl::test
