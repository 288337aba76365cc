// The wavefront integrator (kernels/wavefront/, --integrator wavefront): every strategy
// against the Cornell box's committed reference, as the megakernel is tested (and the
// comparison shown to fail on a deliberately broken shading stage); its paths in eight
// lanes per work-item and in one give the same image bit for bit; its image on two
// devices is its one-device image bit for bit; it refuses, in one line, scenes its stages
// do not cover.
#include <string>

#include <gtest/gtest.h>

#include "common/error.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/same_image.h"
#include "support/test_options.h"
#include "support/tool_run.h"

namespace pathcl::test_render_wavefront {
namespace {

const std::string kSource = PATHCL_SOURCE_DIR;

// The settings of tests/references/cornell-box-64.exr, another seed, the wavefront.
RenderOptions wavefront_options()
{
    RenderOptions o = test::independent_options();
    o.width = o.height = 64;
    o.spp = 256;
    o.max_bounces = 8;
    o.seed = 11;
    o.integrator = Integrator::Wavefront;
    return o;
}

const Scene& cornell_box()
{
    static Scene s = load_gltf(kSource + "/scenes/cornell-box.gltf");
    return s;
}

CompareReport against_reference(const RenderOptions& o)
{
    RenderResult r = render(cornell_box(), o);
    EXPECT_EQ(r.stats.bad_samples, 0u);
    CompareOptions co;
    co.pooled_variance = false; // another estimator's variance than the reference's
    co.judge_pixels = o.strategy != Strategy::Bsdf;
    return compare_images(r.image, read_image(kSource + "/tests/references/cornell-box-64.exr"), co);
}

TEST(Wavefront, EveryStrategyMatchesTheCornellBoxReference)
{
    for (Strategy strategy : {Strategy::Bsdf, Strategy::Nee, Strategy::OneSample, Strategy::Mis}) {
        RenderOptions o = wavefront_options();
        o.strategy = strategy;
        CompareReport cmp = against_reference(o);
        std::cout << "strategy " << strategy_name(strategy) << "\n" << cmp.summary();
        EXPECT_TRUE(cmp.passed) << "strategy " << strategy_name(strategy) << "\n" << cmp.summary();
    }
}

TEST(Wavefront, BrokenShadingFailsTheCornellBoxComparison)
{
    // The shading stage's light sample forgetting cos(theta) at the surface: proves the
    // comparison above can fail on a plausible bug of the stage kernels themselves.
    RenderOptions o = wavefront_options();
    o.spp = 64;
    o.kernel_patches = {{"wavefront/shade_lambertian.cl", "lane3_scale(base_color, INV_PI * cos_i)",
                         "lane3_scale(base_color, lane_splat(INV_PI))"}};
    CompareReport cmp = against_reference(o);
    EXPECT_FALSE(cmp.passed) << cmp.summary();
}

TEST(Wavefront, OneLaneAndEightLanesGiveTheSameImageBitForBit)
{
    // The lanes run the same arithmetic per path; one lane is what GPUs get.
    RenderOptions o = wavefront_options();
    o.spp = 16;
    o.wavefront_lanes = 1;
    RenderResult one = render(cornell_box(), o);
    o.wavefront_lanes = 8;
    RenderResult eight = render(cornell_box(), o);
    test::expect_same_image(one.image, eight.image, "1 lane against 8");
}

TEST(Wavefront, RefusesScenesItsStagesDoNotCover)
{
    RenderOptions o = wavefront_options();
    Scene glass = load_gltf(kSource + "/scenes/cornell-box-glass-mirror.gltf");
    try {
        render(glass, o);
        FAIL() << "the wavefront rendered a glossy scene";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("wavefront"), std::string::npos) << e.what();
    }
}

class WavefrontTool : public test::ToolRun {};

TEST_F(WavefrontTool, TwoDevicesRenderTheOneDeviceImage)
{
    // PoCL's "basic" driver twice (see test_multi_device.cpp); 37 rows: the second band
    // ends off the tile grid, and the rows are dealt again after the first pass.
    const std::string devices = "POCL_DEVICES='basic basic'";
    ASSERT_EQ(run("devices", devices), 0) << text("stderr.txt");
    if (text("stdout.txt").find("\n1: ") == std::string::npos)
        GTEST_SKIP() << "the OpenCL platform shows one device (not PoCL?)";
    const std::string render = "render '" + kSource + "/scenes/cornell-box.gltf' --integrator wavefront --width 40 " +
                               "--height 37 --spp 8 --max-bounces 5 --quiet ";
    ASSERT_EQ(run(render + "-o one.exr --device 0", devices), 0) << text("stderr.txt");
    ASSERT_EQ(run(render + "-o two.exr --device 0,1 --device-shares 1,3", devices), 0) << text("stderr.txt");
    test::expect_same_image(read_image((dir_ / "one.exr").string()), read_image((dir_ / "two.exr").string()),
                            "two devices");
}

TEST_F(WavefrontTool, AGlossySceneIsAOneLineError)
{
    ASSERT_EQ(run("render '" + kSource + "/scenes/cornell-box-glass-mirror.gltf' --integrator wavefront -o x.exr"), 2);
    const std::string err = text("stderr.txt");
    EXPECT_NE(err.find("wavefront"), std::string::npos) << err;
    EXPECT_EQ(err.find('\n'), err.size() - 1) << err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "x.exr"));
}

} // namespace
} // namespace pathcl::test_render_wavefront
