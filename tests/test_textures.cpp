// Texture lookups, material inputs and textured emitters through the kernels' own code
// (tests/kernels/texture_test_kernels.cl over kernels/texture/): exact texels at texel
// centres, exact bilinear midpoints, every wrap mode on both sides of [0, 1], nearest
// filtering, sRGB decoding of all 256 values, 16-bit texels, KHR_texture_transform, the
// textured material at a hit (factors x texels x vertex colour), normal mapping with
// file and computed tangents, normals bent back above the surface, and light samples on a
// textured emitter carrying the texel at their point.
// Next to each test: the deliberately broken variant of the kernel that was seen to fail it.
#include <cmath>
#include <cstring>
#include <numbers>

#include <gtest/gtest.h>

#include "render/texture_lookup.h"
#include "support/compiled_scene.h"
#include "scene/gltf_loader.h"
#include "support/device_fixture.h"
#include "support/gltf_builder.h"

namespace pathcl {
namespace {

constexpr int kNearest = 9728, kLinear = 9729;
constexpr int kRepeat = 10497, kClamp = 33071, kMirror = 33648;

constexpr std::uint32_t kTextureFeatures = FEATURE_TEXTURES | FEATURE_NORMAL_MAPS | FEATURE_VERTEX_COLORS;

const cl::Program& texture_program()
{
    static cl::Program p = test::build_test_program("texture_test_kernels.cl", kTextureFeatures);
    return p;
}

using test::upload;

std::vector<pcl_float4> read_back(const cl::Buffer& b, std::size_t n)
{
    return test::read_back<pcl_float4>(b, n);
}

// Texture arrays built by hand, as a compiled scene would hold them.
struct TextureSet {
    SceneArrays t;

    int add_image8(pcl_uint w, pcl_uint h, const std::vector<std::uint8_t>& rgba)
    {
        t.texture_images.push_back({static_cast<pcl_uint>(t.texels.size()), w, h, TEXTURE_FORMAT_RGBA8});
        for (std::size_t i = 0; i < rgba.size(); i += 4)
            t.texels.push_back(rgba[i] | rgba[i + 1] << 8 | rgba[i + 2] << 16 | static_cast<pcl_uint>(rgba[i + 3]) << 24);
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

// The value kernels/textures.cl gives an 8-bit channel: linear byte * (1 / 255), or the sRGB table.
glm::vec4 texel8(const std::uint8_t* c, bool srgb)
{
    glm::vec4 v;
    for (int i = 0; i < 4; ++i)
        v[i] = (srgb && i < 3) ? srgb8_to_linear(c[i]) : static_cast<float>(c[i]) * (1.0f / 255.0f);
    return v;
}

glm::vec4 v4(const pcl_float4& p) { return {p.x, p.y, p.z, p.w}; }

float fl(int i) { return static_cast<float>(i); }

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
    auto out = lookups(set, {{{0.0f, 0.5f}, repeat}, {{0.0f, 0.5f}, clamp}, {{0.0f, 0.5f}, mirror},
                             {{1.0f, 0.5f}, repeat}, {{1.0f, 0.5f}, clamp}, {{1.0f, 0.5f}, mirror}});
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
    auto out = lookups(set, {{{0.25f, 0.5f}, linear}, {{0.75f, 0.5f}, linear}, {{0.25f, 0.5f}, srgb},
                             {{0.75f, 0.5f}, srgb}});
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

// ---------------------------------------------------------------------------------------
// Material inputs at a hit, through the loader and the device scene

struct QuadOptions {
    bool mirrored_uv = false;     // u runs along -x instead of +x
    bool file_tangents = false;   // TANGENT attribute instead of computed tangents
    bool double_sided = false;
    std::vector<std::uint8_t> normal_texel = {128, 128, 255, 255};
    double normal_scale = 1.0;
};

// A unit quad in the z = 0 plane facing +z with smooth normals (+z), texture coordinates
// u = x (or 1 - x), v = 1 - y (the image upright), a constant 1 x 1 texture in every
// core slot, and COLOR_0 (0.5, 1, 1) at every vertex.
Scene textured_quad(const QuadOptions& o)
{
    test::GltfBuilder b;
    std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    int pos = b.add_positions(p);
    int nrm = b.add_normals({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    int idx = b.add_indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    test::GltfBuilder::Pbr pbr;
    pbr.base_color = glm::vec3(0.8f, 0.6f, 0.4f);
    pbr.metallic = 0.5;
    pbr.roughness = 0.8;
    pbr.double_sided = o.double_sided;
    int mat = b.add_pbr_material(pbr);
    int mesh = b.add_mesh(pos, idx, mat, 4, nrm);
    std::vector<glm::vec2> uv;
    for (const glm::vec3& v : p)
        uv.push_back({o.mirrored_uv ? 1.0f - v.x : v.x, 1.0f - v.y});
    b.set_attribute(mesh, "TEXCOORD_0", b.add_texcoords(uv));
    if (o.file_tangents) {
        glm::vec4 t = o.mirrored_uv ? glm::vec4(-1, 0, 0, -1) : glm::vec4(1, 0, 0, 1);
        b.set_attribute(mesh, "TANGENT", b.add_tangents({t, t, t, t}));
    }
    std::vector<glm::vec3> colors(4, glm::vec3(0.5f, 1.0f, 1.0f));
    b.set_attribute(mesh, "COLOR_0", b.add_positions(colors));
    tinygltf::Material& m = b.model.materials.back();
    m.pbrMetallicRoughness.baseColorTexture.index = b.add_texture(b.add_png_image(1, 1, {188, 128, 64, 255}));
    m.pbrMetallicRoughness.metallicRoughnessTexture.index = b.add_texture(b.add_png_image(1, 1, {0, 102, 204, 255}));
    m.emissiveFactor = {2.0, 2.0, 2.0};
    m.emissiveTexture.index = b.add_texture(b.add_png_image(1, 1, {255, 128, 0, 255}));
    m.normalTexture.index = b.add_texture(b.add_png_image(1, 1, o.normal_texel));
    m.normalTexture.scale = o.normal_scale;
    // KHR_materials_specular and _transmission textures (factors 0.8, (1, 0.5, 1), 0.6).
    auto info = [](int index) {
        tinygltf::Value::Object obj;
        obj["index"] = tinygltf::Value(index);
        return tinygltf::Value(obj);
    };
    tinygltf::Value::Object spec, trans;
    spec["specularFactor"] = tinygltf::Value(0.8);
    spec["specularColorFactor"] =
        tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(1.0), tinygltf::Value(0.5), tinygltf::Value(1.0)});
    spec["specularTexture"] = info(b.add_texture(b.add_png_image(1, 1, {10, 20, 30, 153})));
    spec["specularColorTexture"] = info(b.add_texture(b.add_png_image(1, 1, {255, 188, 64, 255})));
    m.extensions["KHR_materials_specular"] = tinygltf::Value(spec);
    trans["transmissionFactor"] = tinygltf::Value(0.6);
    trans["transmissionTexture"] = info(b.add_texture(b.add_png_image(1, 1, {51, 200, 200, 255})));
    m.extensions["KHR_materials_transmission"] = tinygltf::Value(trans);
    b.add_root(b.add_node(mesh));
    return import_gltf(b.model, "quad.gltf");
}

struct MaterialProbe {
    std::vector<pcl_float4> normal, base_color, emission, specular_color, params;
};

// test_material_inputs at barycentrics (b1, b2) of scene triangle 0, seen along -wo.
MaterialProbe probe(const Scene& scene, const std::vector<glm::vec2>& bary, const std::vector<glm::vec3>& wo)
{
    CompiledScene cs = test::compile_default(scene);
    auto order = cs.bvh.triangle_order;
    int leaf = static_cast<int>(std::find(order.begin(), order.end(), 0u) - order.begin());
    float leaf_bits;
    std::memcpy(&leaf_bits, &leaf, 4);
    std::vector<pcl_float4> hits, wos;
    for (std::size_t i = 0; i < bary.size(); ++i) {
        hits.push_back({bary[i].x, bary[i].y, leaf_bits, 0.0f});
        glm::vec3 w = glm::normalize(wo[i]);
        wos.push_back({w.x, w.y, w.z, 0.0f});
    }
    cl::Kernel k(texture_program(), "test_material_inputs");
    ClDevice& dev = test::test_device();
    DeviceArrays arrays = upload_arrays(dev, cs.arrays, 1);
    std::size_t n = hits.size();
    std::vector<cl::Buffer> outs;
    for (int i = 0; i < 5; ++i)
        outs.emplace_back(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Buffer hit_buffer = upload(hits), wo_buffer = upload(wos); // alive until the kernel has run
    bind_kernel(k, arrays, hit_buffer, wo_buffer, outs[0], outs[1], outs[2], outs[3], outs[4]);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    return {read_back(outs[0], n), read_back(outs[1], n), read_back(outs[2], n), read_back(outs[3], n),
            read_back(outs[4], n)};
}

glm::vec3 v3(const pcl_float4& p) { return {p.x, p.y, p.z}; }

TEST(MaterialInputs, TexturesMultiplyTheirFactorsAndVertexColourTheBaseColour)
{
    // base = factor x sRGB texel x COLOR_0; metallic = factor x B, roughness = factor x G;
    // emission = factor x sRGB texel; specular = factor x A, specular colour = factor x
    // sRGB texel, transmission = factor x R. Broken variants seen to fail: metallic from G
    // and roughness from B (swapped channels); emission texels read as linear; specular
    // from R instead of A.
    Scene scene = textured_quad({});
    MaterialProbe p = probe(scene, {{0.2f, 0.3f}}, {{0.0f, 0.0f, 1.0f}});
    glm::vec3 base(0.8f * srgb8_to_linear(188) * 0.5f, 0.6f * srgb8_to_linear(128), 0.4f * srgb8_to_linear(64));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(v3(p.base_color[0])[c], base[c], 1e-6f) << "base colour channel " << c;
    EXPECT_NEAR(p.params[0].x, 0.5f * 204.0f / 255.0f, 1e-6f) << "metallic";
    EXPECT_NEAR(p.params[0].y, 0.8f * 102.0f / 255.0f, 1e-6f) << "roughness";
    glm::vec3 emission(2.0f * srgb8_to_linear(255), 2.0f * srgb8_to_linear(128), 0.0f);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(v3(p.emission[0])[c], emission[c], 1e-6f) << "emission channel " << c;
    EXPECT_NEAR(p.params[0].z, 0.8f * 153.0f / 255.0f, 1e-6f) << "specular";
    glm::vec3 specular_color(srgb8_to_linear(255), 0.5f * srgb8_to_linear(188), srgb8_to_linear(64));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(v3(p.specular_color[0])[c], specular_color[c], 1e-6f) << "specular colour channel " << c;
    EXPECT_NEAR(p.params[0].w, 0.6f * 51.0f / 255.0f, 1e-6f) << "transmission";
}

TEST(MaterialInputs, NormalMapTiltsAlongTheTangentFrame)
{
    // Texel (192, 80, 255) is n_t = (129, -95, 255) / 255 / |.|: towards +u (the
    // tangent) and "down" in the image (against the bitangent, which points up the image,
    // along -v: +y here). For an upright UV layout the tangent is +x; for a mirrored one
    // (u along -x) it is -x, with the bitangent still +y (handedness w = -1). Computed
    // and file tangents agree. Broken variants seen to fail: the bitangent without the
    // handedness sign (mirrored layouts); computed handedness from +dP/dv (the loader's
    // tangents.cpp); the normal map not applied.
    for (bool mirrored : {false, true})
        for (bool file_tangents : {false, true}) {
            SCOPED_TRACE(std::string(mirrored ? "mirrored UVs" : "upright UVs") +
                         (file_tangents ? ", TANGENT from the file" : ", computed tangents"));
            QuadOptions o;
            o.mirrored_uv = mirrored;
            o.file_tangents = file_tangents;
            o.normal_texel = {192, 80, 255, 255};
            MaterialProbe p = probe(textured_quad(o), {{0.3f, 0.3f}}, {{0.0f, 0.0f, 1.0f}});
            double right = 2.0 * 192.0 / 255.0 - 1.0, up = 2.0 * 80.0 / 255.0 - 1.0;
            glm::dvec3 expected = glm::normalize(glm::dvec3(mirrored ? -right : right, up, 1.0));
            glm::dvec3 got(v3(p.normal[0]));
            EXPECT_LT(glm::length(got - expected), 1e-5) << got.x << " " << got.y << " " << got.z;
        }
}

TEST(MaterialInputs, NormalScaleAndBackFaces)
{
    // scale 0.5 halves the tangential part before normalizing; seen from behind (a
    // double-sided material) the mapped normal is the front one turned to the back.
    // Broken variants seen to fail: the scale applied to z too; the front normal used
    // unturned on the back side.
    QuadOptions o;
    o.normal_texel = {255, 0, 255, 255}; // n_t = (1, -1, 1)
    o.normal_scale = 0.5;
    o.double_sided = true;
    MaterialProbe p = probe(textured_quad(o), {{0.3f, 0.3f}, {0.3f, 0.3f}}, {{0.2f, 0.1f, 1.0f}, {0.2f, 0.1f, -1.0f}});
    glm::dvec3 front = glm::normalize(glm::dvec3(0.5, -0.5, 1.0));
    EXPECT_LT(glm::length(glm::dvec3(v3(p.normal[0])) - front), 1e-5);
    EXPECT_LT(glm::length(glm::dvec3(v3(p.normal[1])) + front), 1e-5);
}

TEST(MaterialInputs, NormalsBelowTheSurfaceAreBentBackAboveIt)
{
    // A normal map pointing into the surface, sideways, or exactly backwards (scale 0
    // leaves n_t = (0, 0, -1)), seen from many directions: the shading normal stays a
    // finite unit vector above the geometric surface, on wo's side, and the mirror
    // direction of wo leaves above the surface at no less than min(0.9 cos, 0.01).
    // Broken variant seen to fail: no bending (the normal stays below the surface and
    // every reflected direction is rejected: black).
    struct Case {
        std::vector<std::uint8_t> texel;
        double scale;
    };
    for (const Case& c : {Case{{255, 128, 0, 255}, 1.0}, Case{{255, 128, 128, 255}, 1.0}, Case{{128, 128, 0, 255}, 0.0},
                          Case{{0, 255, 20, 255}, 3.0}, Case{{128, 128, 255, 255}, 1.0}}) {
        QuadOptions o;
        o.normal_texel = c.texel;
        o.normal_scale = c.scale;
        std::vector<glm::vec2> bary;
        std::vector<glm::vec3> wo;
        for (int i = 0; i < 16; ++i) {
            double phi = 2.0 * std::numbers::pi * i / 16.0;
            for (double cos_o : {1.0, 0.5, 0.05, 1e-3}) {
                double s = std::sqrt(1.0 - cos_o * cos_o);
                bary.push_back({0.25f, 0.25f});
                wo.push_back(glm::vec3(glm::dvec3(s * std::cos(phi), s * std::sin(phi), cos_o)));
            }
        }
        MaterialProbe p = probe(textured_quad(o), bary, wo);
        for (std::size_t i = 0; i < wo.size(); ++i) {
            glm::dvec3 n(v3(p.normal[i])), w = glm::normalize(glm::dvec3(wo[i]));
            SCOPED_TRACE("texel " + std::to_string(c.texel[0]) + "," + std::to_string(c.texel[1]) + "," +
                         std::to_string(c.texel[2]) + " wo " + std::to_string(w.x) + "," + std::to_string(w.y) + "," +
                         std::to_string(w.z));
            ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
            EXPECT_NEAR(glm::length(n), 1.0, 1e-5);
            EXPECT_GT(n.z, 0.0) << "above the geometric surface";
            EXPECT_GT(glm::dot(n, w), 0.0) << "on wo's side";
            glm::dvec3 r = 2.0 * glm::dot(n, w) * n - w;
            EXPECT_GE(r.z, std::min(0.9 * w.z, 0.01) - 2e-5) << "mirror direction above the surface";
        }
    }
}

// ---------------------------------------------------------------------------------------
// Textured emitters

TEST(TexturedEmitter, LightSamplesCarryTheTexelAtTheirPoint)
{
    // A unit emissive quad at z = 1 facing down, emissiveFactor 3 times a 2 x 2 nearest
    // texture of four colours. Every light sample from below must carry 3 x the texel
    // under its point (found on the host from the sample's direction). Broken variants
    // seen to fail: the light sample carrying the bare factor; the texture read at the
    // barycentrics of the wrong vertex order.
    test::GltfBuilder b;
    std::vector<glm::vec3> p = {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}}; // counter-clockwise from below
    int pos = b.add_positions(p);
    int idx = b.add_indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    int mat = b.add_material(glm::vec3(0.0f), glm::vec3(3.0f));
    int mesh = b.add_mesh(pos, idx, mat);
    std::vector<glm::vec2> uv;
    for (const glm::vec3& v : p)
        uv.push_back({v.x, 1.0f - v.y});
    b.set_attribute(mesh, "TEXCOORD_0", b.add_texcoords(uv));
    const std::vector<std::uint8_t> texels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    b.model.materials.back().emissiveTexture.index =
        b.add_texture(b.add_png_image(2, 2, texels), b.add_sampler(kNearest, kClamp, kClamp));
    b.add_root(b.add_node(mesh));
    Scene scene = import_gltf(b.model, "emitter.gltf");
    CompiledScene cs = test::compile_default(scene);
    ASSERT_EQ(cs.arrays.lights.size(), 2u);

    const std::size_t n = 20000;
    const glm::vec3 ref(0.3f, 0.6f, 0.0f);
    static cl::Program program = test::build_test_program("trace_test_kernels.cl", kTextureFeatures | FEATURE_AREA_LIGHTS);
    glm::vec3 ref_render(glm::dvec3(ref) - scene.render_origin); // the loader's render space
    std::vector<pcl_float4> rad;
    auto dirs = test::sample_lights_on_device(program, cs.arrays, ref_render, 77u, n, &rad);
    std::size_t checked = 0;
    for (std::size_t i = 0; i < n; ++i) {
        ASSERT_GT(dirs[i].w, 0.0f) << "sample " << i << " failed";
        glm::dvec3 w(dirs[i].x, dirs[i].y, dirs[i].z);
        glm::dvec3 hit = glm::dvec3(ref) + w * ((1.0 - ref.z) / w.z);
        double u = hit.x, v = 1.0 - hit.y;
        if (std::fabs(u - 0.5) < 1e-3 || std::fabs(v - 0.5) < 1e-3)
            continue; // too close to a texel edge to tell which texel the kernel read
        std::size_t texel = (v < 0.5 ? 0 : 2) + (u < 0.5 ? 0 : 1);
        glm::vec3 expected = 3.0f * glm::vec3(texel8(&texels[texel * 4], true));
        EXPECT_NEAR(rad[i].x, expected.x, 1e-6f) << "sample " << i << " texel " << texel;
        EXPECT_NEAR(rad[i].y, expected.y, 1e-6f) << "sample " << i << " texel " << texel;
        EXPECT_NEAR(rad[i].z, expected.z, 1e-6f) << "sample " << i << " texel " << texel;
        ++checked;
    }
    EXPECT_GT(checked, n * 9 / 10);
}

} // namespace
} // namespace pathcl
