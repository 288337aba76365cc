// glTF primitives (host only, no device): index types, strips and fans (vertices and
// winding), byte strides, primitive modes, shading normals (absent, broken, under
// non-uniform scale and mirroring), and degenerate triangles dropped and counted. Each
// test checks one property; the tolerance it allows is stated next to it.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.h"
#include "scene/scene.h"
#include "support/gltf_builder.h"
#include "support/gltf_fixtures.h"

namespace pathcl::test_gltf_primitives {
namespace {

using test::d3;
using test::GltfBuilder;
using test::import;
using test::kQuad;
using test::kQuadIndices;
using test::kTilted;
using test::kTiltedNormal;
using test::kU16;
using test::kU32;
using test::kU8;
using test::near_rel;
using test::one_triangle;
using test::quaternion;
using test::rodrigues;
using test::str;

constexpr int kStrip = 5, kFan = 6;

// Unit geometric normal from the stored (counter-clockwise) winding.
glm::dvec3 geometric_normal(const SceneTriangle& t)
{
    return glm::normalize(glm::cross(d3(t.v[1]) - d3(t.v[0]), d3(t.v[2]) - d3(t.v[0])));
}

// ---------------------------------------------------------------------------------------
// Index types, strips and fans

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
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(import(b).triangles.size(), 1u);
    std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("test.gltf: skipped 2 point and line primitives (only triangles are rendered)"),
              std::string::npos)
        << err;
}

TEST(GltfModes, IndicesBeyondTheLastWholeTriangleAreDroppedWithAWarning)
{
    // A triangle list of 7 indices and one of 5 vertices: 2 + 1 triangles, one warning line
    // counting both primitives. Broken variant seen to fail: no warning (it was silent).
    GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f));
    int pos = b.add_positions(kQuad);
    b.add_root(b.add_node(b.add_mesh(pos, b.add_indices({0, 1, 2, 0, 2, 3, 1}, kU16), mat)));
    std::vector<glm::vec3> five = {kQuad[0], kQuad[1], kQuad[2], kQuad[0], kQuad[2]};
    b.add_root(b.add_node(b.add_mesh(b.add_positions(five), -1, mat)));
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(import(b).triangles.size(), 3u);
    std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(err, "pathcl: warning: test.gltf: ignored the last one or two indices of 2 triangle primitives whose "
                   "index count is not a multiple of 3\n");
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
    Scene scene =
        import(one_triangle(kTilted, {}, quaternion({1, 1, 0}, 0.9), {-1.0, 2.0, 1.0}, true, glm::vec3(kTiltedNormal)));
    ASSERT_EQ(scene.triangles.size(), 1u);
    glm::dvec3 ng = geometric_normal(scene.triangles[0]);
    for (int k = 0; k < 3; ++k)
        EXPECT_TRUE(near_rel(d3(scene.triangles[0].n[k]), ng, 1e-6))
            << "vertex " << k << ": shading " << str(d3(scene.triangles[0].n[k])) << ", geometric " << str(ng);
}

// ---------------------------------------------------------------------------------------
// Degenerate triangles

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

// ---------------------------------------------------------------------------------------
// KHR_mesh_quantization

// A triangle with float positions and normals, or the same values stored as integers the
// way the extension allows: positions unnormalized i16 (8-byte stride: the 4-byte vertex
// alignment), normals normalized i8 (4-byte stride).
GltfBuilder quantized_triangle(bool integers, bool declare_extension)
{
    GltfBuilder b;
    int pos, nrm;
    if (!integers) {
        pos = b.add_positions({{0, 0, 0}, {3, 0, 0}, {0, 2, 0}});
        nrm = b.add_normals({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    } else {
        const std::int16_t p[12] = {0, 0, 0, 0, 3, 0, 0, 0, 0, 2, 0, 0};
        int view = b.add_view(p, sizeof p);
        b.model.bufferViews[static_cast<std::size_t>(view)].byteStride = 8;
        pos = b.add_accessor(view, TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_TYPE_VEC3, 3);
        const std::int8_t n[12] = {0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0};
        view = b.add_view(n, sizeof n);
        b.model.bufferViews[static_cast<std::size_t>(view)].byteStride = 4;
        nrm = b.add_accessor(view, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_TYPE_VEC3, 3);
        b.model.accessors[static_cast<std::size_t>(nrm)].normalized = true;
    }
    if (declare_extension) {
        b.model.extensionsUsed.push_back("KHR_mesh_quantization");
        b.model.extensionsRequired.push_back("KHR_mesh_quantization");
    }
    b.add_root(b.add_node(b.add_mesh(pos, -1, b.add_material(glm::vec3(0.5f)), 4, nrm), {}, {1, 2, 3}));
    return b;
}

TEST(GltfQuantization, IntegerAttributesGiveTheSameTrianglesAsFloats)
{
    // Exact: the integers and 127/127 decode to exactly the float values.
    Scene floats = import(quantized_triangle(false, false));
    Scene integers = import(quantized_triangle(true, true));
    ASSERT_EQ(floats.triangles.size(), 1u);
    ASSERT_EQ(integers.triangles.size(), 1u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(integers.triangles[0].v[k], floats.triangles[0].v[k]) << "vertex " << k;
        EXPECT_EQ(integers.triangles[0].n[k], floats.triangles[0].n[k]) << "normal " << k;
    }
}

TEST(GltfQuantization, IntegerPositionsWithoutTheExtensionAreRefused)
{
    EXPECT_THROW(import(quantized_triangle(true, false)), Error);
}

// ---------------------------------------------------------------------------------------
// Sparse accessors and accessors without a bufferView

// Positions of the triangle (0,0,0), (3,0,0), (0,2,0) as a sparse accessor: on a dense
// base whose vertices 1 and 2 are wrong (base_view true), or on no bufferView at all
// (zeros); the sparse part replaces vertices 1 and 2. `indices` are the sparse indices.
GltfBuilder sparse_triangle(bool base_view, const std::vector<std::uint16_t>& indices)
{
    GltfBuilder b;
    int pos;
    if (base_view)
        pos = b.add_positions({{0, 0, 0}, {9, 9, 9}, {7, 7, 7}});
    else
        pos = b.add_accessor(-1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3);
    const float values[6] = {3, 0, 0, 0, 2, 0};
    tinygltf::Accessor& acc = b.model.accessors[static_cast<std::size_t>(pos)];
    acc.sparse.isSparse = true;
    acc.sparse.count = static_cast<int>(indices.size());
    acc.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    acc.sparse.indices.byteOffset = 0;
    acc.sparse.values.byteOffset = 0;
    int index_view = b.add_view(indices.data(), indices.size() * 2);
    int value_view = b.add_view(values, sizeof values);
    acc.sparse.indices.bufferView = index_view; // add_view leaves the accessors where they are
    acc.sparse.values.bufferView = value_view;
    b.add_root(b.add_node(b.add_mesh(pos, -1, b.add_material(glm::vec3(0.5f)))));
    return b;
}

TEST(GltfSparse, SparseValuesReplaceTheDenseOnesAndTheZerosOfAnAccessorWithoutBufferView)
{
    // Exact: the replaced positions are the float values themselves.
    Scene dense = import(one_triangle({{0, 0, 0}, {3, 0, 0}, {0, 2, 0}}));
    for (bool base_view : {true, false}) {
        Scene sparse = import(sparse_triangle(base_view, {1, 2}));
        ASSERT_EQ(sparse.triangles.size(), 1u) << "base view " << base_view;
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(sparse.triangles[0].v[k], dense.triangles[0].v[k])
                << "base view " << base_view << " vertex " << k;
    }
}

TEST(GltfSparse, IndicesOutOfRangeOrNotIncreasingAreErrors)
{
    EXPECT_THROW(import(sparse_triangle(true, {1, 3})), Error); // past the 3 elements
    EXPECT_THROW(import(sparse_triangle(true, {2, 1})), Error); // decreasing
    EXPECT_THROW(import(sparse_triangle(true, {1, 1})), Error); // repeated
    EXPECT_NO_THROW(import(sparse_triangle(true, {1, 2})));
}

} // namespace
} // namespace pathcl::test_gltf_primitives
