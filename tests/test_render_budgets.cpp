// Budgets and error estimates on the device: the batch-spread estimate tracks the true
// error against a converged reference for the independent and the Sobol' sampler (and the
// per-sample-variance estimate is shown to overstate Sobol's), --time stops within a
// pass of its budget, --target-error stops at the first batch that reaches the target,
// adaptive sampling converges to the uniform image, a stopped render is reproduced by
// its spp and batch size, the program compiled with every feature renders the image
// the scene's own variant renders, and so does the fast-math build.
#include <iostream>

#include <gtest/gtest.h>

#include "compile/kernel_features.h"
#include "image/image_compare.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/render_checks.h"
#include "support/test_options.h"

namespace pathcl::test_render_budgets {
namespace {

const std::string kSource = PATHCL_SOURCE_DIR;

const Scene& cornell_box()
{
    static Scene s = load_gltf(kSource + "/scenes/cornell-box.gltf");
    return s;
}

// 8192 independent samples per pixel (tools/make_references.sh): its own relMSE is about
// 1/128 of a 64-spp independent render's.
const Image& cornell_reference()
{
    static Image ref = read_image(kSource + "/tests/references/cornell-box-64.exr");
    return ref;
}

const Scene& glass_mirror_box()
{
    static Scene s = load_gltf(kSource + "/scenes/cornell-box-glass-mirror.gltf");
    return s;
}

RenderOptions cornell_options(SamplerType sampler)
{
    RenderOptions o = test::independent_options();
    o.sampler = sampler;
    o.width = o.height = 64;
    o.max_bounces = 8; // as the reference
    o.spp = 64;
    return o;
}

struct Tracking {
    double estimated = 0.0, actual = 0.0, per_sample = 0.0;
};

// Summed over seeds: the renders' estimated relMSE (batch spread, or per-sample variance
// for one batch) and their actual relMSE against the reference.
Tracking track(const RenderOptions& o, int seeds)
{
    Renderer renderer(cornell_box(), o);
    Tracking t;
    for (int seed = 1; seed <= seeds; ++seed) {
        RenderResult r = renderer.render(static_cast<std::uint32_t>(seed));
        t.estimated += r.stats.error_estimate;
        t.actual += measure_error(r.image, cornell_reference()).relmse;
    }
    return t;
}

// The band the estimate must stay in: the reference's own error adds about 1% to the
// actual error, and 8 renders of 4 batches leave the sum of estimates a few per cent of
// noise, heavier-tailed where a path finds the light rarely.
constexpr double kBandLow = 0.75, kBandHigh = 1.33;

TEST(ErrorEstimate, BatchSpreadTracksTheTrueErrorForIndependentAndSobol)
{
    for (SamplerType sampler : {SamplerType::Independent, SamplerType::Sobol}) {
        RenderOptions o = cornell_options(sampler);
        o.batch_spp = 16; // four independently scrambled batches
        Tracking t = track(o, 8);
        double ratio = t.estimated / t.actual;
        std::cout << sampler_name(sampler) << ": estimated / actual relMSE " << ratio << '\n';
        EXPECT_GT(ratio, kBandLow) << sampler_name(sampler);
        EXPECT_LT(ratio, kBandHigh) << sampler_name(sampler);
    }
}

TEST(ErrorEstimate, PerSampleVarianceOverstatesSobolError)
{
    // The estimate a single batch falls back on: right for independent samples, but it
    // ignores what stratification gains, so for Sobol' it is far outside the band the
    // batch estimate keeps (which is why --target-error uses batches).
    RenderOptions o = cornell_options(SamplerType::Independent);
    Tracking indep = track(o, 8);
    double ratio = indep.estimated / indep.actual;
    EXPECT_GT(ratio, kBandLow);
    EXPECT_LT(ratio, kBandHigh);
    o.sampler = SamplerType::Sobol;
    Tracking sobol = track(o, 8);
    ratio = sobol.estimated / sobol.actual;
    std::cout << "sobol, per-sample variance: estimated / actual relMSE " << ratio << '\n';
    EXPECT_GT(ratio, kBandHigh); // 1.8 here: Sobol's gain at 64 spp on this scene
}

TEST(Budgets, TimeBudgetStopsWithinOnePass)
{
    RenderOptions o = cornell_options(SamplerType::Sobol);
    o.spp = 1u << 20;
    o.time_budget = 1.0;
    RenderResult r = Renderer(cornell_box(), o).render();
    const RenderStats& s = r.stats;
    EXPECT_EQ(s.stop, StopReason::Time);
    double pass = s.render_seconds / s.spp;
    std::cout << s.spp << " passes in " << s.render_seconds << " s\n";
    EXPECT_GE(s.render_seconds, o.time_budget);
    // One pass may be in flight when the budget runs out, and the films are read after it;
    // the slack covers a machine that stalls a pass.
    EXPECT_LT(s.render_seconds, o.time_budget + 2.0 * pass + 0.25);
    EXPECT_EQ(r.image.spp, s.spp);
}

TEST(Budgets, TargetErrorStopsAtTheFirstBatchThatReachesIt)
{
    RenderOptions o = cornell_options(SamplerType::Sobol);
    o.spp = 4096;
    o.target_error = 2e-3;
    std::vector<double> estimates; // after each whole batch
    std::uint32_t batches_seen = 0;
    Renderer renderer(cornell_box(), o);
    RenderResult r = renderer.render(3, [&](const RenderProgress& p) {
        if (p.batches > batches_seen) {
            batches_seen = p.batches;
            estimates.push_back(p.error_estimate);
        }
        return true;
    });
    const RenderStats& s = r.stats;
    ASSERT_EQ(s.stop, StopReason::TargetError);
    EXPECT_LE(s.error_estimate, o.target_error);
    EXPECT_EQ(s.spp, s.batches * s.batch_spp);
    // No more batches than needed: the estimate before the last batch was above the
    // target (or there were too few batches for one).
    ASSERT_GE(estimates.size(), 2u);
    double previous = estimates[estimates.size() - 2];
    EXPECT_TRUE(previous < 0.0 || previous > o.target_error) << previous;
    double actual = measure_error(r.image, cornell_reference()).relmse;
    std::cout << s.spp << " spp, estimated " << s.error_estimate << ", actual " << actual << '\n';
    EXPECT_LT(actual, kBandHigh * o.target_error);
}

TEST(Budgets, AStoppedRenderIsReproducedByItsSppAndBatchSize)
{
    RenderOptions o = cornell_options(SamplerType::Sobol);
    o.width = o.height = 32;
    o.spp = 1000;
    o.batch_spp = 16;
    RenderResult stopped = Renderer(cornell_box(), o).render(5, [](const RenderProgress& p) { return p.spp < 37; });
    ASSERT_EQ(stopped.stats.stop, StopReason::Interrupted);
    ASSERT_GE(stopped.stats.spp, 37u);
    EXPECT_NE(stopped.stats.spp % 16, 0u) << "the test wants a partial last batch";
    o.spp = stopped.stats.spp;
    RenderResult again = Renderer(cornell_box(), o).render(5);
    BitwiseReport b = compare_bitwise(stopped.image, again.image);
    EXPECT_TRUE(b.identical()) << b.summary();
}

TEST(Budgets, AdaptiveSamplingConvergesToTheUniformImage)
{
    RenderOptions o = cornell_options(SamplerType::Independent);
    o.spp = 512;
    // Low enough that pixels stop before the image does (roulette from the fifth bounce
    // reaches 4e-3 at 64 spp, before any pixel stops).
    o.target_error = 2.5e-3;
    o.adaptive = true;
    RenderResult r = Renderer(cornell_box(), o).render(11);
    ASSERT_EQ(r.image.samples.size(), 64u * 64u);
    std::uint32_t least = *std::min_element(r.image.samples.begin(), r.image.samples.end());
    std::uint32_t most = *std::max_element(r.image.samples.begin(), r.image.samples.end());
    std::cout << "samples per pixel " << least << " to " << most << ", " << r.stats.spp << " passes\n";
    EXPECT_LT(least, most) << "no pixel stopped early: the test does not exercise adaptive sampling";
    CompareReport cmp = compare_images(r.image, cornell_reference());
    std::cout << cmp.summary();
    EXPECT_TRUE(cmp.passed) << cmp.summary();
}

TEST(Specialization, EveryFeatureCompiledInRendersTheSameImage)
{
    // The glass-and-mirror box uses transmission and glossy lobes but no texture, vertex
    // colour, thin lens, environment or punctual light: the full variant reads arrays the
    // scene does not fill (white colours) and runs branches it never takes.
    const Scene& scene = glass_mirror_box();
    RenderOptions o = cornell_options(SamplerType::Independent);
    o.spp = 256;
    RenderOptions all = o;
    all.specialization = Specialization::All;
    ASSERT_NE(kernel_features(scene, o).mask, kernel_features(scene, all).mask);
    RenderResult a = Renderer(scene, o).render(1), b = Renderer(scene, all).render(2);
    test::expect_same_mean(a.image, b.image);
}

TEST(FastMath, RendersTheReferenceImage)
{
    // Reordered and contracted arithmetic may move a pixel by ulps, never the image:
    // glass (refraction, Fresnel) and mirrors are where a dropped check would show.
    const Scene& scene = glass_mirror_box();
    RenderOptions o = cornell_options(SamplerType::Independent);
    o.spp = 256;
    o.fast_math = true;
    ASSERT_NE(program_build_options(kernel_features(scene, o), o).find("-cl-unsafe-math-optimizations"),
              std::string::npos);
    static const Image reference = read_image(kSource + "/tests/references/cornell-box-glass-mirror-64.exr");
    RenderResult r = Renderer(scene, o).render(3);
    EXPECT_EQ(r.stats.bad_samples, 0u);
    CompareReport cmp = compare_images(r.image, reference);
    std::cout << cmp.summary();
    EXPECT_TRUE(cmp.passed) << cmp.summary();
}

} // namespace
} // namespace pathcl::test_render_budgets
