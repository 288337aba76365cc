// The scene fingerprint that keys cached results (converge's reference): equal for equal
// scenes, different when anything a render reads changes.
#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "scene/scene_fingerprint.h"
#include "support/gltf_builder.h"

namespace pathcl {
namespace {

Scene sphere_scene()
{
    test::GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f), glm::vec3(0.5f));
    b.add_root(b.add_node(b.add_sphere_mesh(1.0, 6, 12, mat, /*inward=*/true)));
    return import_gltf(b.model, "sphere");
}

TEST(SceneFingerprint, EqualScenesAgreeAndEveryChangeShows)
{
    const Scene base = sphere_scene();
    const std::uint64_t f = scene_fingerprint(base);
    EXPECT_EQ(scene_fingerprint(sphere_scene()), f);
    EXPECT_EQ(scene_fingerprint_hex(base).size(), 16u);

    Scene s = base;
    s.materials[0].roughness += 0.25f;
    EXPECT_NE(scene_fingerprint(s), f) << "material";
    s = base;
    s.triangles[3].v[1].x = std::nextafter(s.triangles[3].v[1].x, 2.0f);
    EXPECT_NE(scene_fingerprint(s), f) << "one ulp of one vertex";
    s = base;
    s.environment.present = true;
    s.environment.constant = glm::vec3(1.0f);
    EXPECT_NE(scene_fingerprint(s), f) << "environment";
    s = base;
    s.camera.yfov *= 1.01;
    EXPECT_NE(scene_fingerprint(s), f) << "camera";
    s = base;
    s.materials[0].clearcoat = 0.5f;
    const std::uint64_t coated = scene_fingerprint(s);
    EXPECT_NE(coated, f) << "clear coat";
    s.materials[0].clearcoat_roughness = 0.25f;
    EXPECT_NE(scene_fingerprint(s), coated) << "clear coat roughness";
    s.materials[0].textures[TEXTURE_SLOT_CLEARCOAT_NORMAL].image = 0;
    const std::uint64_t coat_mapped = scene_fingerprint(s);
    EXPECT_NE(coat_mapped, coated) << "clear coat normal texture";
    s.materials[0].clearcoat_normal_scale = 0.5f;
    EXPECT_NE(scene_fingerprint(s), coat_mapped) << "clear coat normal scale";
    s = base;
    s.materials[0].sheen_roughness = 0.5f; // no sheen colour: no sheen, nothing changes
    EXPECT_EQ(scene_fingerprint(s), f) << "roughness of no sheen";
    s.materials[0].sheen_color = glm::vec3(0.0f, 0.5f, 0.0f);
    const std::uint64_t sheen = scene_fingerprint(s);
    EXPECT_NE(sheen, f) << "sheen colour";
    s.materials[0].sheen_roughness = 0.25f;
    const std::uint64_t rougher = scene_fingerprint(s);
    EXPECT_NE(rougher, sheen) << "sheen roughness";
    s.materials[0].textures[TEXTURE_SLOT_SHEEN_ROUGHNESS].image = 0;
    EXPECT_NE(scene_fingerprint(s), rougher) << "sheen roughness texture";
    s = base;
    s.materials[0].anisotropy_rotation = 1.0f; // no strength: isotropic, nothing changes
    EXPECT_EQ(scene_fingerprint(s), f) << "rotation of no anisotropy";
    s.materials[0].anisotropy = 0.5f;
    const std::uint64_t brushed = scene_fingerprint(s);
    EXPECT_NE(brushed, f) << "anisotropy strength";
    s.materials[0].anisotropy_rotation = 1.5f;
    const std::uint64_t turned = scene_fingerprint(s);
    EXPECT_NE(turned, brushed) << "anisotropy rotation";
    s.materials[0].textures[TEXTURE_SLOT_ANISOTROPY].image = 0;
    EXPECT_NE(scene_fingerprint(s), turned) << "anisotropy texture";
    s = base;
    s.materials[0].name = "renamed"; // names do not change a render
    EXPECT_EQ(scene_fingerprint(s), f);
}

} // namespace
} // namespace pathcl
