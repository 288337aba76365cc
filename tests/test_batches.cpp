// Batches and error estimates on the host: how a render is laid out in batches
// (render/batches.h), and the error estimate of FilmAccumulator checked on films whose
// batch means are known exactly.
#include <gtest/gtest.h>

#include "common/error.h"
#include "render/batches.h"
#include "render/film.h"
#include "support/expect_error.h"

namespace pathcl::test_batches {
namespace {

RenderOptions budget_options()
{
    RenderOptions o;
    o.sampler = SamplerType::Sobol;
    o.spp = 100;
    return o;
}

TEST(Batches, APlainRenderIsOneBatchOfTheRoundedSpp)
{
    RenderOptions o;
    o.sampler = SamplerType::Jittered;
    o.spp = 10; // jittered rounds to the next square
    BatchPlan p = plan_batches(o);
    EXPECT_EQ(p.batch_spp, 16u);
    EXPECT_EQ(p.max_spp, 16u);
    EXPECT_EQ(p.batch_count(), 1u);
    EXPECT_FALSE(p.budgeted);
}

TEST(Batches, ABudgetSplitsIntoBatchesWithAPartialLastOne)
{
    RenderOptions o = budget_options();
    o.time_budget = 5.0;
    BatchPlan p = plan_batches(o);
    EXPECT_TRUE(p.budgeted);
    EXPECT_EQ(p.batch_spp, 16u); // the default batch under a budget
    EXPECT_EQ(p.max_spp, 100u);  // not rounded to whole batches: --spp N reproduces a stopped render
    EXPECT_EQ(p.batch_count(), 7u);
    EXPECT_EQ(p.batch_passes(0), 16u);
    EXPECT_EQ(p.batch_passes(6), 4u);
    EXPECT_EQ(p.batch_passes(7), 0u);
}

TEST(Batches, BatchSizeIsRoundedByTheSampler)
{
    RenderOptions o = budget_options();
    o.sampler = SamplerType::Hammersley;
    o.batch_spp = 12;
    EXPECT_EQ(plan_batches(o).batch_spp, 16u);
}

TEST(Batches, TargetErrorWaitsForTwoBatches)
{
    RenderOptions o = budget_options();
    o.target_error = 1e-3;
    EXPECT_EQ(plan_batches(o).min_spp, 32u);
    o.min_spp = 50;
    EXPECT_EQ(plan_batches(o).min_spp, 50u);
    o.min_spp = 0;
    o.spp = 20; // fewer than two batches of 16
    EXPECT_TRUE(test::contains(test::error_of([&] { plan_batches(o); }), "two batches"));
}

TEST(Batches, BadBudgetsAreRefused)
{
    RenderOptions o = budget_options();
    o.adaptive = true;
    EXPECT_TRUE(test::contains(test::error_of([&] { plan_batches(o); }), "needs a target error"));
    o = budget_options();
    o.time_budget = -1.0;
    EXPECT_TRUE(test::contains(test::error_of([&] { plan_batches(o); }), "time_budget"));
    o = budget_options();
    o.target_error = std::nan("");
    EXPECT_TRUE(test::contains(test::error_of([&] { plan_batches(o); }), "target_error"));
    o = budget_options();
    o.target_error = 1e-3;
    o.min_spp = 200;
    EXPECT_TRUE(test::contains(test::error_of([&] { plan_batches(o); }), "min_spp"));
}

TEST(Batches, BatchZeroKeepsTheSeedAndTheOthersDiffer)
{
    EXPECT_EQ(batch_seed(7, 0), 7u);
    EXPECT_NE(batch_seed(7, 1), batch_seed(7, 2));
    EXPECT_NE(batch_seed(7, 1), batch_seed(8, 1));
    EXPECT_NE(batch_seed(7, 1), 7u);
}

// One pixel's film holding `n` samples of value v (variance zero within the batch).
FilmSum constant_batch(float v, float n)
{
    FilmPixel px{};
    px.sum = {v * n, v * n, v * n, n};
    px.sum_sq = {v * v * n, v * v * n, v * v * n, n};
    FilmSum s(1);
    s.add({px}, {0u});
    return s;
}

TEST(FilmAccumulator, EstimateIsTheSpreadOfTheBatchMeans)
{
    // Batch means 1 and 3 over 4 samples each: the variance of one batch mean is 2, of
    // the image's mean (8 samples) 2 / 2 = 1; the image's mean is 2, so relMSE
    // 1 / (4 + 0.01).
    FilmAccumulator acc(1, 4);
    acc.add_batch(constant_batch(1.0f, 4.0f));
    EXPECT_LT(acc.relmse_estimate(), 0.0); // one batch: no spread yet
    acc.add_batch(constant_batch(3.0f, 4.0f));
    EXPECT_NEAR(acc.relmse_estimate(), 1.0 / 4.01, 1e-12);
    EXPECT_NEAR(acc.pixel_relmse_estimate(0), 1.0 / 4.01, 1e-12);
    // Within a batch every sample was equal: the per-sample variance sees only the
    // difference between the batches, (6 samples of 1 and 3 around 2) / 7 per sample.
    double per_sample_var = 8.0 / 7.0;
    EXPECT_NEAR(acc.per_sample_relmse_estimate(), per_sample_var / 8.0 / 4.01, 1e-12);
}

TEST(FilmAccumulator, SumsPastTheirRangeLeaveNoEstimateRatherThanZeroOrNan)
{
    // A green radiance of 1e20: its square, 1e40, is past the range of the film's sums
    // (ExactSum: 2e28), so the spread of the samples and of the batch means is lost in
    // that channel. No estimate, not 0 (which would stop adaptive sampling at once), nor
    // nan, nor the other channels' alone.
    FilmAccumulator acc(2, 4);
    FilmPixel huge{}, small{};
    huge.sum = {4.0f, 4e20f, 4.0f, 4.0f};
    huge.sum_sq = {4.0f, INFINITY, 4.0f, 4.0f};
    small.sum = {4.0f, 4.0f, 4.0f, 4.0f};
    small.sum_sq = {4.0f, 4.0f, 4.0f, 4.0f};
    FilmSum batch(2);
    batch.add({huge, small}, {0u});
    acc.add_batch(batch);
    EXPECT_LT(acc.per_sample_relmse_estimate(), 0.0);
    acc.add_batch(batch);
    EXPECT_LT(acc.relmse_estimate(), 0.0);
    EXPECT_LT(acc.pixel_relmse_estimate(0), 0.0);
    EXPECT_GE(acc.pixel_relmse_estimate(1), 0.0); // the other pixel keeps its own
    // The image's variance channel: unbounded where the square was lost, not 0, which
    // would claim an exact pixel; the other channels and pixels keep theirs.
    const Image img = acc.image(2, 1, 8);
    EXPECT_EQ(img.rgb[1], 1e20f);
    EXPECT_EQ(img.variance[1], INFINITY);
    EXPECT_EQ(img.variance[0], 0.0f);
    EXPECT_EQ(img.variance[2], 0.0f);
    for (int c = 3; c < 6; ++c)
        EXPECT_EQ(img.variance[static_cast<std::size_t>(c)], 0.0f);
}

TEST(FilmAccumulator, APartialBatchAddsToTheImageAndScalesTheEstimate)
{
    FilmAccumulator acc(1, 4);
    acc.add_batch(constant_batch(1.0f, 4.0f));
    acc.add_batch(constant_batch(3.0f, 4.0f));
    acc.add_partial_batch(constant_batch(2.0f, 2.0f));
    EXPECT_EQ(acc.batches(), 2u);
    EXPECT_EQ(acc.pixel_samples()[0], 10u);
    // var(batch mean) 2 for 4 samples: 2 * 4 / 10 for the image's 10; its mean is 2.
    EXPECT_NEAR(acc.relmse_estimate(), 0.8 / 4.01, 1e-12);
    Image img = acc.image(1, 1, 10);
    EXPECT_FLOAT_EQ(img.rgb[0], 2.0f);
}

TEST(FilmAccumulator, PixelsWithoutSamplesInABatchKeepTheirSpread)
{
    // Adaptive sampling: a pixel that took no sample in a batch keeps the batches it had.
    FilmAccumulator acc(1, 4);
    acc.add_batch(constant_batch(1.0f, 4.0f));
    acc.add_batch(constant_batch(3.0f, 4.0f));
    double before = acc.pixel_relmse_estimate(0);
    acc.add_batch(FilmSum(1));
    EXPECT_EQ(acc.batches(), 3u);
    EXPECT_DOUBLE_EQ(acc.pixel_relmse_estimate(0), before);
}

TEST(FilmAccumulator, HostMemoryIsCheckedBeforeTheFilmIsAllocated)
{
    // 1920x1080 on two devices: 300 + 64 + 2 x 68 bytes a pixel.
    EXPECT_DOUBLE_EQ(host_film_bytes(1920 * 1080, 2), 1920.0 * 1080.0 * 500.0);
    EXPECT_NO_THROW(check_host_memory(1e9, 2e9));
    EXPECT_EQ(test::error_of([] { check_host_memory(3.0 * 1073741824.0, 2.0 * 1073741824.0); }),
              "the film needs 3.00 GiB of host memory, more than this machine's 2.00 GiB");
    EXPECT_NO_THROW(check_host_memory(1e6)); // this machine has a megabyte
}

// Sample ranges merge exactly: batches added to one film, or to several merged in another
// order, give the same state to the last bit, and so the same image.
TEST(FilmAccumulator, BatchesSplitOverFilmsAndMergedGiveTheSameState)
{
    std::vector<FilmSum> batches;
    for (int b = 0; b < 9; ++b) {
        FilmPixel px{};
        const float v = 0.1f + 0.37f * static_cast<float>(b % 4) + 1e-4f * static_cast<float>(b);
        px.sum = {v * 16, 2 * v * 16, 3e3f * v * 16, 16};
        px.sum_compensation = {1e-9f * static_cast<float>(b), 0, 0, 0};
        px.sum_sq = {v * v * 16, 4 * v * v * 16, 9e6f * v * v * 16, 16};
        FilmSum s(1);
        s.add({px}, {static_cast<pcl_uint>(b % 2)});
        batches.push_back(std::move(s));
    }
    FilmAccumulator whole(1, 16), first(1, 16), second(1, 16);
    for (int b = 0; b < 9; ++b) {
        whole.add_batch(batches[b]);
        (b % 3 == 1 ? first : second).add_batch(batches[b]);
    }
    FilmAccumulator merged(1, 16);
    merged.merge(second.state());
    merged.merge(first.state());
    const auto& a = whole.state();
    const auto& m = merged.state();
    EXPECT_TRUE(a.sum == m.sum && a.sum_sq == m.sum_sq && a.batch_mean_sum == m.batch_mean_sum &&
                a.batch_mean_sq == m.batch_mean_sq);
    EXPECT_EQ(a.samples, m.samples);
    EXPECT_EQ(a.pixel_batches, m.pixel_batches);
    EXPECT_EQ(a.bad, m.bad);
    EXPECT_EQ(a.batches, m.batches);
    EXPECT_EQ(whole.relmse_estimate(), merged.relmse_estimate());
    EXPECT_THROW(merged.merge(FilmAccumulator(2, 16).state()), Error);
}

} // namespace
} // namespace pathcl::test_batches
