// Renders with each triangle sampling (--triangle-sampling): a panel light a few
// centimetres from a wall and above a floor, where solid-angle sampling is taken near
// the panel and area sampling farther off, renders the image area sampling renders; and
// the comparison fails when the pdf that MIS gives a BSDF ray's hit on the panel is off
// (a light sample's pdf at the vertex the ray left must be the one its sampling had).
#include <iostream>

#include <gtest/gtest.h>

#include "image/image_compare.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/test_options.h"

namespace pathcl::test_render_triangle_sampling {
namespace {

// A floor and a back wall; a panel facing down 4 cm above the floor and 3 cm from the
// wall, seen from the front.
Scene panel_beside_a_wall()
{
    test::GltfBuilder b;
    const int grey = b.add_material(glm::vec3(0.7f));
    b.add_root(b.add_node(b.add_quad_mesh({{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}, grey)));   // floor
    b.add_root(b.add_node(b.add_quad_mesh({{-1, 0, -1}, {1, 0, -1}, {1, 2, -1}, {-1, 2, -1}}, grey))); // wall
    const int panel = b.add_material(glm::vec3(0.0f), glm::vec3(5.0f, 4.5f, 4.0f));
    b.add_root(b.add_node(b.add_quad_mesh(
        {{-0.5f, 0.04f, -0.97f}, {0.5f, 0.04f, -0.97f}, {0.5f, 0.04f, -0.47f}, {-0.5f, 0.04f, -0.47f}}, panel)));
    b.add_camera_node(b.add_perspective_camera(0.9), {0.0, 0.5, 1.2}, {-0.1305262, 0.0, 0.0, 0.9914449});
    return import_gltf(b.model, "panel-beside-a-wall");
}

RenderOptions panel_options(TriangleSampling sampling)
{
    RenderOptions o = test::independent_options();
    o.width = o.height = 48;
    o.spp = 256;
    o.max_bounces = 1; // direct light, where triangle sampling acts (deeper bounces add only noise)
    o.seed = 11;
    o.triangle_sampling = sampling;
    return o;
}

CompareReport solid_angle_against_area(const RenderOptions& solid_angle)
{
    static const Scene scene = panel_beside_a_wall();
    static const RenderResult area = [] { // area sampling's tail is long near the panel: more samples
        RenderOptions o = panel_options(TriangleSampling::Area);
        o.spp = 1024;
        return render(scene, o);
    }();
    RenderResult r = render(scene, solid_angle);
    EXPECT_EQ(r.stats.bad_samples, 0u);
    CompareOptions co;
    co.pooled_variance = false; // two estimators
    return compare_images(r.image, area.image, co);
}

TEST(TriangleSampling, PanelBesideAWallRendersTheAreaSamplersImage)
{
    for (Strategy strategy : {Strategy::Nee, Strategy::OneSample, Strategy::Mis}) {
        RenderOptions o = panel_options(TriangleSampling::SolidAngle);
        o.strategy = strategy;
        o.seed = 13;
        CompareReport cmp = solid_angle_against_area(o);
        std::cout << "strategy " << strategy_name(strategy) << "\n" << cmp.summary();
        EXPECT_TRUE(cmp.passed) << "strategy " << strategy_name(strategy) << "\n" << cmp.summary();
    }
}

TEST(TriangleSampling, SolidAnglePdfOffAtTheHitsFailsTheComparison)
{
    // The solid-angle pdf 0 where only MIS at a BSDF ray's hit on the panel reads it:
    // those hits take full weight beside the light samples, and the light near the panel
    // counts about twice.
    RenderOptions o = panel_options(TriangleSampling::SolidAngle);
    o.seed = 13;
    o.kernel_patches = {{"light/triangle.cl", "        return cos_light > 0.0f ? pmf / omega : 0.0f;",
                         "        return cos_light > 0.0f ? 0.0f : 0.0f;"}};
    CompareReport cmp = solid_angle_against_area(o);
    std::cout << cmp.summary();
    EXPECT_FALSE(cmp.passed) << cmp.summary();
}

} // namespace
} // namespace pathcl::test_render_triangle_sampling
