// glTF images on the host (no device), decoded by OpenImageIO: PNG 8 and 16-bit, grey and
// grey-alpha, alpha kept unassociated, JPEG, and images found through the file: URIs
// relative to the glTF file, data: URIs and .glb buffer views. Next to each test: a broken
// variant seen to fail it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "scene/gltf_images.h"
#include "support/gltf_texture_fixtures.h"

namespace pathcl::test_gltf_images {
namespace {

namespace fs = std::filesystem;
using test::kPngGrey8;
using test::kPngGreyAlpha8;
using test::kPngRgba16;
using test::kPngRgba8;
using test::Quad;
using test::quad;
using test::quad_with_image;
using test::TempDir;
using test::write_and_load;
using test::write_bytes;

// ---------------------------------------------------------------------------------------
// Image decoding

SceneImage decoded(const std::vector<unsigned char>& png)
{
    return decode_image(png.data(), png.size(), "test");
}

TEST(GltfImages, PngAlphaStaysUnassociated)
{
    // Broken variant seen to fail: opening without oiio:UnassociatedAlpha (OpenImageIO
    // premultiplies: (200, 100, 50) at alpha 128 comes back as (100, 50, 25)).
    SceneImage img = decoded(kPngRgba8);
    ASSERT_EQ(img.bits, 8);
    ASSERT_EQ(img.width, 2u);
    EXPECT_EQ(img.rgba8, (std::vector<std::uint8_t>{200, 100, 50, 128, 10, 20, 30, 0}));
}

TEST(GltfImages, SixteenBitPngKeepsSixteenBits)
{
    // Broken variant seen to fail: no oiio:UnassociatedAlpha (its alpha 300 premultiplies).
    SceneImage img = decoded(kPngRgba16);
    ASSERT_EQ(img.bits, 16);
    EXPECT_EQ(img.rgba16, (std::vector<std::uint16_t>{1000, 20000, 40000, 65535, 65535, 1, 32768, 300}));
}

TEST(GltfImages, GreyImagesExpandToRgba)
{
    // Broken variant seen to fail: no oiio:UnassociatedAlpha (the grey-alpha texel).
    EXPECT_EQ(decoded(kPngGrey8).rgba8, (std::vector<std::uint8_t>{7, 7, 7, 255, 250, 250, 250, 255}));
    EXPECT_EQ(decoded(kPngGreyAlpha8).rgba8, (std::vector<std::uint8_t>{90, 90, 90, 33}));
}

TEST(GltfImages, JpegDecodes)
{
    // A flat 8 x 8 JPEG (lossy, so only near its colour). Broken variant seen to fail:
    // the format sniffed from the PNG signature only.
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput proxy(bytes);
    auto out = OIIO::ImageOutput::create("jpeg");
    OIIO::ImageSpec spec(8, 8, 3, OIIO::TypeDesc::UINT8);
    std::vector<std::uint8_t> pixels(8 * 8 * 3);
    for (std::size_t i = 0; i < pixels.size(); i += 3) {
        pixels[i] = 180;
        pixels[i + 1] = 90;
        pixels[i + 2] = 30;
    }
    ASSERT_TRUE(out && out->set_ioproxy(&proxy) && out->open("x.jpg", spec) &&
                out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && out->close());
    SceneImage img = decode_image(bytes.data(), bytes.size(), "jpeg");
    ASSERT_EQ(img.width, 8u);
    ASSERT_EQ(img.bits, 8);
    EXPECT_NEAR(img.rgba8[0], 180, 3);
    EXPECT_NEAR(img.rgba8[1], 90, 3);
    EXPECT_NEAR(img.rgba8[2], 30, 3);
    EXPECT_EQ(img.rgba8[3], 255);
}

// ---------------------------------------------------------------------------------------
// Images read through the file: URIs and .glb buffer views

TEST(GltfImages, FileUrisResolveAgainstTheGltfFilesDirectory)
{
    // The scene sits in a subdirectory and names "tex/a.png"; the working directory is
    // elsewhere. Also a data: URI. Broken variant seen to fail: the URI check rejecting
    // every path with a directory part.
    TempDir dir;
    fs::create_directories(dir.path() / "scene" / "tex");
    write_bytes(dir.path() / "scene" / "tex" / "a.png", kPngRgba8);
    tinygltf::Image file_image;
    file_image.uri = "tex/a.png";
    Scene s = write_and_load(quad_with_image(file_image).b, dir.path() / "scene" / "file.gltf");
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].rgba8[0], 200);

    tinygltf::Image data_image;
    const char* b64 = "data:image/png;base64,";
    std::string uri = b64;
    {
        static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        const std::vector<unsigned char>& in = kPngGrey8;
        for (std::size_t i = 0; i < in.size(); i += 3) {
            unsigned v = in[i] << 16 | (i + 1 < in.size() ? in[i + 1] << 8 : 0) | (i + 2 < in.size() ? in[i + 2] : 0);
            uri += t[v >> 18 & 63];
            uri += t[v >> 12 & 63];
            uri += i + 1 < in.size() ? t[v >> 6 & 63] : '=';
            uri += i + 2 < in.size() ? t[v & 63] : '=';
        }
    }
    data_image.uri = uri;
    Scene d = write_and_load(quad_with_image(data_image).b, dir.path() / "data.gltf");
    ASSERT_EQ(d.images.size(), 1u);
    EXPECT_EQ(d.images[0].rgba8[4], 250);
}

TEST(GltfImages, GlbBufferViewImages)
{
    // A .glb written by tinygltf, the PNG in a bufferView of its binary chunk. Broken
    // variant seen to fail: the view's byteOffset ignored.
    TempDir dir;
    Quad q = quad(false);
    q.mat().pbrMetallicRoughness.baseColorTexture.index = q.b.add_texture(q.b.add_image_bytes(kPngRgba16, "image/png"));
    Scene s = write_and_load(q.b, dir.path() / "scene.glb", true);
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].rgba16[1], 20000);
}

} // namespace
} // namespace pathcl::test_gltf_images
