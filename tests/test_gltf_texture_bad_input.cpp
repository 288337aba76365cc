// Bad glTF texture input on the host (no device): broken texture, image and sampler
// references, texCoord sets the mesh lacks, images that are not PNG or JPEG or do not
// decode, malformed transforms, colours and texture coordinates, and image URIs that are
// not read. Each is a one-line pathcl::Error naming the file and what is wrong. Next to
// each test: a broken variant seen to fail it.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "support/expect_error.h"
#include "support/gltf_texture_fixtures.h"

namespace pathcl::test_gltf_texture_bad_input {
namespace {

namespace fs = std::filesystem;
using test::contains;
using test::error_of;
using test::kLinear;
using test::kPngRgba8;
using test::kRepeat;
using test::kU8;
using test::Quad;
using test::quad;
using test::quad_with_image;
using test::TempDir;
using test::white_texture;
using test::write_and_load;
using test::write_bytes;

// ---------------------------------------------------------------------------------------
// Bad input: one line naming the file and what is wrong

struct BadCase {
    const char* name;
    std::function<void(Quad&)> breakit;
    const char* expected; // part of the message
};

void PrintTo(const BadCase& c, std::ostream* os)
{
    *os << c.name;
}

class GltfBrokenTextures : public ::testing::TestWithParam<BadCase> {};

// Broken variant seen to fail (TexcoordTheMeshLacks): the loader without its texCoord check.
TEST_P(GltfBrokenTextures, ThrowsOneLineNamingTheFile)
{
    Quad q = quad(false);
    q.mat().pbrMetallicRoughness.baseColorTexture.index = white_texture(q.b);
    ASSERT_NO_THROW(import_gltf(q.b.model, "broken.gltf")); // valid before breaking it
    GetParam().breakit(q);
    std::string msg = error_of([&] { import_gltf(q.b.model, "broken.gltf"); });
    EXPECT_EQ(msg.rfind("broken.gltf: ", 0), 0u) << msg;
    EXPECT_TRUE(contains(msg, GetParam().expected)) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

INSTANTIATE_TEST_SUITE_P(
    GltfBrokenData, GltfBrokenTextures,
    ::testing::Values(
        BadCase{"TextureIndexOutOfRange", [](Quad& q) { q.mat().pbrMetallicRoughness.baseColorTexture.index = 7; },
                "texture index 7 does not exist"},
        BadCase{"ImageIndexOutOfRange", [](Quad& q) { q.b.model.textures[0].source = 3; },
                "image index 3 does not exist"},
        BadCase{"TextureWithoutSource", [](Quad& q) { q.b.model.textures[0].source = -1; },
                "has no PNG or JPEG source"},
        BadCase{"SamplerIndexOutOfRange", [](Quad& q) { q.b.model.textures[0].sampler = 2; },
                "sampler index 2 does not exist"},
        BadCase{"UnknownWrapMode",
                [](Quad& q) { q.b.model.textures[0].sampler = q.b.add_sampler(kLinear, 12345, kRepeat); },
                "unknown wrap mode 12345"},
        BadCase{"TexcoordTheMeshLacks", [](Quad& q) { q.mat().pbrMetallicRoughness.baseColorTexture.texCoord = 1; },
                "baseColorTexture reads TEXCOORD_1, which the primitive does not have"},
        BadCase{"TexcoordOutOfRange", [](Quad& q) { q.mat().pbrMetallicRoughness.baseColorTexture.texCoord = 100000; },
                "texCoord 100000 is out of range"},
        BadCase{"NotPngOrJpeg",
                [](Quad& q) {
                    // A BMP header: a real image format, but not one glTF allows.
                    q.b.model.images[0].bufferView = q.b.add_view("BM\x3a\0\0\0\0\0\0\0\x36\0\0\0", 14);
                },
                "not a PNG or JPEG image"},
        BadCase{"CorruptPng",
                [](Quad& q) {
                    std::vector<unsigned char> bytes(kPngRgba8.begin(), kPngRgba8.begin() + 40);
                    q.b.model.images[0].bufferView = q.b.add_view(bytes.data(), bytes.size());
                },
                "cannot decode the png image"},
        BadCase{"ImageBufferViewOutsideBuffer",
                [](Quad& q) {
                    auto& view = q.b.model.bufferViews[static_cast<std::size_t>(q.b.model.images[0].bufferView)];
                    view.byteLength = 1 << 20;
                },
                "its bufferView lies outside its buffer"},
        BadCase{"MalformedTextureTransform",
                [](Quad& q) {
                    tinygltf::Value::Object transform;
                    transform["offset"] = tinygltf::Value(1.0);
                    q.mat().pbrMetallicRoughness.baseColorTexture.extensions["KHR_texture_transform"] =
                        tinygltf::Value(transform);
                },
                "\"offset\" must be an array of two finite numbers"},
        BadCase{"NonNormalizedIntegerTexcoords",
                [](Quad& q) {
                    const std::uint8_t uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
                    int acc = q.b.add_accessor(q.b.add_view(uv, 8), kU8, TINYGLTF_TYPE_VEC2, 4);
                    q.prim().attributes["TEXCOORD_0"] = acc;
                },
                "integer components must be normalized"},
        BadCase{"ColourOutsideUnitRange",
                [](Quad& q) {
                    q.prim().attributes["COLOR_0"] = q.b.add_positions({{0, 0, 0}, {2, 0, 0}, {0, 0, 0}, {0, 0, 0}});
                },
                "colour component outside [0, 1]"}),
    [](const ::testing::TestParamInfo<BadCase>& i) { return std::string(i.param.name); });

// Image URIs through load_gltf: missing file, absolute path, other schemes.
struct UriCase {
    const char* name;
    std::string uri;
    const char* expected;
};

void PrintTo(const UriCase& c, std::ostream* os)
{
    *os << c.name;
}

class GltfBadImageUri : public ::testing::TestWithParam<UriCase> {};

// Broken variant seen to fail (the three scheme cases): the URI-scheme check removed.
TEST_P(GltfBadImageUri, ThrowsOneLineNamingTheFile)
{
    TempDir dir;
    write_bytes(dir.path() / "a.png", kPngRgba8);
    tinygltf::Image image;
    image.uri = GetParam().uri == "ABSOLUTE" ? (dir.path() / "a.png").string() : GetParam().uri;
    fs::path file = dir.path() / "bad-uri.gltf";
    std::string msg = error_of([&] { write_and_load(quad_with_image(image).b, file); });
    EXPECT_EQ(msg.rfind(file.string() + ": ", 0), 0u) << msg;
    EXPECT_TRUE(contains(msg, GetParam().expected)) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

INSTANTIATE_TEST_SUITE_P(
    GltfBrokenData, GltfBadImageUri,
    ::testing::Values(UriCase{"MissingFile", "missing.png", "no such file in the scene's directory"},
                      UriCase{"AbsolutePath", "ABSOLUTE", "is absolute"},
                      UriCase{"HttpScheme", "http://example.com/a.png", "the URI scheme 'http:' is not read"},
                      UriCase{"FileScheme", "file:///tmp/a.png", "the URI scheme 'file:' is not read"},
                      UriCase{"UnsupportedDataUri", "data:image/webp;base64,AAAA", "a data: URI with a media type"}),
    [](const ::testing::TestParamInfo<UriCase>& i) { return std::string(i.param.name); });

} // namespace
} // namespace pathcl::test_gltf_texture_bad_input
