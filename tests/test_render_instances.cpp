// The two-level BVH on the device: meshes stored once and drawn by instances render as
// their copies do (the one-level BVH of --copy-instances), textures, normal maps and
// mirroring maps included; and a large instanced scene's device arrays stay the size of
// its mesh, not of its copies.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compile/compile_scene.h"
#include "compile/kernel_features.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/render_checks.h"
#include "support/test_options.h"
#include "support/tool_run.h"

namespace pathcl::test_render_instances {
namespace {

const std::string kSource = PATHCL_SOURCE_DIR;

SceneChoice copies()
{
    SceneChoice c;
    c.copy_instances = true;
    return c;
}

RenderOptions small_options(std::uint32_t spp)
{
    RenderOptions o = test::independent_options();
    o.width = 64;
    o.height = 64;
    o.spp = spp;
    o.max_bounces = 8;
    o.seed = 11;
    return o;
}

// The instanced and the copied scene, rendered with different seeds, agree statistically.
void expect_same_render(const Scene& instanced, const Scene& copied, const RenderOptions& o)
{
    RenderResult ra = Renderer(instanced, o).render(1), rb = Renderer(copied, o).render(2);
    EXPECT_EQ(ra.stats.bad_samples, 0u);
    EXPECT_EQ(rb.stats.bad_samples, 0u);
    test::expect_same_mean(ra.image, rb.image);
}

TEST(RenderInstances, InstancedCornellBoxRendersAsItsCopies)
{
    // scenes/cornell-box-instanced.gltf: a block drawn by two nodes (the second mirrored,
    // stretched and turned) and six beads of one smooth sphere drawn by
    // EXT_mesh_gpu_instancing (non-uniform scales); against the same file copied. Broken
    // variants seen to fail: the mirrored instance's front not flipped; normals mapped by
    // to_render instead of its inverse transpose.
    const std::string path = kSource + "/scenes/cornell-box-instanced.gltf";
    Scene instanced = load_gltf(path), copied = load_gltf(path, copies());
    ASSERT_EQ(instanced.meshes.size(), 2u);
    ASSERT_EQ(instanced.instances.size(), 8u);
    ASSERT_TRUE(copied.instances.empty());
    EXPECT_EQ(instanced.drawn_triangles(), copied.triangles.size());
    RenderOptions o = small_options(256);
    ASSERT_TRUE(kernel_features(instanced, o).has(FEATURE_INSTANCES));
    ASSERT_FALSE(kernel_features(copied, o).has(FEATURE_INSTANCES));
    expect_same_render(instanced, copied, o);
}

class InstancedTextures : public test::ToolRun {};

TEST_F(InstancedTextures, NormalMappedMirroredDrawingsRenderAsTheirCopies)
{
    // scenes/textured.gltf with its normal-mapped, textured box drawn twice more: large,
    // turned and mirrored in front (a negative scale: the tangent frame's handedness
    // flips), and small.
    // Broken variants seen to fail: tangents not mapped to render space; the mirrored
    // instance's handedness kept.
    std::ifstream in(kSource + "/scenes/textured.gltf");
    nlohmann::json doc = nlohmann::json::parse(in);
    const double turn[4] = {0.0, 0.3826834, 0.0, 0.9238795}; // 45 degrees about +y
    doc["nodes"].push_back({{"name", "box_mirrored"},
                            {"mesh", 3},
                            {"translation", {-0.2, 0.55, 1.6}},
                            {"rotation", turn},
                            {"scale", {-1.5, 1.5, 1.5}}});
    doc["nodes"].push_back(
        {{"name", "box_small"}, {"mesh", 3}, {"translation", {0.2, 0.12, 1.1}}, {"scale", {0.4, 0.4, 0.4}}});
    const int n = static_cast<int>(doc["nodes"].size());
    doc["scenes"][0]["nodes"].push_back(n - 2);
    doc["scenes"][0]["nodes"].push_back(n - 1);
    std::filesystem::copy(kSource + "/scenes/textures", dir_ / "textures");
    const std::string path = (dir_ / "textured-instanced.gltf").string();
    std::ofstream(path) << doc.dump();

    Scene instanced = load_gltf(path), copied = load_gltf(path, copies());
    ASSERT_EQ(instanced.meshes.size(), 1u);
    ASSERT_EQ(instanced.instances.size(), 3u);
    RenderOptions o = small_options(256);
    ASSERT_TRUE(kernel_features(instanced, o).has(FEATURE_NORMAL_MAPS));
    expect_same_render(instanced, copied, o);
}

TEST(RenderInstances, TenThousandDrawingsOfAMeshCostItsTrianglesOnce)
{
    // The scale of tools/make_instance_field.py: 10,000 instances of a 10,000-triangle mesh (10^8 triangles
    // drawn). The device arrays hold the mesh once and one Instance record (112 bytes)
    // and a top-level share per drawing: under 20 MB, where the copies would need 10^8 x
    // (48 + 64) bytes of triangles alone (11 GB). Its triangles are a 50 x 100 grid of
    // quads; drawings on a 100 x 100 grid, each turned.
    test::GltfBuilder b;
    std::vector<glm::vec3> positions;
    for (int i = 0; i < 50; ++i)
        for (int j = 0; j < 100; ++j) {
            glm::vec3 p(0.01f * static_cast<float>(j), 0.02f * static_cast<float>(i), 0.0f);
            glm::vec3 dx(0.01f, 0.0f, 0.0f), dy(0.0f, 0.02f, 0.0f);
            for (glm::vec3 v : {p, p + dx, p + dx + dy, p, p + dx + dy, p + dy})
                positions.push_back(v + glm::vec3(0.0f, 0.0f, 0.001f * static_cast<float>((i + j) % 7)));
        }
    int mesh = b.add_mesh(b.add_positions(positions), -1, b.add_material(glm::vec3(0.5f)));
    for (int k = 0; k < 10000; ++k)
        b.add_root(b.add_node(mesh, {}, {1.5 * (k % 100), 0.0, 1.5 * (k / 100)},
                              {0.0, std::sin(0.001 * k), 0.0, std::cos(0.001 * k)}));
    Scene scene = import_gltf(b.model, "field.gltf");
    ASSERT_EQ(scene.triangles.size(), 10000u);
    ASSERT_EQ(scene.instances.size(), 10000u);
    EXPECT_EQ(scene.drawn_triangles(), 100000000u);
    CompiledScene cs = compile_scene(scene, kernel_features(scene, RenderOptions{}));
    std::size_t bytes = 0;
#define PATHCL_COUNT_BYTES(type, name) bytes += cs.arrays.name.size() * sizeof(type);
    PATHCL_SCENE_ARRAYS(PATHCL_COUNT_BYTES)
#undef PATHCL_COUNT_BYTES
    std::cout << "device arrays: " << bytes << " bytes\n";
    EXPECT_EQ(cs.arrays.instances.size(), 10000u);
    EXPECT_EQ(cs.arrays.triangles.size(), 10000u);
    EXPECT_LT(bytes, 20u << 20);
}

} // namespace
} // namespace pathcl::test_render_instances
