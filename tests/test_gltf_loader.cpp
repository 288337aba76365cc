// glTF import (host only, no device): node hierarchy composed in double precision,
// instancing, index types, strips and fans, shading normals and mirroring, degenerate
// and broken data, materials, the camera, and the committed Cornell box. Each test
// checks one property; the tolerance it allows is stated next to it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <ostream>
#include <numbers>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "common/error.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "support/expect_error.h"
#include "support/gltf_builder.h"

namespace pathcl {
namespace {

namespace fs = std::filesystem;
using test::GltfBuilder;

constexpr int kU8 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kU16 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kU32 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
constexpr int kStrip = 5, kFan = 6;

// ---------------------------------------------------------------------------------------
// Helpers

// The loader returns render space (positions relative to render_origin, the camera);
// these tests state their expectations in world space.
Scene in_world_space(Scene s)
{
    for (SceneTriangle& t : s.triangles)
        for (glm::vec3& v : t.v)
            v = glm::vec3(glm::dvec3(v) + s.render_origin);
    s.camera.position += s.render_origin;
    s.render_origin = glm::dvec3(0.0);
    return s;
}

Scene import(const GltfBuilder& b, const std::string& source = "test.gltf")
{
    return in_world_space(import_gltf(b.model, source));
}

glm::dvec3 d3(const glm::vec3& v) { return glm::dvec3(v); }

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

// Unit geometric normal from the stored (counter-clockwise) winding.
glm::dvec3 geometric_normal(const SceneTriangle& t)
{
    return glm::normalize(glm::cross(d3(t.v[1]) - d3(t.v[0]), d3(t.v[2]) - d3(t.v[0])));
}

// |a - b| <= rel * max(1, |b|), componentwise on the vector length.
bool near_rel(const glm::dvec3& a, const glm::dvec3& b, double rel)
{
    return glm::length(a - b) <= rel * std::max(1.0, glm::length(b));
}

std::string str(const glm::dvec3& v)
{
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

// True when `t` has the vertices a, b, c in this counter-clockwise order, up to which
// vertex comes first (a cyclic rotation keeps the winding).
bool same_triangle(const SceneTriangle& t, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                   double rel)
{
    const glm::dvec3 e[3] = {a, b, c};
    for (int s = 0; s < 3; ++s) {
        bool all = true;
        for (int k = 0; k < 3; ++k)
            all = all && near_rel(d3(t.v[k]), e[(k + s) % 3], rel);
        if (all)
            return true;
    }
    return false;
}

// Axis-angle rotation written out (Rodrigues), independent of glm's quaternion code.
glm::dmat3 rodrigues(glm::dvec3 axis, double angle)
{
    axis = glm::normalize(axis);
    glm::dmat3 k(0.0); // cross-product matrix [axis]x, by columns
    k[0] = glm::dvec3(0.0, axis.z, -axis.y);
    k[1] = glm::dvec3(-axis.z, 0.0, axis.x);
    k[2] = glm::dvec3(axis.y, -axis.x, 0.0);
    return glm::dmat3(1.0) + std::sin(angle) * k + (1.0 - std::cos(angle)) * (k * k);
}

// The glTF quaternion [x, y, z, w] of the same rotation.
std::vector<double> quaternion(glm::dvec3 axis, double angle)
{
    axis = glm::normalize(axis);
    double s = std::sin(0.5 * angle);
    return {axis.x * s, axis.y * s, axis.z * s, std::cos(0.5 * angle)};
}

glm::dmat4 affine(const glm::dmat3& m, const glm::dvec3& t = glm::dvec3(0.0))
{
    glm::dmat4 r(m);
    r[3] = glm::dvec4(t, 1.0);
    return r;
}

// One triangle (1,0,0), (0,2,0), (0,0,3): its counter-clockwise normal is (6,3,2)/7.
const std::vector<glm::vec3> kTilted = {{1.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, {0.0f, 0.0f, 3.0f}};
const glm::dvec3 kTiltedNormal = glm::dvec3(6.0, 3.0, 2.0) / 7.0;

// A model with the triangle `p` (non-indexed) in one root node with the given TRS.
GltfBuilder one_triangle(const std::vector<glm::vec3>& p, const std::vector<double>& translation = {},
                         const std::vector<double>& rotation = {}, const std::vector<double>& scale = {},
                         bool with_normals = false, glm::vec3 normal = glm::vec3(0.0f))
{
    GltfBuilder b;
    int pos = b.add_positions(p);
    int nrm = with_normals ? b.add_normals({normal, normal, normal}) : -1;
    int mat = b.add_material(glm::vec3(0.5f));
    int mesh = b.add_mesh(pos, -1, mat, 4, nrm);
    b.add_root(b.add_node(mesh, {}, translation, rotation, scale));
    return b;
}

// Runs `f`, expecting pathcl::Error; returns its message ("" and a failure otherwise).
using test::contains;
using test::error_of;

// ---------------------------------------------------------------------------------------
// Node hierarchy and instancing

// Parent: T * R * S (glTF TRS); child: a general `matrix` with shear. Expected world
// matrix written out here, independently of the loader's composition.
struct Hierarchy {
    glm::dvec3 t{1.5, -2.0, 3.25};
    glm::dvec3 axis{1.0, -2.0, 0.5};
    double angle = 0.7;
    glm::dvec3 s{2.0, 3.0, 0.5};
    // Column-major, as glTF stores it: columns c0, c1, c2, c3.
    std::vector<double> child_matrix = {1.0, 0.2, 0.0, 0.0, //
                                        0.0, 1.0, 0.3, 0.0, //
                                        0.1, 0.0, 1.5, 0.0, //
                                        -0.5, 4.0, 2.0, 1.0};

    glm::dmat4 expected_world() const
    {
        glm::dmat4 T(1.0);
        T[3] = glm::dvec4(t, 1.0);
        glm::dmat4 R = affine(rodrigues(axis, angle));
        glm::dmat4 S(1.0);
        S[0][0] = s.x;
        S[1][1] = s.y;
        S[2][2] = s.z;
        glm::dmat4 M(glm::dvec4(1.0, 0.2, 0.0, 0.0), glm::dvec4(0.0, 1.0, 0.3, 0.0), glm::dvec4(0.1, 0.0, 1.5, 0.0),
                     glm::dvec4(-0.5, 4.0, 2.0, 1.0));
        return T * R * S * M;
    }
};

TEST(GltfHierarchy, ParentTrsTimesChildMatrixGivesWorldPositions)
{
    // Tolerance: 1e-5 relative (positions are stored as float).
    Hierarchy h;
    const std::vector<glm::vec3> p = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.5f, -0.25f}, {-0.75f, 2.0f, 1.0f}};
    GltfBuilder b;
    int mesh = b.add_mesh(b.add_positions(p), -1, b.add_material(glm::vec3(0.5f)));
    int child = b.add_node(mesh, h.child_matrix);
    int parent = b.add_node(-1, {}, {h.t.x, h.t.y, h.t.z}, quaternion(h.axis, h.angle), {h.s.x, h.s.y, h.s.z});
    b.model.nodes[static_cast<std::size_t>(parent)].children = {child};
    b.add_root(parent);

    Scene scene = import(b);
    ASSERT_EQ(scene.triangles.size(), 1u);
    glm::dmat4 w = h.expected_world();
    ASSERT_GT(glm::determinant(glm::dmat3(w)), 0.0); // no mirroring: the vertex order is kept
    glm::dvec3 e[3];
    for (int k = 0; k < 3; ++k)
        e[k] = transform_point(w, d3(p[static_cast<std::size_t>(k)]));
    const SceneTriangle& t = scene.triangles[0];
    EXPECT_TRUE(same_triangle(t, e[0], e[1], e[2], 1e-5))
        << "got " << str(d3(t.v[0])) << " " << str(d3(t.v[1])) << " " << str(d3(t.v[2])) << ", expected "
        << str(e[0]) << " " << str(e[1]) << " " << str(e[2]);
}

TEST(GltfHierarchy, MeshInstancedByTwoNodesGivesTwoCopies)
{
    // Tolerance: 1e-6 relative. Node A: translation (5,0,0); node B: translation (0,0,-3)
    // and 90 degrees about +Z, (x, y) -> (-y, x).
    GltfBuilder b;
    int mesh = b.add_mesh(b.add_positions({{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}), -1,
                          b.add_material(glm::vec3(0.5f)));
    b.add_root(b.add_node(mesh, {}, {5.0, 0.0, 0.0}));
    b.add_root(b.add_node(mesh, {}, {0.0, 0.0, -3.0}, quaternion({0.0, 0.0, 1.0}, std::numbers::pi / 2)));
    Scene scene = import(b);
    ASSERT_EQ(scene.triangles.size(), 2u);
    auto count = [&](glm::dvec3 a, glm::dvec3 bb, glm::dvec3 c) {
        int n = 0;
        for (const SceneTriangle& t : scene.triangles)
            n += same_triangle(t, a, bb, c, 1e-6) ? 1 : 0;
        return n;
    };
    EXPECT_EQ(count({5, 0, 0}, {6, 0, 0}, {5, 1, 0}), 1) << "copy at node A";
    EXPECT_EQ(count({0, 0, -3}, {0, 1, -3}, {-1, 0, -3}), 1) << "copy at node B";
}

TEST(GltfHierarchy, TransformsAreComposedInDoublePrecision)
{
    // Tolerance: 1e-9 absolute. Parent at x = 1e5, child at x = -99999.999: the sum 0.001
    // survives in double precision; composed in float (spacing 0.0078 at 1e5) it is 0.
    GltfBuilder b;
    int mesh = b.add_mesh(b.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, b.add_material(glm::vec3(0.5f)));
    int child = b.add_node(mesh, {}, {-99999.999, 0.0, 0.0});
    int parent = b.add_node(-1, {}, {100000.0, 0.0, 0.0});
    b.model.nodes[static_cast<std::size_t>(parent)].children = {child};
    b.add_root(parent);
    Scene scene = import(b);
    ASSERT_EQ(scene.triangles.size(), 1u);
    double x_min = std::min({scene.triangles[0].v[0].x, scene.triangles[0].v[1].x, scene.triangles[0].v[2].x});
    EXPECT_NEAR(x_min, static_cast<double>(0.001f), 1e-9);
}

TEST(GltfHierarchy, OnlyTheDefaultSceneIsImported)
{
    // Exact count: scene 1 is the default and holds one triangle; scene 0 holds another.
    GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f));
    int m0 = b.add_mesh(b.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, mat);
    int m1 = b.add_mesh(b.add_positions({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}}), -1, mat);
    b.add_root(b.add_node(m0));
    b.model.scenes.emplace_back();
    b.model.scenes[1].nodes = {b.add_node(m1)};
    b.model.defaultScene = 1;
    Scene scene = import(b);
    ASSERT_EQ(scene.triangles.size(), 1u);
    EXPECT_EQ(scene.triangles[0].v[0].z, 5.0f);
}

// ---------------------------------------------------------------------------------------
// Index types, strips and fans

// A unit quad as two triangles, (0,1,2) and (0,2,3), counter-clockwise from +Z.
const std::vector<glm::vec3> kQuad = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
const std::vector<std::uint32_t> kQuadIndices = {0, 1, 2, 0, 2, 3};

Scene quad_with_indices(int component_type) // 0: not indexed
{
    GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f));
    int mesh;
    if (component_type == 0) {
        std::vector<glm::vec3> soup;
        for (std::uint32_t i : kQuadIndices)
            soup.push_back(kQuad[i]);
        mesh = b.add_mesh(b.add_positions(soup), -1, mat);
    } else {
        int pos = b.add_positions(kQuad);
        mesh = b.add_mesh(pos, b.add_indices(kQuadIndices, component_type), mat);
    }
    b.add_root(b.add_node(mesh));
    return import(b);
}

class IndexTypes : public ::testing::TestWithParam<int> {};

TEST_P(IndexTypes, GiveTheSameTriangles)
{
    // Exact: identity transform, the float positions must come through unchanged.
    Scene scene = quad_with_indices(GetParam());
    ASSERT_EQ(scene.triangles.size(), 2u);
    for (std::size_t t = 0; t < 2; ++t)
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_EQ(scene.triangles[t].v[k], kQuad[kQuadIndices[t * 3 + k]]) << "triangle " << t << " vertex " << k;
}

INSTANTIATE_TEST_SUITE_P(GltfIndices, IndexTypes, ::testing::Values(0, kU8, kU16, kU32),
                         [](const ::testing::TestParamInfo<int>& i) {
                             return i.param == 0      ? std::string("NotIndexed")
                                    : i.param == kU8  ? std::string("UnsignedByte")
                                    : i.param == kU16 ? std::string("UnsignedShort")
                                                      : std::string("UnsignedInt");
                         });

// Zig-zag strip in the XY plane whose first triangle (0,1,2) is counter-clockwise from +Z.
const std::vector<glm::vec3> kStripVerts = {{0, 1, 0}, {0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {2, 1, 0}, {2, 0, 0}};
// Fan around vertex 0, counter-clockwise from +Z.
const std::vector<glm::vec3> kFanVerts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}, {-1, 0, 0}};

Scene strip_or_fan(int mode, bool indexed)
{
    const std::vector<glm::vec3>& v = mode == kStrip ? kStripVerts : kFanVerts;
    GltfBuilder b;
    int pos = b.add_positions(v);
    int ind = -1;
    if (indexed) {
        std::vector<std::uint32_t> idx(v.size());
        for (std::size_t i = 0; i < idx.size(); ++i)
            idx[i] = static_cast<std::uint32_t>(i);
        ind = b.add_indices(idx, kU16);
    }
    b.add_root(b.add_node(b.add_mesh(pos, ind, b.add_material(glm::vec3(0.5f)), mode)));
    return import(b);
}

struct StripFanCase {
    int mode;
    bool indexed;
};

void PrintTo(const StripFanCase& c, std::ostream* os)
{
    *os << (c.mode == kStrip ? "strip" : "fan") << (c.indexed ? ", indexed" : ", not indexed");
}

class StripsAndFans : public ::testing::TestWithParam<StripFanCase> {};

TEST_P(StripsAndFans, GiveOneTrianglePerVertexAfterTheSecondOverTheRightVertices)
{
    // Exact positions: triangle i of a strip uses vertices {i, i+1, i+2}; of a fan {0, i+1, i+2}.
    StripFanCase c = GetParam();
    const std::vector<glm::vec3>& v = c.mode == kStrip ? kStripVerts : kFanVerts;
    Scene scene = strip_or_fan(c.mode, c.indexed);
    ASSERT_EQ(scene.triangles.size(), v.size() - 2);
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        std::size_t want[3] = {c.mode == kStrip ? i : 0, i + 1, i + 2};
        for (std::size_t w : want) {
            bool found = false;
            for (const glm::vec3& got : scene.triangles[i].v)
                found = found || got == v[w];
            EXPECT_TRUE(found) << "triangle " << i << " lacks vertex " << w;
        }
    }
}

TEST_P(StripsAndFans, KeepCounterClockwiseWinding)
{
    // Tolerance: geometric normal within 1e-6 of +Z (all source triangles face +Z).
    StripFanCase c = GetParam();
    Scene scene = strip_or_fan(c.mode, c.indexed);
    ASSERT_FALSE(scene.triangles.empty());
    for (std::size_t i = 0; i < scene.triangles.size(); ++i)
        EXPECT_TRUE(near_rel(geometric_normal(scene.triangles[i]), {0, 0, 1}, 1e-6))
            << "triangle " << i << " normal " << str(geometric_normal(scene.triangles[i]));
}

INSTANTIATE_TEST_SUITE_P(GltfModes, StripsAndFans,
                         ::testing::Values(StripFanCase{kStrip, false}, StripFanCase{kStrip, true},
                                           StripFanCase{kFan, false}, StripFanCase{kFan, true}),
                         [](const ::testing::TestParamInfo<StripFanCase>& i) {
                             return std::string(i.param.mode == kStrip ? "Strip" : "Fan") +
                                    (i.param.indexed ? "Indexed" : "NotIndexed");
                         });

TEST(GltfIndices, InterleavedPositionsAndNormalsHonourByteStride)
{
    // Exact positions and normals: one buffer view with stride 24 holding
    // position, normal, position, normal, ...
    std::vector<glm::vec3> interleaved;
    for (const glm::vec3& p : kTilted) {
        interleaved.push_back(p);
        interleaved.push_back(glm::vec3(0.0f, 0.0f, 1.0f));
    }
    GltfBuilder b;
    int view = b.add_view(interleaved.data(), interleaved.size() * sizeof(glm::vec3));
    b.model.bufferViews[static_cast<std::size_t>(view)].byteStride = 24;
    int pos = b.add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3);
    int nrm = b.add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3);
    b.model.accessors[static_cast<std::size_t>(nrm)].byteOffset = 12;
    b.add_root(b.add_node(b.add_mesh(pos, -1, b.add_material(glm::vec3(0.5f)), 4, nrm)));
    Scene scene = import(b);
    ASSERT_EQ(scene.triangles.size(), 1u);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(scene.triangles[0].v[k], kTilted[k]) << "vertex " << k;
        EXPECT_EQ(scene.triangles[0].n[k], glm::vec3(0.0f, 0.0f, 1.0f)) << "normal " << k;
    }
}

// tinygltf's Primitive() sets mode = -1 ("not given"); glTF's default mode is 4
// (triangles). Files are unaffected (tinygltf's parser fills in 4); models built in code
// once imported nothing.
TEST(GltfModes, PrimitiveWithoutModeIsTriangles)
{
    // Exact count: one triangle from a primitive whose mode was never set.
    GltfBuilder b = one_triangle(kTilted);
    b.model.meshes[0].primitives[0].mode = tinygltf::Primitive().mode;
    EXPECT_EQ(import(b).triangles.size(), 1u);
}

TEST(GltfModes, PointsAndLinesAreSkipped)
{
    // Exact count: a points primitive and a lines primitive next to one triangle.
    GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f));
    int pos = b.add_positions(kQuad);
    int tri = b.add_mesh(b.add_positions(kTilted), -1, mat);
    b.add_root(b.add_node(tri));
    b.add_root(b.add_node(b.add_mesh(pos, -1, mat, 0)));
    b.add_root(b.add_node(b.add_mesh(pos, -1, mat, 1)));
    EXPECT_EQ(import(b).triangles.size(), 1u);
}

// ---------------------------------------------------------------------------------------
// Normals

TEST(GltfNormals, AbsentNormalsGiveTheGeometricNormal)
{
    // Tolerance: 1e-6. The tilted triangle's normal is (6,3,2)/7 by hand.
    Scene scene = import(one_triangle(kTilted));
    ASSERT_EQ(scene.triangles.size(), 1u);
    for (int k = 0; k < 3; ++k)
        EXPECT_TRUE(near_rel(d3(scene.triangles[0].n[k]), kTiltedNormal, 1e-6))
            << "vertex " << k << ": " << str(d3(scene.triangles[0].n[k]));
}

TEST(GltfNormals, ZeroLengthAndNanNormalsAreReplacedByTheGeometricNormalAndCounted)
{
    // A zero-length and a NaN normal would give the kernels a NaN shading frame; they
    // become the geometric normal (exact: the same float computation), the valid one is
    // kept (normalized), and the two are counted for the load warning. Naive variant
    // that fails: normalizing every normal unchecked (NaN shading normals).
    GltfBuilder b;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    int normals = b.add_normals({{0.0f, 0.0f, 0.0f}, {nan, 0.0f, 1.0f}, {2.0f, 0.0f, 0.0f}});
    int mesh = b.add_mesh(b.add_positions(kTilted), -1, b.add_material(glm::vec3(0.5f)), 4, normals);
    b.add_root(b.add_node(mesh));
    Scene scene = import(b);
    ASSERT_EQ(scene.triangles.size(), 1u);
    const SceneTriangle& t = scene.triangles[0];
    glm::vec3 c = glm::cross(t.v[1] - t.v[0], t.v[2] - t.v[0]);
    glm::vec3 ng = c / glm::length(c);
    EXPECT_EQ(t.n[0], ng);
    EXPECT_EQ(t.n[1], ng);
    EXPECT_EQ(t.n[2], glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(scene.repaired_normals, 2u);
    EXPECT_EQ(import(one_triangle(kTilted)).repaired_normals, 0u);
}

TEST(GltfNormals, NonUniformScaleTransformsNormalsByTheInverseTranspose)
{
    // Tolerance: 1e-6. Scale (4, 1, 0.5) and a translation: n' ~ (nx/4, ny/1, nz/0.5), so
    // (6,3,2)/7 -> normalize(1.5, 3, 4) (the plain matrix would give normalize(24, 3, 1)).
    Scene scene = import(one_triangle(kTilted, {7.0, -2.0, 1.0}, {}, {4.0, 1.0, 0.5}, true, glm::vec3(kTiltedNormal)));
    ASSERT_EQ(scene.triangles.size(), 1u);
    const glm::dvec3 expected = glm::normalize(glm::dvec3(1.5, 3.0, 4.0));
    for (int k = 0; k < 3; ++k)
        EXPECT_TRUE(near_rel(d3(scene.triangles[0].n[k]), expected, 1e-6))
            << "vertex " << k << ": " << str(d3(scene.triangles[0].n[k])) << ", expected " << str(expected);
}

TEST(GltfNormals, MirrorAcrossZFlipsTheWindingSoTheFrontSideIsKept)
{
    // Tolerance: 1e-6. A triangle in the XY plane facing +Z, mirrored by scale (1, 1, -1):
    // the half-space it faced (z > 0) becomes z < 0, so the geometric normal must be -Z.
    GltfBuilder b = one_triangle({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, {}, {1.0, 1.0, -1.0});
    Scene scene = import(b);
    ASSERT_EQ(scene.triangles.size(), 1u);
    EXPECT_TRUE(near_rel(geometric_normal(scene.triangles[0]), {0, 0, -1}, 1e-6))
        << str(geometric_normal(scene.triangles[0]));
}

TEST(GltfNormals, GeneralMirroringTransformKeepsTheFrontSide)
{
    // Tolerance: 1e-6. Rotation * scale(-1, 2, 1) has a negative determinant; the front
    // side is where the inverse transpose sends the original normal (6,3,2)/7.
    glm::dvec3 axis(0.3, 1.0, -0.4);
    double angle = 2.1;
    Scene scene = import(one_triangle(kTilted, {0.5, 0.0, -1.0}, quaternion(axis, angle), {-1.0, 2.0, 1.0}));
    ASSERT_EQ(scene.triangles.size(), 1u);
    glm::dmat3 m = rodrigues(axis, angle) * glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, 2, 0), glm::dvec3(0, 0, 1));
    ASSERT_LT(glm::determinant(m), 0.0);
    glm::dvec3 expected = glm::normalize(glm::transpose(glm::inverse(m)) * kTiltedNormal);
    EXPECT_TRUE(near_rel(geometric_normal(scene.triangles[0]), expected, 1e-6))
        << "got " << str(geometric_normal(scene.triangles[0])) << ", expected " << str(expected);
}

TEST(GltfNormals, MirroredShadingNormalsAgreeWithTheGeometricNormal)
{
    // Tolerance: 1e-6. The file's NORMAL is the exact face normal, so after any transform
    // the shading normal must equal the (flipped-winding) geometric normal.
    Scene scene = import(one_triangle(kTilted, {}, quaternion({1, 1, 0}, 0.9), {-1.0, 2.0, 1.0}, true,
                                      glm::vec3(kTiltedNormal)));
    ASSERT_EQ(scene.triangles.size(), 1u);
    glm::dvec3 ng = geometric_normal(scene.triangles[0]);
    for (int k = 0; k < 3; ++k)
        EXPECT_TRUE(near_rel(d3(scene.triangles[0].n[k]), ng, 1e-6))
            << "vertex " << k << ": shading " << str(d3(scene.triangles[0].n[k])) << ", geometric " << str(ng);
}

// ---------------------------------------------------------------------------------------
// Degenerate and broken data

// Three triangles: one good, one with a repeated vertex, one with collinear vertices.
GltfBuilder with_degenerates()
{
    GltfBuilder b;
    int pos = b.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}, {2, 2, 2}});
    int ind = b.add_indices({0, 1, 2, 0, 0, 1, 0, 3, 4}, kU16);
    b.add_root(b.add_node(b.add_mesh(pos, ind, b.add_material(glm::vec3(0.5f)))));
    return b;
}

TEST(GltfDegenerate, ZeroAreaTrianglesAreDropped)
{
    // Exact count.
    EXPECT_EQ(import(with_degenerates()).triangles.size(), 1u);
}

TEST(GltfDegenerate, ZeroAreaTrianglesAreCounted)
{
    // Exact count.
    EXPECT_EQ(import(with_degenerates()).dropped_degenerate, 2u);
}

// Node 0 (no mesh) has child node 1 'wing', whose mesh 1 'fuselage' reads POSITION from
// accessor 2, where vertex 1 has the given bad coordinate. Accessors 0 and 1 and mesh 0
// are valid and unused, so the indices in the message cannot be confused.
GltfBuilder with_bad_position(float bad)
{
    GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f));
    int a0 = b.add_positions(kTilted);
    int a1 = b.add_indices({0, 1, 2}, kU16);
    b.add_mesh(a0, a1, mat);
    int a2 = b.add_positions({{0, 0, 0}, {1, bad, 0}, {0, 1, 0}});
    EXPECT_EQ(a2, 2);
    int mesh = b.add_mesh(a2, -1, mat);
    EXPECT_EQ(mesh, 1);
    b.model.meshes[1].name = "fuselage";
    int root = b.add_node(-1);
    int child = b.add_node(mesh);
    EXPECT_EQ(child, 1);
    b.model.nodes[1].name = "wing";
    b.model.nodes[static_cast<std::size_t>(root)].children = {child};
    b.add_root(root);
    return b;
}

void expect_names_source_node_mesh_accessor(const std::string& msg)
{
    EXPECT_TRUE(contains(msg, "plane.gltf")) << msg;
    EXPECT_TRUE(contains(msg, "node 1") || contains(msg, "wing")) << msg;
    EXPECT_TRUE(contains(msg, "mesh 1") || contains(msg, "fuselage")) << msg;
    EXPECT_TRUE(contains(msg, "accessor 2")) << msg;
}

TEST(GltfBrokenData, NanPositionThrowsNamingSourceNodeMeshAccessor)
{
    GltfBuilder b = with_bad_position(std::numeric_limits<float>::quiet_NaN());
    expect_names_source_node_mesh_accessor(error_of([&] { import_gltf(b.model, "plane.gltf"); }));
}

TEST(GltfBrokenData, InfinitePositionThrowsNamingSourceNodeMeshAccessor)
{
    GltfBuilder b = with_bad_position(-std::numeric_limits<float>::infinity());
    expect_names_source_node_mesh_accessor(error_of([&] { import_gltf(b.model, "plane.gltf"); }));
}

TEST(GltfBrokenData, IndexOutOfRangeThrows)
{
    GltfBuilder b;
    int pos = b.add_positions(kTilted);
    b.add_root(b.add_node(b.add_mesh(pos, b.add_indices({0, 1, 3}, kU16), b.add_material(glm::vec3(0.5f)))));
    std::string msg = error_of([&] { import_gltf(b.model, "range.gltf"); });
    EXPECT_TRUE(contains(msg, "range.gltf")) << msg;
}

// Each case breaks one read of a valid one-triangle model so it runs past the end.
struct PastEndCase {
    const char* name;
    std::function<void(GltfBuilder&, int pos_accessor, int index_accessor)> breakit;
};

void PrintTo(const PastEndCase& c, std::ostream* os) { *os << c.name; }

class AccessorPastEnd : public ::testing::TestWithParam<PastEndCase> {};

TEST_P(AccessorPastEnd, Throws)
{
    GltfBuilder b;
    int pos = b.add_positions(kTilted); // 36 bytes
    int ind = b.add_indices({0, 1, 2}, kU16);
    // Unused bytes after the views, so reading past a view's end stays inside the buffer:
    // the accessor must still be refused (it must fit its view, not just the buffer).
    const std::vector<unsigned char> padding(256, 0);
    b.add_view(padding.data(), padding.size());
    b.add_root(b.add_node(b.add_mesh(pos, ind, b.add_material(glm::vec3(0.5f)))));
    ASSERT_NO_THROW(import_gltf(b.model, "end.gltf")); // valid before breaking it
    GetParam().breakit(b, pos, ind);
    std::string msg = error_of([&] { import_gltf(b.model, "end.gltf"); });
    EXPECT_TRUE(contains(msg, "end.gltf")) << msg;
}

INSTANTIATE_TEST_SUITE_P(
    GltfBrokenData, AccessorPastEnd,
    ::testing::Values(
        PastEndCase{"PositionCountTooLarge",
                    [](GltfBuilder& b, int pos, int) {
                        b.model.accessors[static_cast<std::size_t>(pos)].count = 4;
                    }},
        PastEndCase{"PositionByteOffsetTooLarge",
                    [](GltfBuilder& b, int pos, int) {
                        b.model.accessors[static_cast<std::size_t>(pos)].byteOffset = 4;
                    }},
        PastEndCase{"ViewLongerThanBuffer",
                    [](GltfBuilder& b, int pos, int) {
                        // The view claims more than the buffer holds, and the accessor uses it.
                        auto& acc = b.model.accessors[static_cast<std::size_t>(pos)];
                        b.model.bufferViews[static_cast<std::size_t>(acc.bufferView)].byteLength = 8192;
                        acc.count = 600;
                    }},
        PastEndCase{"IndexCountTooLarge",
                    [](GltfBuilder& b, int, int ind) {
                        b.model.accessors[static_cast<std::size_t>(ind)].count = 4;
                    }},
        PastEndCase{"ByteStrideTooLarge",
                    [](GltfBuilder& b, int pos, int) {
                        auto& acc = b.model.accessors[static_cast<std::size_t>(pos)];
                        b.model.bufferViews[static_cast<std::size_t>(acc.bufferView)].byteStride = 16;
                    }}),
    [](const ::testing::TestParamInfo<PastEndCase>& i) { return std::string(i.param.name); });

// A huge count or byteOffset must not wrap the bounds arithmetic around (this once let a
// file read before the start of its buffer).
TEST(GltfBrokenData, WrappingAccessorByteOffsetThrows)
{
    // View 1 starts at byte 36; the accessor's byteOffset 2^64 - 8 makes the start wrap
    // to byte 28, inside the buffer but before the view. The read must be refused (the
    // buggy check passes it and silently reads the wrong bytes).
    GltfBuilder b;
    b.add_positions(kTilted); // view 0: bytes 0..36
    int view = b.add_view(kQuad.data(), kQuad.size() * sizeof(glm::vec3)); // bytes 36..84
    ASSERT_EQ(b.model.bufferViews[static_cast<std::size_t>(view)].byteOffset, 36u);
    int pos = b.add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3);
    b.model.accessors[static_cast<std::size_t>(pos)].byteOffset = std::numeric_limits<std::size_t>::max() - 7;
    b.add_root(b.add_node(b.add_mesh(pos, -1, b.add_material(glm::vec3(0.5f)))));
    std::string msg = error_of([&] { import_gltf(b.model, "wrap.gltf"); });
    EXPECT_TRUE(contains(msg, "wrap.gltf")) << msg;
}

TEST(GltfBrokenData, HugeAccessorCountThrowsPathclError)
{
    // count = 2^62 + 1 VEC3 floats: (count - 1) * 12 bytes is 3 * 2^64, which wraps to 0 in
    // 64-bit arithmetic. The bounds check must still refuse it with a pathcl::Error naming
    // the source (not a std::length_error / bad_alloc from allocating the vertices).
    GltfBuilder b = one_triangle(kTilted);
    b.model.accessors[0].count = (std::size_t{1} << 62) + 1;
    std::string msg = error_of([&] { import_gltf(b.model, "huge.gltf"); });
    EXPECT_TRUE(contains(msg, "huge.gltf")) << msg;
}

TEST(GltfBrokenData, MissingMaterialIndexThrows)
{
    GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f));
    b.add_root(b.add_node(b.add_mesh(b.add_positions(kTilted), -1, mat + 5)));
    std::string msg = error_of([&] { import_gltf(b.model, "material.gltf"); });
    EXPECT_TRUE(contains(msg, "material.gltf")) << msg;
}

TEST(GltfBrokenData, NodeCycleThrows)
{
    // Node 0 -> node 1 -> node 0.
    GltfBuilder b;
    int mesh = b.add_mesh(b.add_positions(kTilted), -1, b.add_material(glm::vec3(0.5f)));
    int n0 = b.add_node(mesh);
    int n1 = b.add_node(-1, {}, {1.0, 0.0, 0.0});
    b.model.nodes[static_cast<std::size_t>(n0)].children = {n1};
    b.model.nodes[static_cast<std::size_t>(n1)].children = {n0};
    b.add_root(n0);
    std::string msg = error_of([&] { import_gltf(b.model, "cycle.gltf"); });
    EXPECT_TRUE(contains(msg, "cycle.gltf")) << msg;
}

TEST(GltfBrokenData, NodeThatIsItsOwnChildThrows)
{
    GltfBuilder b;
    int n0 = b.add_node(b.add_mesh(b.add_positions(kTilted), -1, b.add_material(glm::vec3(0.5f))));
    b.model.nodes[static_cast<std::size_t>(n0)].children = {n0};
    b.add_root(n0);
    std::string msg = error_of([&] { import_gltf(b.model, "self.gltf"); });
    EXPECT_TRUE(contains(msg, "self.gltf")) << msg;
}

TEST(GltfBrokenData, UnknownRequiredExtensionThrowsNamingIt)
{
    GltfBuilder b = one_triangle(kTilted);
    b.model.extensionsUsed = {"EXT_pathcl_test_unknown"};
    b.model.extensionsRequired = {"EXT_pathcl_test_unknown"};
    std::string msg = error_of([&] { import_gltf(b.model, "ext.gltf"); });
    EXPECT_TRUE(contains(msg, "ext.gltf")) << msg;
    EXPECT_TRUE(contains(msg, "EXT_pathcl_test_unknown")) << msg;
}

TEST(GltfBrokenData, SupportedRequiredExtensionIsAccepted)
{
    // Control for the test above: requiring an extension pathcl implements is fine.
    GltfBuilder b = one_triangle(kTilted);
    b.model.extensionsUsed = {"KHR_materials_emissive_strength"};
    b.model.extensionsRequired = {"KHR_materials_emissive_strength"};
    EXPECT_NO_THROW(import_gltf(b.model, "ext.gltf"));
}

// ---------------------------------------------------------------------------------------
// Materials

// One triangle with material `m` (edited by the caller); returns the triangle's material.
SceneMaterial material_of(const std::function<void(tinygltf::Material&)>& edit)
{
    GltfBuilder b = one_triangle(kTilted);
    edit(b.model.materials[0]);
    Scene scene = import(b);
    EXPECT_EQ(scene.triangles.size(), 1u);
    if (scene.triangles.empty())
        return {};
    std::int32_t i = scene.triangles[0].material;
    EXPECT_GE(i, 0);
    EXPECT_LT(static_cast<std::size_t>(i), scene.materials.size());
    return scene.materials.at(static_cast<std::size_t>(i));
}

TEST(GltfMaterials, BaseColorFactor)
{
    // Tolerance: 1e-6.
    SceneMaterial m = material_of([](tinygltf::Material& g) {
        g.pbrMetallicRoughness.baseColorFactor = {0.2, 0.4, 0.6, 1.0};
    });
    EXPECT_TRUE(near_rel(d3(m.base_color), {0.2, 0.4, 0.6}, 1e-6)) << str(d3(m.base_color));
}

TEST(GltfMaterials, MetallicAndRoughnessFactors)
{
    // Tolerance: 1e-6.
    SceneMaterial m = material_of([](tinygltf::Material& g) {
        g.pbrMetallicRoughness.metallicFactor = 0.3;
        g.pbrMetallicRoughness.roughnessFactor = 0.7;
    });
    EXPECT_NEAR(m.metallic, 0.3, 1e-6);
    EXPECT_NEAR(m.roughness, 0.7, 1e-6);
}

TEST(GltfMaterials, EmissionIsEmissiveFactorTimesEmissiveStrength)
{
    // Tolerance: 1e-6 relative. (1, 0.5, 0.25) x 4 = (4, 2, 1).
    SceneMaterial m = material_of([](tinygltf::Material& g) {
        g.emissiveFactor = {1.0, 0.5, 0.25};
        tinygltf::Value::Object ext;
        ext["emissiveStrength"] = tinygltf::Value(4.0);
        g.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(ext);
    });
    EXPECT_TRUE(near_rel(d3(m.emission), {4.0, 2.0, 1.0}, 1e-6)) << str(d3(m.emission));
}

TEST(GltfMaterials, IntegerEmissiveStrength)
{
    // Tolerance: 1e-6 relative. A JSON integer ("emissiveStrength": 17) is an int Value.
    SceneMaterial m = material_of([](tinygltf::Material& g) {
        g.emissiveFactor = {1.0, 0.5, 0.25};
        tinygltf::Value::Object ext;
        ext["emissiveStrength"] = tinygltf::Value(17);
        g.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(ext);
    });
    EXPECT_TRUE(near_rel(d3(m.emission), {17.0, 8.5, 4.25}, 1e-6)) << str(d3(m.emission));
}

TEST(GltfMaterials, EmissionWithoutStrengthIsTheEmissiveFactor)
{
    // Tolerance: 1e-6 relative.
    SceneMaterial m = material_of([](tinygltf::Material& g) { g.emissiveFactor = {1.0, 0.5, 0.25}; });
    EXPECT_TRUE(near_rel(d3(m.emission), {1.0, 0.5, 0.25}, 1e-6)) << str(d3(m.emission));
}

TEST(GltfMaterials, DoubleSidedTrue)
{
    EXPECT_TRUE(material_of([](tinygltf::Material& g) { g.doubleSided = true; }).double_sided);
}

TEST(GltfMaterials, DoubleSidedFalse)
{
    EXPECT_FALSE(material_of([](tinygltf::Material& g) { g.doubleSided = false; }).double_sided);
}

TEST(GltfMaterials, PrimitiveWithoutMaterialGetsTheGltfDefaultMaterial)
{
    // Exact: glTF default material is base colour 1, metallic 1, roughness 1, no emission,
    // single-sided. The model also has a red material (used by another mesh), which the
    // material-less primitive must not pick up.
    GltfBuilder b;
    int red = b.add_material(glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f), true);
    b.add_root(b.add_node(b.add_mesh(b.add_positions(kTilted), -1, red)));
    b.add_root(b.add_node(b.add_mesh(b.add_positions(kQuad), -1, -1, 6)));
    Scene scene = import(b);
    ASSERT_EQ(scene.triangles.size(), 3u);
    int checked = 0;
    for (const SceneTriangle& t : scene.triangles) {
        if (t.v[0].z != 0.0f || t.v[1].z != 0.0f || t.v[2].z != 0.0f)
            continue; // the red triangle (kTilted) is not in z = 0
        ASSERT_GE(t.material, 0);
        ASSERT_LT(static_cast<std::size_t>(t.material), scene.materials.size());
        const SceneMaterial& m = scene.materials[static_cast<std::size_t>(t.material)];
        EXPECT_EQ(m.base_color, glm::vec3(1.0f));
        EXPECT_EQ(m.metallic, 1.0f);
        EXPECT_EQ(m.roughness, 1.0f);
        EXPECT_EQ(m.emission, glm::vec3(0.0f));
        EXPECT_FALSE(m.double_sided);
        ++checked;
    }
    EXPECT_EQ(checked, 2);
}

// ---------------------------------------------------------------------------------------
// Camera

// Root node: translation (10, -4, 2) and uniform scale 2. Its child: translation
// (1, 2, 3), a general rotation, scale 3 and the perspective camera (yfov 0.7).
struct CameraRig {
    glm::dvec3 parent_t{10.0, -4.0, 2.0};
    double parent_s = 2.0;
    glm::dvec3 child_t{1.0, 2.0, 3.0};
    glm::dvec3 axis{1.0, 2.0, 3.0};
    double angle = 1.1;
    double yfov = 0.7;

    Scene load() const
    {
        GltfBuilder b;
        b.add_root(b.add_node(b.add_mesh(b.add_positions(kTilted), -1, b.add_material(glm::vec3(0.5f)))));
        int cam = b.add_node(-1, {}, {child_t.x, child_t.y, child_t.z}, quaternion(axis, angle), {3.0, 3.0, 3.0});
        b.model.nodes[static_cast<std::size_t>(cam)].camera = b.add_perspective_camera(yfov);
        int parent = b.add_node(-1, {}, {parent_t.x, parent_t.y, parent_t.z}, {}, {parent_s, parent_s, parent_s});
        b.model.nodes[static_cast<std::size_t>(parent)].children = {cam};
        b.add_root(parent);
        return import(b);
    }
    glm::dmat3 rotation() const { return rodrigues(axis, angle); }
};

TEST(GltfCamera, PositionIsTheNodeWorldPosition)
{
    // Tolerance: 1e-9 relative. parent_t + parent_s * child_t.
    CameraRig rig;
    Scene s = rig.load();
    glm::dvec3 expected = rig.parent_t + rig.parent_s * rig.child_t;
    EXPECT_TRUE(near_rel(s.camera.position, expected, 1e-9)) << str(s.camera.position);
}

TEST(GltfCamera, ForwardIsLocalMinusZ)
{
    // Tolerance: 1e-9.
    CameraRig rig;
    Scene s = rig.load();
    glm::dvec3 expected = rig.rotation() * glm::dvec3(0, 0, -1);
    EXPECT_TRUE(near_rel(s.camera.forward, expected, 1e-9)) << str(s.camera.forward) << " vs " << str(expected);
}

TEST(GltfCamera, UpIsLocalPlusY)
{
    // Tolerance: 1e-9.
    CameraRig rig;
    Scene s = rig.load();
    glm::dvec3 expected = rig.rotation() * glm::dvec3(0, 1, 0);
    EXPECT_TRUE(near_rel(s.camera.up, expected, 1e-9)) << str(s.camera.up) << " vs " << str(expected);
}

TEST(GltfCamera, RightIsLocalPlusX)
{
    // Tolerance: 1e-9.
    CameraRig rig;
    Scene s = rig.load();
    glm::dvec3 expected = rig.rotation() * glm::dvec3(1, 0, 0);
    EXPECT_TRUE(near_rel(s.camera.right, expected, 1e-9)) << str(s.camera.right) << " vs " << str(expected);
}

TEST(GltfCamera, NodeScaleDoesNotChangeYfov)
{
    // Tolerance: exact (the file's value; scale 2 x 3 on the camera's nodes).
    CameraRig rig;
    Scene s = rig.load();
    EXPECT_EQ(s.camera.yfov, rig.yfov);
    EXPECT_TRUE(s.camera.from_file);
}

TEST(GltfCamera, FirstCameraNodeIsUsedAndCameraNPicksTheNth)
{
    // Tolerance: exact. Root order: an orthographic camera, perspective A (yfov 0.5),
    // perspective B (yfov 0.9). By default the first camera node (the orthographic one);
    // --camera N counts camera nodes of either type from 0.
    GltfBuilder b;
    b.add_root(b.add_node(b.add_mesh(b.add_positions(kTilted), -1, b.add_material(glm::vec3(0.5f)))));
    tinygltf::Camera ortho;
    ortho.type = "orthographic";
    ortho.orthographic.xmag = ortho.orthographic.ymag = 1.0;
    ortho.orthographic.znear = 0.01;
    ortho.orthographic.zfar = 100.0;
    b.model.cameras.push_back(ortho);
    int o = b.add_node(-1, {}, {0.0, 0.0, 9.0});
    b.model.nodes[static_cast<std::size_t>(o)].camera = 0;
    int a = b.add_node(-1, {}, {0.0, 0.0, 5.0});
    b.model.nodes[static_cast<std::size_t>(a)].camera = b.add_perspective_camera(0.5);
    int c = b.add_node(-1, {}, {0.0, 0.0, 7.0});
    b.model.nodes[static_cast<std::size_t>(c)].camera = b.add_perspective_camera(0.9);
    b.add_root(o);
    b.add_root(a);
    b.add_root(c);
    Scene s = import(b);
    EXPECT_TRUE(s.camera.orthographic);
    EXPECT_EQ(s.camera.ymag, 1.0);
    EXPECT_EQ(s.camera.position, glm::dvec3(0.0, 0.0, 9.0));
    Scene s1 = in_world_space(import_gltf(b.model, "test.gltf", "", 1));
    EXPECT_FALSE(s1.camera.orthographic);
    EXPECT_EQ(s1.camera.yfov, 0.5);
    EXPECT_EQ(s1.camera.position, glm::dvec3(0.0, 0.0, 5.0));
    Scene s2 = in_world_space(import_gltf(b.model, "test.gltf", "", 2));
    EXPECT_EQ(s2.camera.yfov, 0.9);
    EXPECT_EQ(s2.camera.position, glm::dvec3(0.0, 0.0, 7.0));
    EXPECT_THROW(import_gltf(b.model, "test.gltf", "", 3), Error);
}

// Bounds (0..2, -1..1, 3..4) from two triangles; no camera in the file.
Scene framed_scene()
{
    GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f));
    b.add_root(b.add_node(b.add_mesh(b.add_positions({{0, -1, 3}, {2, -1, 3}, {2, 1, 3}}), -1, mat)));
    b.add_root(b.add_node(b.add_mesh(b.add_positions({{0, -1, 4}, {2, 1, 4}, {0, 1, 4}}), -1, mat)));
    return import(b);
}

TEST(GltfCamera, WithoutCameraTheFramingCameraIsOutsideTheBounds)
{
    // Exact comparison with the bounds (0..2, -1..1, 3..4): outside the bounding sphere.
    Scene s = framed_scene();
    EXPECT_FALSE(s.camera.from_file);
    glm::dvec3 centre(1.0, 0.0, 3.5);
    double radius = 0.5 * glm::length(glm::dvec3(2.0, 2.0, 1.0));
    EXPECT_GT(glm::length(s.camera.position - centre), radius) << str(s.camera.position);
}

TEST(GltfCamera, WithoutCameraTheFramingCameraLooksAtTheCentre)
{
    // Tolerance: direction to the centre within 1e-9 of forward.
    Scene s = framed_scene();
    glm::dvec3 to_centre = glm::normalize(glm::dvec3(1.0, 0.0, 3.5) - s.camera.position);
    EXPECT_TRUE(near_rel(s.camera.forward, to_centre, 1e-9)) << str(s.camera.forward) << " vs " << str(to_centre);
}

TEST(GltfCamera, WithoutCameraEveryBoundsCornerIsInsideTheVerticalFieldOfView)
{
    // Tolerance: 1e-9 rad. The angle from forward to each corner of the bounds is at most
    // half the vertical field of view (the narrower one for any aspect ratio >= 1).
    Scene s = framed_scene();
    ASSERT_GT(s.camera.yfov, 0.0);
    for (int i = 0; i < 8; ++i) {
        glm::dvec3 corner((i & 1) ? 2.0 : 0.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 4.0 : 3.0);
        double cosang = glm::dot(glm::normalize(corner - s.camera.position), glm::normalize(s.camera.forward));
        EXPECT_LE(std::acos(std::min(1.0, cosang)), 0.5 * s.camera.yfov + 1e-9) << "corner " << str(corner);
    }
}

// ---------------------------------------------------------------------------------------
// Files

const std::string kCornell = std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box.gltf";

const Scene& cornell_box()
{
    static const Scene s = in_world_space(load_gltf(kCornell));
    return s;
}

TEST(GltfCornellBox, Has38Triangles)
{
    EXPECT_EQ(cornell_box().triangles.size(), 38u); // exact
}

TEST(GltfCornellBox, TwoTrianglesEmitRadiance17_12_4)
{
    // Tolerance: 1e-4 absolute per channel.
    const Scene& s = cornell_box();
    int emissive = 0;
    for (const SceneTriangle& t : s.triangles) {
        const SceneMaterial& m = s.materials.at(static_cast<std::size_t>(t.material));
        if (!m.emits())
            continue;
        ++emissive;
        EXPECT_NEAR(m.emission.x, 17.0, 1e-4);
        EXPECT_NEAR(m.emission.y, 12.0, 1e-4);
        EXPECT_NEAR(m.emission.z, 4.0, 1e-4);
    }
    EXPECT_EQ(emissive, 2);
}

TEST(GltfCornellBox, CameraPosition)
{
    // Tolerance: 1e-9 absolute.
    const SceneCamera& c = cornell_box().camera;
    EXPECT_TRUE(c.from_file);
    EXPECT_NEAR(c.position.x, 0.278, 1e-9);
    EXPECT_NEAR(c.position.y, 0.273, 1e-9);
    EXPECT_NEAR(c.position.z, -0.8, 1e-9);
}

TEST(GltfCornellBox, CameraLooksAlongPlusZWithPlusYUp)
{
    // Tolerance: 1e-9.
    const SceneCamera& c = cornell_box().camera;
    EXPECT_TRUE(near_rel(c.forward, {0, 0, 1}, 1e-9)) << str(c.forward);
    EXPECT_TRUE(near_rel(c.up, {0, 1, 0}, 1e-9)) << str(c.up);
}

TEST(GltfCornellBox, Yfov)
{
    // Tolerance: 1e-9 rad. A 35 mm lens on a 25 mm tall film.
    EXPECT_NEAR(cornell_box().camera.yfov, 2.0 * std::atan(12.5 / 35.0), 1e-9);
}

// A fresh directory for files a test writes; removed afterwards.
class GltfFiles : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("pathcl-gltf-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override
    {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    fs::path dir_;
};

TEST_F(GltfFiles, MissingFileThrowsNamingIt)
{
    std::string path = (dir_ / "no-such-scene.gltf").string();
    std::string msg = error_of([&] { load_gltf(path); });
    EXPECT_TRUE(contains(msg, "no-such-scene.gltf")) << msg;
}

TEST_F(GltfFiles, InvalidJsonThrowsNamingTheFile)
{
    fs::path path = dir_ / "broken-json.gltf";
    std::ofstream(path) << "{ \"asset\": { \"version\": \"2.0\" }, \"nodes\": [ { \"mesh\": ";
    std::string msg = error_of([&] { load_gltf(path.string()); });
    EXPECT_TRUE(contains(msg, "broken-json.gltf")) << msg;
}

TEST_F(GltfFiles, ErrorMessagesAreOneLine)
{
    // The CLI prints the message as one line: no newline inside it.
    fs::path path = dir_ / "broken-json.gltf";
    std::ofstream(path) << "{ not json at all\n\n";
    std::string msg = error_of([&] { load_gltf(path.string()); });
    EXPECT_FALSE(msg.empty());
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

} // namespace
} // namespace pathcl
