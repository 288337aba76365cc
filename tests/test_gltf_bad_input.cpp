// Broken glTF data (host only, no device): NaN and infinite positions, indices out of
// range, accessors, views and strides past their ends or wrapping around, missing
// materials, node cycles and unknown required extensions. Each is a pathcl::Error whose
// message names the source (and where it helps, the node, mesh and accessor).
#include <cstddef>
#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "support/expect_error.h"
#include "support/gltf_builder.h"
#include "support/gltf_fixtures.h"

namespace pathcl::test_gltf_bad_input {
namespace {

using test::GltfBuilder;
using test::kQuad;
using test::kTilted;
using test::kU16;
using test::one_triangle;

// Runs `f`, expecting pathcl::Error; returns its message ("" and a failure otherwise).
using test::contains;
using test::error_of;

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

void PrintTo(const PastEndCase& c, std::ostream* os)
{
    *os << c.name;
}

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
                    [](GltfBuilder& b, int pos, int) { b.model.accessors[static_cast<std::size_t>(pos)].count = 4; }},
        PastEndCase{
            "PositionByteOffsetTooLarge",
            [](GltfBuilder& b, int pos, int) { b.model.accessors[static_cast<std::size_t>(pos)].byteOffset = 4; }},
        PastEndCase{"ViewLongerThanBuffer",
                    [](GltfBuilder& b, int pos, int) {
                        // The view claims more than the buffer holds, and the accessor uses it.
                        auto& acc = b.model.accessors[static_cast<std::size_t>(pos)];
                        b.model.bufferViews[static_cast<std::size_t>(acc.bufferView)].byteLength = 8192;
                        acc.count = 600;
                    }},
        PastEndCase{"IndexCountTooLarge",
                    [](GltfBuilder& b, int, int ind) { b.model.accessors[static_cast<std::size_t>(ind)].count = 4; }},
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
    b.add_positions(kTilted);                                              // view 0: bytes 0..36
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

} // namespace
} // namespace pathcl::test_gltf_bad_input
