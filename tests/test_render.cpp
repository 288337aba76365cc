// End-to-end renders on the device: the Cornell box against its committed high-spp
// reference (statistical, and shown to fail on a deliberately broken BSDF), the analytic
// furnace sphere for several bounce limits, and reproducibility.
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "image/image_compare.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/test_options.h"
#include "types.h"
#include <tiny_gltf.h>

namespace pathcl::test_render {
namespace {

const std::string kSource = PATHCL_SOURCE_DIR;

// Settings of tests/references/cornell-box-64.exr (tools/make_references.sh).
RenderOptions cornell_test_options()
{
    RenderOptions o = test::independent_options();
    o.width = 64;
    o.height = 64;
    o.spp = 64;
    o.max_bounces = 8;
    o.seed = 7; // any seed but the reference's
    return o;
}

const Scene& cornell_box()
{
    static Scene s = load_gltf(kSource + "/scenes/cornell-box.gltf");
    return s;
}

TEST(Render, CornellBoxMatchesCommittedReference)
{
    RenderResult r = render(cornell_box(), cornell_test_options());
    EXPECT_EQ(r.stats.bad_samples, 0u);
    Image ref = read_image(kSource + "/tests/references/cornell-box-64.exr");
    CompareReport cmp = compare_images(r.image, ref);
    std::cout << cmp.summary();
    EXPECT_TRUE(cmp.passed) << cmp.summary();
}

TEST(Render, BrokenBsdfFailsTheCornellBoxComparison)
{
    // The same comparison with a Lambertian that forgets cos(theta) in its evaluation:
    // proves the test above can fail on a plausible kernel bug.
    RenderOptions o = cornell_test_options();
    o.kernel_patches = {
        {"closure/bsdf_eval.cl", "e.f_cos = p->base_color * (INV_PI * cos_i);", "e.f_cos = p->base_color * INV_PI;"}};
    RenderResult r = render(cornell_box(), o);
    Image ref = read_image(kSource + "/tests/references/cornell-box-64.exr");
    CompareReport cmp = compare_images(r.image, ref);
    std::cout << cmp.summary();
    EXPECT_FALSE(cmp.passed) << cmp.summary();
}

// Inside a closed sphere of albedo a whose inner surface emits Le everywhere, radiance
// is the same in every direction: L = Le (1 + a + ... + a^B) for B bounces, Le / (1 - a)
// in the limit (1 for a = Le = 0.5). Exact for any closed shape, so the tessellation
// does not matter; it checks emission, NEE, MIS weights and Russian roulette together.
Scene furnace_sphere()
{
    test::GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f), glm::vec3(0.5f));
    int mesh = b.add_sphere_mesh(1.0, 12, 24, mat, /*inward=*/true);
    b.add_root(b.add_node(mesh));
    int cam = b.add_perspective_camera(1.2);
    int cam_node = b.add_node(-1, {}, {0.1, -0.05, 0.2});
    b.model.nodes[static_cast<std::size_t>(cam_node)].camera = cam;
    b.add_root(cam_node);
    return import_gltf(b.model, "furnace-sphere");
}

struct ImageMean {
    double mean[3];
    double stderr_[3];
};

ImageMean image_mean(const Image& img)
{
    ImageMean m{};
    std::size_t n = static_cast<std::size_t>(img.width) * img.height;
    for (int c = 0; c < 3; ++c) {
        double s = 0.0, v = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            s += img.rgb[i * 3 + c];
            v += img.variance[i * 3 + c] / static_cast<double>(img.spp);
        }
        m.mean[c] = s / static_cast<double>(n);
        m.stderr_[c] = std::sqrt(v) / static_cast<double>(n);
    }
    return m;
}

TEST(Render, FurnaceSphereMatchesAnalyticRadianceForEveryStrategy)
{
    Scene scene = furnace_sphere();
    for (Strategy strategy : {Strategy::Bsdf, Strategy::Nee, Strategy::OneSample, Strategy::Mis})
        for (std::uint32_t bounces : {0u, 1u, 2u, 1000u}) {
            SCOPED_TRACE("strategy " + std::string(strategy_name(strategy)) + " bounces " + std::to_string(bounces));
            RenderOptions o = test::independent_options();
            o.strategy = strategy;
            o.width = 32;
            o.height = 32;
            o.spp = 64;
            o.max_bounces = bounces;
            o.seed = 3;
            RenderResult r = render(scene, o);
            EXPECT_EQ(r.stats.bad_samples, 0u);
            double expected = 0.5 * (1.0 - std::pow(0.5, bounces + 1.0)) / 0.5; // Le * sum a^k
            ImageMean m = image_mean(r.image);
            for (int c = 0; c < 3; ++c) {
                if (bounces == 0) { // emission only: no randomness at all
                    EXPECT_NEAR(m.mean[c], 0.5, 1e-6);
                    EXPECT_LT(m.stderr_[c], 1e-6);
                    continue;
                }
                // Tolerance from the measured variance; the test must also be sharp enough
                // to see a 1% error.
                EXPECT_LT(m.stderr_[c], 0.002) << "bounces " << bounces;
                EXPECT_NEAR(m.mean[c], expected, 5.0 * m.stderr_[c]) << "bounces " << bounces << " channel " << c;
            }
        }
}

// The Cornell box file with every root node placed under a new root with this TRS.
Scene transformed_cornell_box(const std::vector<double>& translation, double scale)
{
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warning;
    EXPECT_TRUE(loader.LoadASCIIFromFile(&model, &err, &warning, kSource + "/scenes/cornell-box.gltf")) << err;
    tinygltf::Node root;
    root.translation = translation;
    root.scale = {scale, scale, scale};
    root.children = model.scenes[0].nodes;
    model.nodes.push_back(root);
    model.scenes[0].nodes = {static_cast<int>(model.nodes.size()) - 1};
    return import_gltf(model, "transformed cornell-box.gltf");
}

TEST(Render, CornellBoxIsInvariantUnderTranslationAndScale)
{
    // Far from the origin, float positions would move the geometry by millimetres;
    // render space (relative to the camera, composed in double) keeps it exact. Scale
    // changes no radiance. Naive variant that fails: world-space float positions (the
    // 1e5 translation), or a fixed ray epsilon (the 1e-3 and 1e3 scales).
    Image ref = read_image(kSource + "/tests/references/cornell-box-64.exr");
    const std::vector<std::pair<std::vector<double>, double>> cases = {
        {{1e5, 1e5, 1e5}, 1.0}, {{0.0, 0.0, 0.0}, 1e-3}, {{0.0, 0.0, 0.0}, 1e3}, {{-3e4, 2e5, 7e4}, 1e3}};
    for (const auto& [translation, scale] : cases) {
        RenderResult r = render(transformed_cornell_box(translation, scale), cornell_test_options());
        EXPECT_EQ(r.stats.bad_samples, 0u);
        CompareReport cmp = compare_images(r.image, ref);
        EXPECT_TRUE(cmp.passed) << "translation " << translation[0] << "," << translation[1] << "," << translation[2]
                                << " scale " << scale << "\n"
                                << cmp.summary();
    }
}

TEST(Render, WhiteFurnaceOfAlbedoOneGainsExactlyLePerBounce)
{
    // A closed sphere of white Lambertian (albedo 1) emitting Le = 0.25 inside: every
    // bounce adds exactly Le, so L = Le (B + 1). Russian roulette never fires (the
    // throughput stays 1) and nothing may be lost or gained. Naive variant that fails: a
    // BSDF sample weight 1% too high (energy gain; verified). Roulette that does not
    // divide by its survival probability is caught by the albedo-0.5 furnace above.
    test::GltfBuilder b;
    int mat = b.add_material(glm::vec3(1.0f), glm::vec3(0.25f));
    b.add_root(b.add_node(b.add_sphere_mesh(1.0, 12, 24, mat, /*inward=*/true)));
    b.add_camera_node(b.add_perspective_camera(1.0), {0.2, 0.1, -0.3});
    Scene scene = import_gltf(b.model, "white-furnace");
    for (std::uint32_t bounces : {3u, 6u}) {
        RenderOptions o = test::independent_options();
        o.width = o.height = 16;
        o.spp = 32;
        o.max_bounces = bounces;
        RenderResult r = render(scene, o);
        EXPECT_EQ(r.stats.bad_samples, 0u);
        ImageMean m = image_mean(r.image);
        for (int c = 0; c < 3; ++c) {
            EXPECT_LT(m.stderr_[c], 0.01) << "bounces " << bounces;
            EXPECT_NEAR(m.mean[c], 0.25 * (bounces + 1), 1e-5 + 5.0 * m.stderr_[c]) << "bounces " << bounces;
        }
    }
}

TEST(Render, EveryStrategyConvergesToTheCornellBoxReference)
{
    // Different estimators share the mean, not the variance: separate (Welch) variances.
    // BSDF-only sampling finds the small light so rarely that single pixels are far from
    // normal at this spp, so for it only the tile and image scales are judged.
    Image ref = read_image(kSource + "/tests/references/cornell-box-64.exr");
    for (Strategy strategy : {Strategy::Bsdf, Strategy::Nee, Strategy::OneSample, Strategy::Mis}) {
        RenderOptions o = cornell_test_options();
        o.spp = 256;
        o.strategy = strategy;
        RenderResult r = render(cornell_box(), o);
        EXPECT_EQ(r.stats.bad_samples, 0u);
        CompareOptions co;
        co.pooled_variance = false;
        co.judge_pixels = strategy != Strategy::Bsdf;
        CompareReport cmp = compare_images(r.image, ref, co);
        std::cout << "strategy " << strategy_name(strategy) << "\n" << cmp.summary();
        EXPECT_TRUE(cmp.passed) << "strategy " << strategy_name(strategy) << "\n" << cmp.summary();
    }
}

// scenes/NAME.gltf rendered at spp (the reference's size and options) against
// tests/references/NAME-64.exr, with no NaN/Inf sample.
void expect_scene_matches_its_reference(const std::string& name, std::uint32_t spp)
{
    Scene scene = load_gltf(kSource + "/scenes/" + name + ".gltf");
    RenderOptions o = cornell_test_options();
    o.spp = spp;
    RenderResult r = render(scene, o);
    EXPECT_EQ(r.stats.bad_samples, 0u) << name;
    Image ref = read_image(kSource + "/tests/references/" + name + "-64.exr");
    CompareReport cmp = compare_images(r.image, ref);
    std::cout << name << "\n" << cmp.summary();
    EXPECT_TRUE(cmp.passed) << name << "\n" << cmp.summary();
}

TEST(Render, EachLightTypeSceneMatchesItsCommittedReference)
{
    // One scene per light type besides the area light (tools/make_scenes.sh), against its
    // 8192-spp reference (tools/make_references.sh); zero NaN/Inf samples. 256 spp, not
    // 64: under the spot lights the walls see only light bounced off a small lit patch,
    // and at 64 spp those pixel means are too skewed for a z-test (seeds 1-4 and 7 failed
    // 0.2-0.4 % of pixels and, for seed 7, 3 of 192 tiles; at 256 spp 0.07-0.12 % and none).
    for (const char* name : {"cornell-box-point", "cornell-box-sphere", "cornell-box-spot", "cornell-box-rect-spot",
                             "cornell-box-directional", "sky-spheres"}) {
        expect_scene_matches_its_reference(name, 256);
    }
}

TEST(Render, MaterialScenesMatchTheirCommittedReferences)
{
    // The glTF material model end to end (tools/make_scenes.sh): an ideal glass sphere
    // and an ideal mirror block in the Cornell box (caustics, total internal reflection;
    // checked against Mitsuba 3 separately, docs/testing.md), and spheres over metallic x
    // roughness under an environment map, each against its 8192-spp reference. 256 spp:
    // caustics reached only by BSDF sampling make single pixels heavy-tailed.
    for (const char* name : {"cornell-box-glass-mirror", "material-spheres"}) {
        expect_scene_matches_its_reference(name, 256);
    }
    // The glTF extensions in one scene: a tinted glass sphere (absorption), a
    // clear-coated block and an alpha-cut leaf card in the box. 1024 spp: at 256 its
    // coloured caustic failed 48-84 pixels of 12288 (limit 122) and up to one 8x8 tile
    // of 192 over seeds 1-5; at 1024, 0-2 pixels and at most one tile.
    expect_scene_matches_its_reference("cornell-box-features", 1024);
    // Meshes stored once and drawn by instances (a two-level BVH), against the reference
    // drawn by copies (tools/make_references.sh: --copy-instances).
    expect_scene_matches_its_reference("cornell-box-instanced", 256);
}

TEST(Render, SameSeedGivesIdenticalImageOtherSeedDoesNot)
{
    RenderOptions o = test::independent_options();
    o.width = 24;
    o.height = 24;
    o.spp = 4;
    o.seed = 99;
    Image a = render(cornell_box(), o).image;
    Image b = render(cornell_box(), o).image;
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(a.variance, b.variance);
    o.seed = 100;
    Image c = render(cornell_box(), o).image;
    EXPECT_NE(a.rgb, c.rgb);
}

TEST(Render, SceneWithoutLightsIsBlack)
{
    test::GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.8f));
    b.add_root(b.add_node(b.add_sphere_mesh(1.0, 8, 16, mat, false)));
    Scene scene = import_gltf(b.model, "no-lights");
    RenderOptions o = test::independent_options();
    o.width = 16;
    o.height = 16;
    o.spp = 2;
    RenderResult r = render(scene, o);
    EXPECT_EQ(r.stats.lights, 0u);
    for (float v : r.image.rgb)
        ASSERT_EQ(v, 0.0f);
}

} // namespace
} // namespace pathcl::test_render
