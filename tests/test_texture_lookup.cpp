// Texture lookups through the kernels' own code (tests/kernels/texture_test_kernels.cl over
// kernels/texture/), on texture arrays built by hand: exact texels at texel centres, exact
// bilinear midpoints, every wrap mode on both sides of [0, 1], nearest filtering, sRGB
// decoding of all 256 values, 16-bit texels and KHR_texture_transform.
// Next to each test: the deliberately broken variant of the kernel that was seen to fail it.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "compile/device_arrays.h"
#include "compile/texture_lookup.h"
#include "support/device_fixture.h"
#include "support/texture_kernels.h"

namespace pathcl::test_texture_lookup {
namespace {

using test::read_back;
using test::texel8;
using test::texture_program;
using test::upload;

// Texture arrays built by hand, as a compiled scene would hold them.
struct TextureSet {
    SceneArrays t;

    int add_image8(pcl_uint w, pcl_uint h, const std::vector<std::uint8_t>& rgba)
    {
        t.texture_images.push_back({static_cast<pcl_uint>(t.texels.size()), w, h, TEXTURE_FORMAT_RGBA8});
        for (std::size_t i = 0; i < rgba.size(); i += 4)
            t.texels.push_back(rgba[i] | rgba[i + 1] << 8 | rgba[i + 2] << 16 |
                               static_cast<pcl_uint>(rgba[i + 3]) << 24);
        return static_cast<int>(t.texture_images.size()) - 1;
    }
    int add_image16(pcl_uint w, pcl_uint h, const std::vector<std::uint16_t>& rgba)
    {
        t.texture_images.push_back({static_cast<pcl_uint>(t.texels.size()), w, h, TEXTURE_FORMAT_RGBA16});
        for (std::size_t i = 0; i < rgba.size(); i += 4) {
            t.texels.push_back(rgba[i] | static_cast<pcl_uint>(rgba[i + 1]) << 16);
            t.texels.push_back(rgba[i + 2] | static_cast<pcl_uint>(rgba[i + 3]) << 16);
        }
        return static_cast<int>(t.texture_images.size()) - 1;
    }
    int add_view(int image, pcl_uint wrap_s, pcl_uint wrap_t, pcl_uint flags, pcl_float4 row_u = {1, 0, 0, 0},
                 pcl_float4 row_v = {0, 1, 0, 0})
    {
        TextureView v{};
        v.transform_u = row_u;
        v.transform_v = row_v;
        v.image = image;
        v.wrap_s = wrap_s;
        v.wrap_t = wrap_t;
        v.flags = flags;
        t.texture_views.push_back(v);
        return static_cast<int>(t.texture_views.size()) - 1;
    }
};

// texture_sample(view, uv) on the device for each (u, v, view).
std::vector<pcl_float4> lookups(const TextureSet& set, const std::vector<std::pair<glm::vec2, int>>& queries)
{
    std::vector<pcl_float4> q;
    for (const auto& [uv, view] : queries) {
        float view_bits;
        std::memcpy(&view_bits, &view, 4);
        q.push_back({uv.x, uv.y, view_bits, 0.0f});
    }
    cl::Kernel k(texture_program(), "test_texture_sample");
    DeviceArrays arrays = upload_arrays(test::test_device(), set.t, 1);
    cl::Buffer qb = upload(q);
    cl::Buffer out(test::test_device().context, CL_MEM_WRITE_ONLY, q.size() * sizeof(pcl_float4));
    bind_kernel(k, arrays, qb, out);
    test::test_device().queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(q.size()));
    return read_back(out, q.size());
}

glm::vec4 v4(const pcl_float4& p)
{
    return {p.x, p.y, p.z, p.w};
}

float fl(int i)
{
    return static_cast<float>(i);
}

std::string str(const glm::vec4& v)
{
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ", " +
           std::to_string(v.w) + ")";
}

// 4 x 2 RGBA8 texels, all channels distinct.
std::vector<std::uint8_t> four_by_two()
{
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < 8; ++i)
        for (int c = 0; c < 4; ++c)
            rgba.push_back(static_cast<std::uint8_t>(17 + 29 * i + 7 * c));
    return rgba;
}

TEST(TextureLookup, TexelCentresReturnTheTexelExactly)
{
    // Broken variant seen to fail: texel centres at i / W instead of (i + 0.5) / W (the
    // lookup blends two texels).
    TextureSet set;
    auto rgba = four_by_two();
    int img = set.add_image8(4, 2, rgba);
    int linear = set.add_view(img, TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_REPEAT, 0);
    int srgb = set.add_view(img, TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_REPEAT, TEXTURE_SRGB);
    std::vector<std::pair<glm::vec2, int>> q;
    for (int view : {linear, srgb})
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 4; ++i)
                q.push_back({{(fl(i) + 0.5f) / 4.0f, (fl(j) + 0.5f) / 2.0f}, view});
    auto out = lookups(set, q);
    for (std::size_t n = 0; n < q.size(); ++n) {
        std::size_t texel = n % 8;
        glm::vec4 expected = texel8(&rgba[texel * 4], q[n].second == srgb);
        EXPECT_EQ(v4(out[n]), expected) << "texel " << texel << " view " << q[n].second << ": " << str(v4(out[n]));
    }
}

TEST(TextureLookup, BilinearMidpointsAreExact)
{
    // Between two texel centres the weights are exactly 1/2; between four, 1/4 each.
    // Broken variant seen to fail: the u and v fractions exchanged (invisible at texel
    // centres, where both are 0).
    TextureSet set;
    auto rgba = four_by_two();
    int img = set.add_image8(4, 2, rgba);
    int view = set.add_view(img, TEXTURE_WRAP_CLAMP_TO_EDGE, TEXTURE_WRAP_CLAMP_TO_EDGE, TEXTURE_SRGB);
    auto t = [&](int i, int j) { return texel8(&rgba[static_cast<std::size_t>(j * 4 + i) * 4], true); };
    auto lerp = [](glm::vec4 a, glm::vec4 b) { return a + 0.5f * (b - a); }; // the kernel's order
    std::vector<std::pair<glm::vec2, int>> q;
    std::vector<glm::vec4> expected;
    for (int i = 0; i < 3; ++i) {
        q.push_back({{fl(i + 1) / 4.0f, 0.25f}, view}); // between (i, 0) and (i + 1, 0)
        expected.push_back(lerp(t(i, 0), t(i + 1, 0)));
        q.push_back({{fl(i + 1) / 4.0f, 0.5f}, view}); // between four texels
        expected.push_back(lerp(lerp(t(i, 0), t(i + 1, 0)), lerp(t(i, 1), t(i + 1, 1))));
    }
    auto out = lookups(set, q);
    for (std::size_t n = 0; n < q.size(); ++n)
        EXPECT_EQ(v4(out[n]), expected[n]) << "query " << n << ": " << str(v4(out[n])) << " vs " << str(expected[n]);
}

TEST(TextureLookup, WrapModesOnBothSidesOfTheUnitSquare)
{
    // Texel i of a 4 x 1 image (nearest) at u = (i + 0.5) / 4 for i = -5 .. 8, each mode;
    // the v axis (a 1 x 4 image) with a different mode than u. Broken variant seen to
    // fail: mirrored repeat with period W instead of 2W.
    TextureSet set;
    const std::vector<std::uint8_t> row = {10, 0, 0, 255, 20, 0, 0, 255, 30, 0, 0, 255, 40, 0, 0, 255};
    int wide = set.add_image8(4, 1, row), tall = set.add_image8(1, 4, row);
    const pcl_uint modes[3] = {TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_CLAMP_TO_EDGE, TEXTURE_WRAP_MIRRORED_REPEAT};
    auto expected_texel = [](int i, pcl_uint mode) {
        if (mode == TEXTURE_WRAP_REPEAT)
            return ((i % 4) + 4) % 4;
        if (mode == TEXTURE_WRAP_CLAMP_TO_EDGE)
            return std::clamp(i, 0, 3);
        int r = ((i % 8) + 8) % 8; // mirrored: 0 1 2 3 3 2 1 0, period 8
        return r < 4 ? r : 7 - r;
    };
    std::vector<std::pair<glm::vec2, int>> q;
    std::vector<int> expected;
    for (pcl_uint m : modes) {
        // u wraps by m (v clamps), then v wraps by m (u clamps, on the 1 x 4 image).
        int view_u = set.add_view(wide, m, TEXTURE_WRAP_CLAMP_TO_EDGE, TEXTURE_NEAREST);
        int view_v = set.add_view(tall, TEXTURE_WRAP_CLAMP_TO_EDGE, m, TEXTURE_NEAREST);
        for (int i = -5; i <= 8; ++i) {
            float c = (fl(i) + 0.5f) / 4.0f;
            q.push_back({{c, 0.5f}, view_u});
            q.push_back({{0.5f, c}, view_v});
            expected.push_back(expected_texel(i, m));
            expected.push_back(expected_texel(i, m));
        }
    }
    auto out = lookups(set, q);
    for (std::size_t n = 0; n < q.size(); ++n)
        EXPECT_EQ(out[n].x, static_cast<float>(10 * (expected[n] + 1)) * (1.0f / 255.0f))
            << "query " << n << " at (" << q[n].first.x << ", " << q[n].first.y << ") view " << q[n].second;
}

TEST(TextureLookup, BilinearBlendsAcrossTheWrapSeam)
{
    // At u = 0 (between texel -1 and texel 0): repeat blends the last and first texels,
    // clamp and mirrored repeat return the first (and at u = 1, the last). Broken variants
    // seen to fail: the right neighbour's index not wrapped (clamp reads texel 4 of a
    // 4-wide image); repeat with C's % left negative for texel -1 (reads before the
    // image: the test binary crashed).
    TextureSet set;
    std::vector<std::uint8_t> row = {0, 0, 0, 255, 40, 0, 0, 255, 80, 0, 0, 255, 200, 0, 0, 255};
    int img = set.add_image8(4, 1, row);
    int repeat = set.add_view(img, TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_REPEAT, 0);
    int clamp = set.add_view(img, TEXTURE_WRAP_CLAMP_TO_EDGE, TEXTURE_WRAP_REPEAT, 0);
    int mirror = set.add_view(img, TEXTURE_WRAP_MIRRORED_REPEAT, TEXTURE_WRAP_REPEAT, 0);
    auto out = lookups(set, {{{0.0f, 0.5f}, repeat},
                             {{0.0f, 0.5f}, clamp},
                             {{0.0f, 0.5f}, mirror},
                             {{1.0f, 0.5f}, repeat},
                             {{1.0f, 0.5f}, clamp},
                             {{1.0f, 0.5f}, mirror}});
    float first = 0.0f, last = 200.0f * (1.0f / 255.0f);
    EXPECT_EQ(out[0].x, last + 0.5f * (first - last));
    EXPECT_EQ(out[1].x, first);
    EXPECT_EQ(out[2].x, first);
    EXPECT_EQ(out[3].x, last + 0.5f * (first - last));
    EXPECT_EQ(out[4].x, last);
    EXPECT_EQ(out[5].x, last);
}

TEST(TextureLookup, NearestReturnsTheTexelContainingTheCoordinate)
{
    // Broken variant seen to fail: ignoring TEXTURE_NEAREST (bilinear everywhere).
    TextureSet set;
    auto rgba = four_by_two();
    int img = set.add_image8(4, 2, rgba);
    int view = set.add_view(img, TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_REPEAT, TEXTURE_NEAREST);
    std::vector<std::pair<glm::vec2, int>> q;
    std::vector<int> texel;
    for (float u : {0.01f, 0.26f, 0.3f, 0.49f, 0.74f, 0.99f})
        for (float v : {0.1f, 0.45f, 0.55f, 0.9f}) {
            q.push_back({{u, v}, view});
            texel.push_back(static_cast<int>(v * 2.0f) * 4 + static_cast<int>(u * 4.0f));
        }
    auto out = lookups(set, q);
    for (std::size_t n = 0; n < q.size(); ++n)
        EXPECT_EQ(v4(out[n]), texel8(&rgba[static_cast<std::size_t>(texel[n]) * 4], false)) << "query " << n;
}

TEST(TextureLookup, SrgbDecodingIsExactForAll256Values)
{
    // Every 8-bit value through an sRGB view equals the IEC 61966-2-1 formula evaluated in
    // double and rounded to float; alpha stays linear. Broken variants seen to fail: the
    // gamma-2.2 approximation; a table entry off by one index.
    TextureSet set;
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < 256; ++i)
        rgba.insert(rgba.end(), {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(255 - i),
                                 static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i)});
    int img = set.add_image8(256, 1, rgba);
    int view = set.add_view(img, TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_REPEAT, TEXTURE_SRGB | TEXTURE_NEAREST);
    std::vector<std::pair<glm::vec2, int>> q;
    for (int i = 0; i < 256; ++i)
        q.push_back({{(fl(i) + 0.5f) / 256.0f, 0.5f}, view});
    auto out = lookups(set, q);
    for (int i = 0; i < 256; ++i) {
        auto u = static_cast<std::uint8_t>(i);
        double c = i / 255.0;
        float exact = static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        ASSERT_EQ(srgb8_to_linear(u), exact);
        EXPECT_EQ(out[static_cast<std::size_t>(i)].x, exact) << "value " << i;
        EXPECT_EQ(out[static_cast<std::size_t>(i)].y, srgb8_to_linear(static_cast<std::uint8_t>(255 - i))) << i;
        EXPECT_EQ(out[static_cast<std::size_t>(i)].w, static_cast<float>(i) * (1.0f / 255.0f)) << "alpha " << i;
    }
}

TEST(TextureLookup, SixteenBitTexels)
{
    // RGBA16 texels (two words each): linear values v / 65535 exactly, sRGB within a few
    // float ulps of the formula (the kernel uses pow). Broken variant seen to fail: the
    // second word's halves swapped (B and A exchanged).
    TextureSet set;
    std::vector<std::uint16_t> rgba = {0, 1, 32768, 65535, 1000, 20000, 40000, 60000};
    int img = set.add_image16(2, 1, rgba);
    int linear = set.add_view(img, TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_REPEAT, TEXTURE_NEAREST);
    int srgb = set.add_view(img, TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_REPEAT, TEXTURE_NEAREST | TEXTURE_SRGB);
    auto out =
        lookups(set, {{{0.25f, 0.5f}, linear}, {{0.75f, 0.5f}, linear}, {{0.25f, 0.5f}, srgb}, {{0.75f, 0.5f}, srgb}});
    for (int t = 0; t < 2; ++t)
        for (int c = 0; c < 4; ++c) {
            std::uint16_t v = rgba[static_cast<std::size_t>(t * 4 + c)];
            float lin = static_cast<float>(v) * (1.0f / 65535.0f);
            EXPECT_EQ(v4(out[static_cast<std::size_t>(t)])[c], lin) << "texel " << t << " channel " << c;
            double x = v / 65535.0;
            double s = c == 3 ? x : (x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4));
            EXPECT_NEAR(v4(out[static_cast<std::size_t>(2 + t)])[c], s, 4e-7 * s + 1e-9)
                << "sRGB texel " << t << " channel " << c;
        }
}

TEST(TextureLookup, TextureTransformIsAppliedBeforeWrapping)
{
    // The KHR_texture_transform example (offset (0, 1), rotation pi/2, scale 1/2) as the
    // loader turns it into rows: (u, v) -> (v / 2, 1 - u / 2), the lower-left quadrant of
    // the image turned. Texel values identify where each lookup landed. Broken variant
    // seen to fail: the rows applied as columns (transposed matrix).
    TextureSet set;
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < 16; ++i)
        rgba.insert(rgba.end(), {static_cast<std::uint8_t>(i * 10), 0, 0, 255});
    int img = set.add_image8(4, 4, rgba);
    int view = set.add_view(img, TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_REPEAT, TEXTURE_NEAREST, {0.0f, 0.5f, 0.0f, 0.0f},
                            {-0.5f, 0.0f, 1.0f, 0.0f});
    std::vector<std::pair<glm::vec2, int>> q;
    std::vector<int> expected;
    for (float u : {0.1f, 0.35f, 0.6f, 0.9f})
        for (float v : {0.1f, 0.35f, 0.6f, 0.9f}) {
            q.push_back({{u, v}, view});
            float tu = 0.5f * v, tv = 1.0f - 0.5f * u;
            expected.push_back(static_cast<int>(tv * 4.0f) * 4 + static_cast<int>(tu * 4.0f));
        }
    auto out = lookups(set, q);
    for (std::size_t n = 0; n < q.size(); ++n)
        EXPECT_EQ(out[n].x, static_cast<float>(expected[n] * 10) * (1.0f / 255.0f))
            << "uv (" << q[n].first.x << ", " << q[n].first.y << ")";
}

} // namespace
} // namespace pathcl::test_texture_lookup
