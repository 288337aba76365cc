// Convergence studies on the device: on the Cornell box the independent sampler's relMSE
// falls as 1 / spp (slope -1) and Sobol's faster (the command itself:
// test_cli_converge.cpp).
#include <iostream>

#include <gtest/gtest.h>

#include "converge/convergence.h"
#include "converge/convergence_summary.h"
#include "image/image_io.h"
#include "scene/gltf_loader.h"
#include "support/test_options.h"

namespace pathcl::test_converge {
namespace {

const std::string kSource = PATHCL_SOURCE_DIR;

TEST(Converge, IndependentSlopeIsMinusOneAndSobolSteeper)
{
    // Against the committed 8192-spp reference (64 x 64, 8 bounces), ladder 4 .. 128, four
    // seeds per point. Measured over base seeds 0, 10, 20, 30: independent -0.97 to -1.03,
    // Sobol' -1.13 to -1.15 (steeper by 0.12 to 0.17): the tolerance on -1 and the margin
    // for "steeper" cover that spread.
    Scene scene = load_gltf(kSource + "/scenes/cornell-box.gltf");
    Image reference = read_image(kSource + "/tests/references/cornell-box-64.exr");
    ConvergenceStudy study;
    study.base = test::independent_options();
    study.base.width = study.base.height = 64;
    study.base.max_bounces = 8; // as the reference
    study.settings = settings_product(study.base, {parse_knob("sampler=independent,sobol")});
    study.ladder = {4, 8, 16, 32, 64, 128};
    study.seeds = 4;
    std::vector<ConvergenceRow> rows;
    ConvergenceCallbacks cb;
    cb.row = [&](const ConvergenceRow& r) {
        rows.push_back(r);
        return true;
    };
    ASSERT_TRUE(run_convergence(scene, study, reference, cb));
    ASSERT_EQ(rows.size(), 2u * 6u * 4u);
    std::vector<SettingCurve> c = setting_curves(rows, 2, study.ladder);
    double independent = log_log_slope(c[0].spp, c[0].relmse), sobol = log_log_slope(c[1].spp, c[1].relmse);
    std::cout << "slopes: independent " << independent << ", sobol " << sobol << '\n';
    EXPECT_NEAR(independent, -1.0, 0.1);
    EXPECT_LT(sobol, independent - 0.05);
}

} // namespace
} // namespace pathcl::test_converge
