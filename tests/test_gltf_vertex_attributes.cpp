// glTF vertex attributes for texturing on the host (no device): COLOR_0 in every allowed
// form, and tangents from the file (following the node, flipped under a mirror) and
// computed (orthonormal, right-handed on mirrored layouts, one frame per flat face).
// Next to each test: a broken variant seen to fail it.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "compile/kernel_features.h"
#include "scene/gltf_loader.h"
#include "scene/tangents.h"
#include "support/gltf_builder.h"
#include "support/gltf_texture_fixtures.h"

namespace pathcl::test_gltf_vertex_attributes {
namespace {

using test::GltfBuilder;
using test::kU16;
using test::kU8;
using test::Quad;
using test::quad;
using test::white_texture;

// ---------------------------------------------------------------------------------------
// Vertex colours

TEST(GltfTextures, VertexColorsInEveryAllowedForm)
{
    // COLOR_0 as VEC3 float, VEC4 normalized u8 and u16 (alpha kept), VEC3 normalized
    // u8 (alpha 1); a primitive without COLOR_0 in the same scene is opaque white.
    // Broken variant seen to fail: u16 colours divided by 255.
    GltfBuilder b;
    int mat = b.add_material(glm::vec3(1.0f));
    auto add = [&](int color_accessor, float x) {
        int pos = b.add_positions({{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}});
        int mesh = b.add_mesh(pos, -1, mat);
        if (color_accessor >= 0)
            b.set_attribute(mesh, "COLOR_0", color_accessor);
        b.add_root(b.add_node(mesh));
    };
    auto normalized = [&](int accessor) {
        b.model.accessors[static_cast<std::size_t>(accessor)].normalized = true;
        return accessor;
    };
    add(b.add_positions({{0.25f, 0.5f, 1.0f}, {0, 0, 0}, {1, 1, 1}}), 0.0f);
    const std::uint8_t u8v4[12] = {255, 0, 51, 7, 0, 0, 0, 0, 0, 0, 0, 0};
    add(normalized(b.add_accessor(b.add_view(u8v4, 12), kU8, TINYGLTF_TYPE_VEC4, 3)), 2.0f);
    const std::uint16_t u16v4[12] = {65535, 0, 13107, 1, 0, 0, 0, 0, 0, 0, 0, 0};
    add(normalized(b.add_accessor(b.add_view(u16v4, 24), kU16, TINYGLTF_TYPE_VEC4, 3)), 4.0f);
    const std::uint8_t u8v3[12] = {0, 255, 102, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    add(normalized(b.add_accessor(b.add_view(u8v3, 12), kU8, TINYGLTF_TYPE_VEC3, 3)), 6.0f);
    add(-1, 8.0f);
    Scene s = import_gltf(b.model, "colors.gltf");
    ASSERT_EQ(s.colors.size(), 5u);
    EXPECT_TRUE(kernel_features(s, RenderOptions{}).has(FEATURE_VERTEX_COLORS));
    auto first_color = [&](float x) {
        for (std::size_t i = 0; i < s.triangles.size(); ++i)
            if (std::fabs(s.triangles[i].v[0].x + static_cast<float>(s.render_origin.x) - x) < 1e-4f)
                return s.colors[i][0];
        ADD_FAILURE() << "no triangle at x = " << x;
        return glm::vec4(-1.0f);
    };
    auto near = [](glm::vec4 a, glm::vec4 e) { return glm::length(a - e) < 1e-6f; };
    EXPECT_TRUE(near(first_color(0.0f), {0.25f, 0.5f, 1.0f, 1.0f}));
    EXPECT_TRUE(near(first_color(2.0f), {1.0f, 0.0f, 0.2f, 7.0f / 255.0f}));
    EXPECT_TRUE(near(first_color(4.0f), {1.0f, 0.0f, 0.2f, 1.0f / 65535.0f}));
    EXPECT_TRUE(near(first_color(6.0f), {0.0f, 1.0f, 0.4f, 1.0f}));
    EXPECT_TRUE(near(first_color(8.0f), {1.0f, 1.0f, 1.0f, 1.0f}));
}

// ---------------------------------------------------------------------------------------
// Tangents

// A material with a normal texture on the quad.
Quad normal_mapped_quad()
{
    Quad q = quad(false);
    q.mat().normalTexture.index = white_texture(q.b);
    return q;
}

TEST(GltfTangents, FileTangentsFollowTheNodeAndFlipUnderAMirror)
{
    // TANGENT (1, 0, 0, +1): rotated 90 degrees about +z it becomes (0, 1, 0, +1); under
    // the mirror scale (-1, 1, 1) it becomes (-1, 0, 0) with handedness -1. Broken
    // variant seen to fail: handedness kept under the mirror.
    for (bool mirror : {false, true}) {
        Quad q = normal_mapped_quad();
        glm::vec4 t(1, 0, 0, 1);
        q.b.set_attribute(q.mesh, "TANGENT", q.b.add_tangents({t, t, t, t}));
        tinygltf::Node& node = q.b.model.nodes[0];
        if (mirror)
            node.scale = {-1.0, 1.0, 1.0};
        else
            node.rotation = {0.0, 0.0, std::sin(std::numbers::pi / 4.0), std::cos(std::numbers::pi / 4.0)};
        Scene s = import_gltf(q.b.model, "tangents.gltf");
        ASSERT_EQ(s.tangents.size(), 2u);
        glm::vec4 expected = mirror ? glm::vec4(-1, 0, 0, -1) : glm::vec4(0, 1, 0, 1);
        for (const TriangleTangent& tri : s.tangents)
            for (const glm::vec4& got : tri)
                EXPECT_LT(glm::length(got - expected), 1e-6f) << (mirror ? "mirrored" : "rotated");
    }
}

TEST(GltfTangents, ComputedTangentsAreOrthonormalAndRightHanded)
{
    // A bent strip (normals not equal to face normals, non-uniform UV density). At every
    // corner: |t| = 1, t . n = 0, t along +dP/du, and w cross(n, t) along -dP/dv (the
    // image's "up"), for the upright layout (w = +1) and the mirrored one (u -> 1 - u,
    // w = -1). Broken variants seen to fail: no Gram-Schmidt (t . n != 0 on the bend);
    // handedness from +dP/dv.
    for (bool mirrored : {false, true}) {
        std::vector<glm::dvec3> p, n;
        std::vector<glm::dvec2> uv;
        for (int i = 0; i <= 4; ++i) {
            double a = 0.3 * i, x = std::sin(a), z = 1.0 - std::cos(a);
            for (int j = 0; j <= 1; ++j) {
                p.push_back({x, j * 1.5, z});
                n.push_back(glm::normalize(glm::dvec3(-std::sin(a), 0.0, std::cos(a))));
                double u = 0.2 * i * i / 4.0 + 0.1 * i; // non-uniform
                uv.push_back({mirrored ? 1.0 - u : u, 1.0 - 0.8 * j});
            }
        }
        std::vector<std::uint32_t> tris;
        for (std::uint32_t i = 0; i < 4; ++i) {
            std::uint32_t a = 2 * i, b2 = 2 * i + 2, c = 2 * i + 3, d = 2 * i + 1;
            tris.insert(tris.end(), {a, b2, c, a, c, d});
        }
        std::vector<glm::dvec4> t = compute_tangents(p, n, uv, tris);
        ASSERT_EQ(t.size(), tris.size());
        for (std::size_t c = 0; c < tris.size(); ++c) {
            const glm::dvec3& nn = n[tris[c]];
            glm::dvec3 tt(t[c]);
            EXPECT_NEAR(glm::length(tt), 1.0, 1e-12);
            EXPECT_NEAR(glm::dot(tt, nn), 0.0, 1e-12);
            // dP/du points along the strip's length (+x side) when u grows with i.
            glm::dvec3 along =
                glm::normalize(glm::dvec3(std::cos(0.3 * (tris[c] / 2)), 0.0, std::sin(0.3 * (tris[c] / 2))));
            EXPECT_GT(glm::dot(tt, along) * (mirrored ? -1.0 : 1.0), 0.9);
            // v decreases with +y (v = 1 - 0.8 j), so "up" in the image is +y.
            glm::dvec3 bitangent = t[c].w * glm::cross(nn, tt);
            EXPECT_GT(bitangent.y, 0.99);
            EXPECT_EQ(t[c].w, mirrored ? -1.0 : 1.0);
        }
    }
}

TEST(GltfTangents, FlatShadingGetsOneFramePerFace)
{
    // Without NORMAL each triangle gets a tangent orthogonal to its own face normal.
    // Broken variant seen to fail: every face framed around the first face's normal.
    std::vector<glm::dvec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}};
    std::vector<glm::dvec2> uv = {{0, 1}, {1, 1}, {0, 0}, {1, 1}, {1, 0}, {0, 0}};
    std::vector<std::uint32_t> tris = {0, 1, 2, 3, 4, 5};
    std::vector<glm::dvec4> t = compute_tangents(p, {}, uv, tris);
    for (int f = 0; f < 2; ++f) {
        glm::dvec3 fn =
            glm::normalize(glm::cross(p[tris[3 * f + 1]] - p[tris[3 * f]], p[tris[3 * f + 2]] - p[tris[3 * f]]));
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(glm::dot(glm::dvec3(t[static_cast<std::size_t>(3 * f + k)]), fn), 0.0, 1e-12) << "face " << f;
            EXPECT_EQ(t[static_cast<std::size_t>(3 * f + k)], t[static_cast<std::size_t>(3 * f)]);
        }
    }
}

TEST(GltfTangents, LoaderComputesTangentsWhenTheFileHasNone)
{
    // The quad (u = x, v = 1 - y): tangent +x, handedness +1, through the loader. Broken
    // variant seen to fail: handedness from +dP/dv.
    Quad q = normal_mapped_quad();
    Scene s = import_gltf(q.b.model, "computed.gltf");
    ASSERT_EQ(s.tangents.size(), 2u);
    for (const TriangleTangent& tri : s.tangents)
        for (const glm::vec4& t : tri)
            EXPECT_LT(glm::length(t - glm::vec4(1, 0, 0, 1)), 1e-6f);
}

} // namespace
} // namespace pathcl::test_gltf_vertex_attributes
