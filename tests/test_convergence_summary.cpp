// The host side of `pathcl converge`: knobs and their product, the summary's arithmetic
// (slope, time to a target, default targets, curves over seeds) and the CSV's columns,
// on rows whose values are known exactly.
#include <cmath>

#include <gtest/gtest.h>

#include "converge/convergence_csv.h"
#include "converge/convergence_summary.h"
#include "converge/knobs.h"
#include "support/expect_error.h"

namespace pathcl::test_convergence_summary {
namespace {

TEST(Knobs, ProductVariesTheFirstKnobSlowest)
{
    RenderOptions base;
    std::vector<Setting> s =
        settings_product(base, {parse_knob("sampler=independent,sobol"), parse_knob("max-bounces=1,3,5")});
    ASSERT_EQ(s.size(), 6u);
    EXPECT_EQ(s[0].label(), "sampler=independent, max-bounces=1");
    EXPECT_EQ(s[5].label(), "sampler=sobol, max-bounces=5");
    EXPECT_EQ(s[4].options.sampler, SamplerType::Sobol);
    EXPECT_EQ(s[4].options.max_bounces, 3u);
    EXPECT_EQ(s[4].value("max-bounces"), "3");
    EXPECT_EQ(s[4].value("strategy"), "");
}

TEST(Knobs, EveryKnobSetsItsOption)
{
    RenderOptions base;
    std::vector<Setting> s = settings_product(
        base, {parse_knob("strategy=nee"), parse_knob("stratified-bounces=3"), parse_knob("batch-spp=8"),
               parse_knob("fast-math=on"), parse_knob("specialization=all"), parse_knob("adaptive=on"),
               parse_knob("light-sampler=tree"), parse_knob("integrator=wavefront")});
    ASSERT_EQ(s.size(), 1u);
    const RenderOptions& o = s[0].options;
    EXPECT_EQ(o.strategy, Strategy::Nee);
    EXPECT_EQ(o.stratified_bounces, 3u);
    EXPECT_EQ(o.batch_spp, 8u);
    EXPECT_TRUE(o.fast_math);
    EXPECT_EQ(o.specialization, Specialization::All);
    EXPECT_TRUE(o.adaptive);
    EXPECT_EQ(o.light_sampler, LightSampler::Tree);
    EXPECT_EQ(o.integrator, Integrator::Wavefront);
    EXPECT_EQ(knob_names().size(), 10u);
}

TEST(Knobs, BadSpecificationsAreOneLineErrors)
{
    EXPECT_TRUE(test::contains(test::error_of([] { parse_knob("colour=red"); }), "unknown knob \"colour\""));
    EXPECT_TRUE(test::contains(test::error_of([] { parse_knob("sampler"); }), "KNOB=V1,V2"));
    EXPECT_TRUE(test::contains(test::error_of([] { parse_knob("sampler=sobol,bogus"); }), "\"bogus\""));
    EXPECT_TRUE(test::contains(test::error_of([] { parse_knob("max-bounces=2,x"); }), "\"x\""));
    EXPECT_TRUE(test::contains(test::error_of([] { parse_knob("fast-math=yes"); }), "neither off nor on"));
    EXPECT_TRUE(test::contains(test::error_of([] { parse_knob("light-sampler=bvh"); }), "'bvh'"));
    EXPECT_TRUE(test::contains(test::error_of([] { parse_knob("sampler=sobol,sobol"); }), "twice"));
    EXPECT_TRUE(test::contains(
        test::error_of([] {
            settings_product(RenderOptions{}, {parse_knob("sampler=sobol"), parse_knob("sampler=halton")});
        }),
        "twice"));
}

TEST(ConvergenceSummary, SlopeOfAPowerLawIsItsExponent)
{
    std::vector<double> x = {1, 2, 4, 8, 16}, y;
    for (double v : x)
        y.push_back(3.0 * std::pow(v, -1.5));
    EXPECT_NEAR(log_log_slope(x, y), -1.5, 1e-12);
    EXPECT_TRUE(std::isnan(log_log_slope({1.0}, {1.0})));
}

TEST(ConvergenceSummary, TimeToReachInterpolatesInLogLog)
{
    SettingCurve c;
    c.seconds = {1.0, 4.0};
    c.relmse = {0.1, 0.025};
    // relMSE falls as 1 / t here: 0.05 is reached at 2 s.
    EXPECT_NEAR(time_to_reach(c, 0.05), 2.0, 1e-12);
    EXPECT_DOUBLE_EQ(time_to_reach(c, 0.2), 1.0); // already at the first point
    EXPECT_TRUE(std::isnan(time_to_reach(c, 0.01)));
}

// Two seeds at two ladder points for one setting.
std::vector<ConvergenceRow> two_seed_rows()
{
    std::vector<ConvergenceRow> rows;
    for (std::uint32_t n : {4u, 16u})
        for (std::uint32_t seed : {0u, 1u}) {
            ConvergenceRow r;
            r.spp = n;
            r.spp_taken = n;
            r.seed = seed;
            r.render_seconds = 0.01 * n * (1 + seed);
            r.error.relmse = 0.4 / n * (1 + seed);
            rows.push_back(r);
        }
    return rows;
}

TEST(ConvergenceSummary, CurvesTakeTheMedianAndRangeOverSeeds)
{
    std::vector<SettingCurve> c = setting_curves(two_seed_rows(), 1, {4, 16, 64});
    ASSERT_EQ(c.size(), 1u);
    ASSERT_EQ(c[0].relmse.size(), 2u); // 64 has no rows
    EXPECT_DOUBLE_EQ(c[0].relmse[0], 0.15);
    EXPECT_DOUBLE_EQ(c[0].relmse_min[0], 0.1);
    EXPECT_DOUBLE_EQ(c[0].relmse_max[1], 0.05);
    EXPECT_DOUBLE_EQ(c[0].seconds[1], 0.24);
    std::vector<double> t = default_targets(c);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_LT(t[0], 0.15);
    EXPECT_GT(t[2], 0.0375);
}

TEST(ConvergenceSummary, ABiasLimitedFirstSettingDoesNotNarrowTheTargets)
{
    // The first setting stalls at 0.1 to 0.09 (a bounce limit's bias); two others converge
    // from 0.15 to 0.0375. Targets from the first curve alone would all sit near 0.09.
    SettingCurve stalled, converging = setting_curves(two_seed_rows(), 1, {4, 16})[0];
    stalled.spp = {4, 16};
    stalled.seconds = {0.04, 0.16};
    stalled.relmse = stalled.relmse_min = stalled.relmse_max = {0.1, 0.09};
    std::vector<double> t = default_targets({stalled, converging, converging});
    ASSERT_EQ(t.size(), 3u);
    EXPECT_LT(t[0], 0.15);
    EXPECT_LT(t[2], 0.085);
    EXPECT_GT(t[2], 0.0375);
}

TEST(ConvergenceCsv, OneColumnPerKnobAndPerFigure)
{
    ConvergenceStudy study;
    study.settings = settings_product(RenderOptions{}, {parse_knob("sampler=sobol"), parse_knob("strategy=nee")});
    std::string header = csv_header(study);
    EXPECT_EQ(header.rfind("setting,sampler,strategy,spp,", 0), 0u) << header;
    ConvergenceRow row = two_seed_rows()[0];
    row.stop = "spp";
    std::string line = csv_line(study, {SettingBuild{1.5, 0.01}}, row);
    EXPECT_EQ(line.rfind("0,sobol,nee,4,4,0,", 0), 0u) << line;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), std::count(header.begin(), header.end(), ','));
    EXPECT_EQ(line.back(), '\n');
}

} // namespace
} // namespace pathcl::test_convergence_summary
