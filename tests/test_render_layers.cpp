// The layers over the base material end to end: KHR_materials_clearcoat,
// KHR_materials_sheen and KHR_materials_anisotropy on two spheres on a floor under an area
// light render the same by BSDF sampling alone, by light sampling and by MIS, so each
// layer's eval, pdf and sampling agree inside the integrator. The BSDF itself is tested against the reference
// model in test_bsdf_eval/_sampling/_energy.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compile/kernel_features.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/render_checks.h"
#include "support/test_options.h"
#include <tiny_gltf.h>

namespace pathcl::test_render_layers {
namespace {

// A floor, an area light above it, a camera, and two spheres of materials `left` and
// `right` (indices into b's materials, which the caller has added), with tangents along
// their parallels.
Scene two_spheres(test::GltfBuilder& b, int left, int right, std::uint32_t feature, const std::string& name)
{
    auto sphere = [&](int material) {
        const int stacks = 24, slices = 48; // add_sphere_mesh's vertices: stack by stack, slice by slice
        int mesh = b.add_sphere_mesh(0.45, stacks, slices, material, false, true);
        std::vector<glm::vec4> tangents;
        for (int i = 0; i <= stacks; ++i)
            for (int j = 0; j < slices; ++j) {
                double phi = 2.0 * std::numbers::pi * j / slices;
                tangents.emplace_back(-std::sin(phi), 0.0, std::cos(phi), 1.0);
            }
        b.set_attribute(mesh, "TANGENT", b.add_tangents(tangents));
        return mesh;
    };
    int floor_mat = b.add_material(glm::vec3(0.7f));
    b.add_root(b.add_node(b.add_quad_mesh({{-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}}, floor_mat)));
    int light_mat = b.add_material(glm::vec3(0.0f), glm::vec3(1.0f), false, 4.0);
    b.add_root(b.add_node(b.add_quad_mesh({{-1, 2.5, 1}, {-1, 2.5, -1}, {1, 2.5, -1}, {1, 2.5, 1}}, light_mat)));
    b.add_root(b.add_node(sphere(left), {}, {-0.5, 0.45, 0.0}));
    b.add_root(b.add_node(sphere(right), {}, {0.5, 0.45, 0.0}));
    b.add_camera_node(b.add_perspective_camera(0.8), {0.0, 0.6, 2.5});
    Scene scene = import_gltf(b.model, name);
    EXPECT_TRUE(kernel_features(scene, RenderOptions{}).has(feature));
    return scene;
}

// BSDF sampling at 2048 spp against MIS and light sampling at 512, 32 x 32, six bounces.
void expect_strategies_agree(const Scene& scene)
{
    RenderOptions o = test::independent_options();
    o.width = o.height = 32;
    o.spp = 2048;
    o.seed = 3;
    o.max_bounces = 6;
    test::expect_same_image_by_strategies(scene, o, {Strategy::Mis, Strategy::Nee}, 512, 1);
}

TEST(RenderClearcoat, CoatedSpheresRenderTheSameByBsdfSamplingAndMis)
{
    // A rough coat over a rough plastic, a smooth coat over a rough metal. Broken variant
    // seen to fail: the coat's pdf left out of bsdf_eval (BSDF sampling then overweights
    // the coat: image mean 0.33 against 0.22 by light sampling).
    test::GltfBuilder b;
    test::GltfBuilder::Pbr plastic;
    plastic.base_color = {0.8f, 0.15f, 0.1f};
    plastic.roughness = 0.6;
    int coated_plastic = b.add_pbr_material(plastic);
    test::set_clearcoat(b.material(coated_plastic), 1.0, 0.25);
    test::GltfBuilder::Pbr gold;
    gold.base_color = {0.95f, 0.7f, 0.3f};
    gold.metallic = 1.0;
    gold.roughness = 0.5;
    int lacquered_gold = b.add_pbr_material(gold);
    test::set_clearcoat(b.material(lacquered_gold), 0.8, 0.0);
    expect_strategies_agree(two_spheres(b, coated_plastic, lacquered_gold, FEATURE_CLEARCOAT, "coated-spheres.gltf"));
}

TEST(RenderSheen, SheenSpheresRenderTheSameByBsdfSamplingAndMis)
{
    // Velvet (a white sheen over a dark red Lambertian), and a smooth blue sheen over a
    // rough gold under a part coat. Broken variant seen to fail: the sheen's pdf left out
    // of bsdf_eval.
    test::GltfBuilder b;
    int velvet = b.add_material(glm::vec3(0.3f, 0.03f, 0.05f));
    test::set_sheen(b.material(velvet), {1.0, 1.0, 1.0}, 0.35);
    test::GltfBuilder::Pbr gold;
    gold.base_color = {0.95f, 0.7f, 0.3f};
    gold.metallic = 1.0;
    gold.roughness = 0.5;
    int sheen_gold = b.add_pbr_material(gold);
    test::set_sheen(b.material(sheen_gold), {0.3, 0.5, 1.0}, 0.1);
    test::set_clearcoat(b.material(sheen_gold), 0.5, 0.3);
    expect_strategies_agree(two_spheres(b, velvet, sheen_gold, FEATURE_SHEEN, "sheen-spheres.gltf"));
}

TEST(RenderAnisotropy, BrushedSpheresRenderTheSameByBsdfSamplingAndMis)
{
    // Brushed gold along the parallels (strength 0.8), and a part metal over a plastic
    // brushed along the meridians (rotation pi / 2; the plastic's dielectric layer
    // anisotropic too) under a rough coat. Broken variant seen to fail: the conductor's
    // visible-normal density with the isotropic alpha in bsdf_eval.
    test::GltfBuilder b;
    test::GltfBuilder::Pbr gold;
    gold.base_color = {0.95f, 0.7f, 0.3f};
    gold.metallic = 1.0;
    gold.roughness = 0.3;
    int brushed = b.add_pbr_material(gold);
    test::set_anisotropy(b.material(brushed), 0.8);
    test::GltfBuilder::Pbr half;
    half.base_color = {0.3f, 0.5f, 0.8f};
    half.metallic = 0.5;
    half.roughness = 0.4;
    int turned = b.add_pbr_material(half);
    test::set_anisotropy(b.material(turned), 0.9, std::numbers::pi / 2.0);
    test::set_clearcoat(b.material(turned), 0.7, 0.3);
    expect_strategies_agree(two_spheres(b, brushed, turned, FEATURE_ANISOTROPY, "brushed-spheres.gltf"));
}

} // namespace
} // namespace pathcl::test_render_layers
