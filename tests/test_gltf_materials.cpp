// glTF materials (host only, no device): base colour, metallic and roughness factors,
// emission times KHR_materials_emissive_strength (float or integer), doubleSided, and the
// glTF default material for a primitive without one. Each test checks one property; the
// tolerance it allows is stated next to it.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "scene/scene.h"
#include "support/gltf_builder.h"
#include "support/gltf_fixtures.h"

namespace pathcl::test_gltf_materials {
namespace {

using test::d3;
using test::GltfBuilder;
using test::import;
using test::kQuad;
using test::kTilted;
using test::near_rel;
using test::one_triangle;
using test::str;
using test::tilted_triangle_with;

// One triangle with material `m` (edited by the caller); returns the triangle's material.
SceneMaterial material_of(const std::function<void(tinygltf::Material&)>& edit)
{
    Scene scene = import(tilted_triangle_with(edit));
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

// What a file uses and pathcl does not render is said, one line each: an extension it does
// not read (listed twice, said once). alphaMode MASK and KHR_materials_volume attenuation
// are read, so they are not warned about. A file without them loads silently.
TEST(GltfWarnings, EachIgnoredFeatureIsOneWarningLine)
{
    GltfBuilder b = one_triangle(kTilted);
    b.model.extensionsUsed = {"KHR_materials_iridescence", "KHR_materials_specular", "KHR_materials_iridescence"};
    b.model.materials[0].alphaMode = "MASK";
    tinygltf::Value::Object volume;
    volume["attenuationDistance"] = tinygltf::Value(2.0);
    b.model.materials[0].extensions["KHR_materials_volume"] = tinygltf::Value(volume);
    ::testing::internal::CaptureStderr();
    import(b);
    std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find("pathcl: warning: test.gltf: ignores the extension KHR_materials_iridescence"),
              std::string::npos)
        << err;
    EXPECT_EQ(err.find("KHR_materials_specular"), std::string::npos) << err;
    EXPECT_EQ(err.find("alphaMode"), std::string::npos) << err;
    EXPECT_EQ(err.find("KHR_materials_volume"), std::string::npos) << err;

    ::testing::internal::CaptureStderr();
    import(one_triangle(kTilted));
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

} // namespace
} // namespace pathcl::test_gltf_materials
