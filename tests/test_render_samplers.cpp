// Whole renders with each sampler, and the sampler and camera tools end to end through
// the `pathcl` binary: every sampler renders the Cornell box to its reference image;
// `pathcl samples` writes a readable plot; `--ray-log` writes the camera rays, which for
// a thin lens start on the lens disk and meet again on the plane of focus.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "image/image_compare.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "sampling/samplers.h"
#include "scene/gltf_loader.h"
#include "support/test_options.h"
#include "support/tool_run.h"
#include "types.h"

namespace pathcl::test_render_samplers {
namespace {

namespace fs = std::filesystem;
const std::string kSource = PATHCL_SOURCE_DIR;

TEST(SamplerRender, EverySamplerRendersTheCornellBoxReference)
{
    // 64x64, 64 spp (a square and a power of two: no sampler rounds), against the
    // 8192-spp reference made with the independent sampler. Every sampler hands each
    // decision a value that is, on its own, uniform, so one path sample has the same
    // distribution (and per-sample variance) as with the independent sampler: pooling
    // the per-sample variance with the reference's is valid. Only the variance of the
    // mean differs: stratified and quasi-Monte Carlo means vary less than variance/spp,
    // so for them the test is conservative (it cannot fail a correct sampler more often
    // than the stated rate; it needs a larger bias to fail a wrong one). Pooled rather
    // than separate (Welch) variances: with its own 64-spp variance the independent
    // render fails 0.76 % of its pixels against the 1 % limit (heavy tails), pooled
    // 0.05 %. Broken variant seen to fail: a scramble and permutation seed without the
    // dimension (every decision of a sample drawing the same point: correlated light
    // pick, light point and BSDF direction), for every stratified sampler. Each sampler
    // renders twice: stratified in every bounce, and (the default) in the first only.
    Scene scene = load_gltf(kSource + "/scenes/cornell-box.gltf");
    Image ref = read_image(kSource + "/tests/references/cornell-box-64.exr");
    for (const auto& [sampler_label, sampler] : sampler_names())
        for (std::uint32_t stratified_bounces : {8u, 1u}) {
            RenderOptions o = test::independent_options();
            o.width = o.height = 64;
            o.spp = 64;
            o.max_bounces = 8;
            o.seed = 7;
            o.sampler = sampler;
            o.stratified_bounces = stratified_bounces;
            RenderResult r = render(scene, o);
            EXPECT_EQ(r.stats.bad_samples, 0u);
            EXPECT_EQ(r.image.spp, 64u);
            CompareReport cmp = compare_images(r.image, ref);
            std::cout << sampler_name(sampler) << ", stratified bounces " << stratified_bounces << "\n"
                      << cmp.summary();
            EXPECT_TRUE(cmp.passed) << sampler_name(sampler) << ", stratified bounces " << stratified_bounces << "\n"
                                    << cmp.summary();
        }
}

TEST(SamplerRender, RoundedSppIsWhatTheImageRecords)
{
    // Jittered rounds 5 spp up to 9 (3 x 3 strata), Hammersley to 8; the image and the
    // statistics say so.
    Scene scene = load_gltf(kSource + "/scenes/cornell-box.gltf");
    RenderOptions o = test::independent_options();
    o.width = o.height = 8;
    o.spp = 5;
    o.sampler = SamplerType::Jittered;
    RenderResult r = render(scene, o);
    EXPECT_EQ(r.image.spp, 9u);
    EXPECT_EQ(r.stats.spp, 9u);
    o.sampler = SamplerType::Hammersley;
    EXPECT_EQ(render(scene, o).image.spp, 8u);
}

using test::ToolRun;

TEST_F(ToolRun, SamplesWritesAPlotWithItsSpectrum)
{
    ASSERT_EQ(run("samples --sampler multi-jittered --spp 16 --pixel 3,2 --dims 4,5 --spectrum -o points.png"), 0);
    const Image plot = read_image((dir_ / "points.png").string()); // 8-bit values as v / 255
    // Two 560 x 540 panels (host/sampling/sample_plot.cpp), the points drawn in blue.
    ASSERT_EQ(plot.width, 2u * 560u);
    ASSERT_EQ(plot.height, 540u);
    std::size_t blue = 0;
    for (std::size_t i = 0; i < plot.rgb.size(); i += 3)
        blue += plot.rgb[i + 2] * 255.0f > 120.0f && plot.rgb[i] * 255.0f < 60.0f ? 1 : 0;
    EXPECT_GT(blue, 16u * 10u) << "fewer blue pixels than 16 dots make";
    ASSERT_EQ(run("samples --sampler halton --spp 10 --dims 0,7 -o points1d.png"), 0); // two 1D decisions
    EXPECT_TRUE(fs::exists(dir_ / "points1d.png"));
}

TEST_F(ToolRun, KernelBenchmarksPrintEveryStage)
{
    // `bench --kernels` on a tiny image: every stage is timed and printed with a positive
    // rate (the figures themselves are for docs/performance.md, not for a test). Broken variant
    // seen to fail: the shadow-ray stage left out.
    ASSERT_EQ(run("bench '" + kSource + "/scenes/cornell-box.gltf' --kernels --runs 1 --width 16 --height 16"), 0);
    std::ifstream in(dir_ / "stdout.txt");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const char* stage :
         {"BVH build", "program build, cold", "program binary for the cache, cold", "program build, cached",
          "camera rays", "closest hit, primary rays", "any hit, primary rays", "closest hit, diffuse bounce rays",
          "any hit, diffuse bounce rays", "any hit, shadow rays", "path samples", "film accumulation"}) {
        std::size_t at = text.find(stage);
        ASSERT_NE(at, std::string::npos) << stage << " missing in:\n" << text;
        std::istringstream line(text.substr(at + std::string(stage).size()));
        double lo = 0.0;
        line >> lo;
        if (lo == 0.0) { // stage names with a parenthesis
            line.clear();
            line.ignore(64, ')');
            line >> lo;
        }
        EXPECT_GT(lo, 0.0) << stage;
    }
}

TEST_F(ToolRun, RayLogRaysStartOnTheLensAndMeetOnThePlaneOfFocus)
{
    // The Cornell box camera (world position (0.278, 0.273, -0.8), looking along +Z)
    // with a lens of radius 0.02 focused at 1: 16 x 16 pixels x 4 samples. Every origin
    // lies in the lens disk (the camera's z plane, within 0.02 of its position), every
    // direction is unit and points forward, and the rays of one pixel pass within one
    // pixel footprint (at distance 1, 0.71 / 64 wide) of each other on the plane of
    // focus, while they leave the lens up to 0.04 apart.
    ASSERT_EQ(run("render '" + kSource +
                  "/scenes/cornell-box.gltf' -o img.exr --width 64 --height 64 --spp 4 --aperture 0.02 "
                  "--focus-distance 1 --ray-log rays.ply"),
              0);
    std::ifstream ply(dir_ / "rays.ply");
    std::string line;
    std::size_t vertices = 0;
    while (std::getline(ply, line) && line != "end_header")
        if (line.rfind("element vertex ", 0) == 0)
            vertices = std::stoul(line.substr(15));
    ASSERT_EQ(vertices, 16u * 16u * 4u);
    struct Ray3 {
        double o[3], d[3];
        unsigned x, y, s;
    };
    std::vector<Ray3> rays;
    for (std::size_t i = 0; i < vertices && std::getline(ply, line); ++i) {
        std::istringstream ls(line);
        Ray3 r{};
        ls >> r.o[0] >> r.o[1] >> r.o[2] >> r.d[0] >> r.d[1] >> r.d[2] >> r.x >> r.y >> r.s;
        rays.push_back(r);
    }
    ASSERT_EQ(rays.size(), vertices);
    const double cam[3] = {0.278, 0.273, -0.8};
    double max_lens_spread = 0.0;
    for (const Ray3& r : rays) {
        EXPECT_NEAR(r.o[2], cam[2], 1e-6);
        EXPECT_LE(std::hypot(r.o[0] - cam[0], r.o[1] - cam[1]), 0.02 + 1e-6);
        EXPECT_NEAR(std::hypot(r.d[0], r.d[1], r.d[2]), 1.0, 1e-6);
        EXPECT_GT(r.d[2], 0.0);
    }
    // Group by pixel: focus points within one footprint.
    const double footprint = 2.0 * std::tan(0.5 * 2.0 * std::atan(0.0125 / 0.035)) / 64.0 * std::sqrt(2.0);
    for (std::size_t i = 0; i < rays.size(); ++i)
        for (std::size_t j = i + 1; j < rays.size(); ++j) {
            if (rays[i].x != rays[j].x || rays[i].y != rays[j].y)
                continue;
            double fi[3], fj[3];
            for (int c = 0; c < 3; ++c) { // the plane z = camera z + 1 (forward is +Z)
                fi[c] = rays[i].o[c] + rays[i].d[c] * (1.0 / rays[i].d[2]);
                fj[c] = rays[j].o[c] + rays[j].d[c] * (1.0 / rays[j].d[2]);
            }
            EXPECT_LE(std::hypot(fi[0] - fj[0], fi[1] - fj[1]), footprint + 1e-6);
            max_lens_spread =
                std::max(max_lens_spread, std::hypot(rays[i].o[0] - rays[j].o[0], rays[i].o[1] - rays[j].o[1]));
        }
    EXPECT_GT(max_lens_spread, 0.02); // the lens is really sampled
}

} // namespace
} // namespace pathcl::test_render_samplers
