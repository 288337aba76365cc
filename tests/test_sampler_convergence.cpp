// The samplers of kernels/sample/sampler.cl as estimators, through the real kernel code:
// bit-identical values whatever the order of computation, and the convergence order of
// smooth 2D integrals. Each property test names, beside it, the deliberately broken variant
// that was seen to fail it (checked once, by hand).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sample/dimensions.h"
#include "sampling/samplers.h"
#include "support/device_fixture.h"
#include "support/sampler_points.h"

namespace pathcl::test_sampler_convergence {
namespace {

using test::pixel_range;
using test::points;
using test::sampler_program;

TEST(Samplers, ValuesDoNotDependOnTheOrderOfComputation)
{
    // The same (pixel, sample, dimension) gives bit-identical values whether the pixels
    // are computed in order, shuffled, or one at a time, and whether the samples are
    // computed in one launch or in two. Broken variant seen to fail: a scramble seeded
    // with the work-item id instead of the pixel.
    std::vector<std::uint32_t> order = pixel_range(500, 64);
    std::vector<std::uint32_t> shuffled = order;
    std::mt19937 rng(5);
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const std::uint32_t spp = 64;
    for (const auto& [sampler_label, sampler] : sampler_names())
        for (bool one_d : {false, true}) {
            SCOPED_TRACE(sampler_name(sampler) + (one_d ? " 1D" : " 2D"));
            const std::uint32_t dim = DIM_PATH_START + 2 * DIMS_PER_BOUNCE + 3;
            std::vector<glm::vec2> a = points(sampler, spp, order, dim, one_d);
            std::vector<glm::vec2> b = points(sampler, spp, shuffled, dim, one_d);
            for (std::size_t i = 0; i < shuffled.size(); ++i) {
                std::size_t j = shuffled[i] - 500; // where pixel shuffled[i] sits in `a`
                for (std::uint32_t k = 0; k < spp; ++k) {
                    ASSERT_EQ(b[i * spp + k].x, a[j * spp + k].x);
                    ASSERT_EQ(b[i * spp + k].y, a[j * spp + k].y);
                }
            }
            // Samples 40..63 of one pixel alone.
            SamplerPointsRequest r;
            r.sampler = sampler;
            r.spp = spp;
            r.seed = 11;
            r.dim0 = dim;
            r.dim1 = one_d ? dim + 2 : dim + 1;
            r.pixels = {order[17]};
            r.first_sample = 40;
            r.count = 24;
            std::vector<glm::vec2> c = compute_sampler_points(test::test_device(), sampler_program(), r);
            for (std::uint32_t k = 0; k < 24; ++k) {
                ASSERT_EQ(c[k].x, a[17 * spp + 40 + k].x);
                ASSERT_EQ(c[k].y, a[17 * spp + 40 + k].y);
            }
        }
}

// Least-squares slope of log(mse) against log(spp).
double loglog_slope(const std::vector<double>& spp, const std::vector<double>& mse)
{
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < spp.size(); ++i) {
        mx += std::log(spp[i]);
        my += std::log(mse[i]);
    }
    mx /= static_cast<double>(spp.size());
    my /= static_cast<double>(spp.size());
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < spp.size(); ++i) {
        double dx = std::log(spp[i]) - mx;
        sxy += dx * (std::log(mse[i]) - my);
        sxx += dx * dx;
    }
    return sxy / sxx;
}

// Integral over [0, 1] of exp(-(x - mu)^2 / (2 sigma^2)).
double gaussian_integral(double mu, double sigma)
{
    double k = sigma * std::sqrt(2.0);
    return sigma * std::sqrt(std::numbers::pi / 2.0) * (std::erf((1.0 - mu) / k) + std::erf(mu / k));
}

TEST(Samplers, ConvergenceOrderOfSmooth2DIntegrals)
{
    // The MSE of the per-pixel estimate over 256 pixels (independent randomizations) at
    // spp 16, 64, 256, 1024, 4096, for the film-position pair and a padded pair deep in
    // the path, of two smooth integrands with known integrals:
    //   bump:  an off-centre Gaussian, exp(-(x-0.45)^2 / (2 0.12^2) - (y-0.55)^2 / (2 0.18^2)),
    //          about 3e-5 of its peak at the border (product of erf integrals);
    //   exp(x y), whose integral is sum_{n>=1} 1 / (n n!) = 1.3179021514...
    // Independent sampling converges as spp^-1; jittered as spp^-2, the Owen-scrambled
    // nets faster. Multi-jittered is Kensler's correlated construction: all samples of a
    // row of cells share one sub-column offset, so each row is a randomly shifted grid
    // rule in x, whose first-order error (f(1, y) - f(0, y)) / (2 cols) does not cancel
    // between rows: spp^-3 on the bump, but only about spp^-1.5 on exp(x y) (measured
    // -1.46; the original, uncorrelated multi-jittered construction of Chiu, Shirley and
    // Wang, simulated outside this repository, gave -2.1). Halton at dims 45, 46 (bases
    // 199 and 211) is only reported: at these spp its high bases converge slowly (-1.4).
    // Broken variant seen to fail: jittered with each sample's stratum drawn at random
    // (slope -1.0 on both integrands).
    double exp_xy = 0.0, term = 1.0;
    for (int n = 1; n < 30; ++n) {
        term /= n;
        exp_xy += term / n;
    }
    const double bump = gaussian_integral(0.45, 0.12) * gaussian_integral(0.55, 0.18);
    auto f_bump = [](double x, double y) {
        return std::exp(-(x - 0.45) * (x - 0.45) / (2.0 * 0.12 * 0.12) - (y - 0.55) * (y - 0.55) / (2.0 * 0.18 * 0.18));
    };
    const std::vector<double> spps = {16, 64, 256, 1024, 4096};
    const std::uint32_t replicates = 256;
    for (std::uint32_t dim :
         {static_cast<std::uint32_t>(DIM_PIXEL), static_cast<std::uint32_t>(DIM_PATH_START + 4 * DIMS_PER_BOUNCE + 5)})
        for (const auto& [sampler_label, sampler] : sampler_names()) {
            std::vector<double> mse_bump, mse_exp;
            for (double spp_d : spps) {
                auto spp = static_cast<std::uint32_t>(spp_d);
                std::vector<glm::vec2> p = points(sampler, spp, pixel_range(0, replicates), dim, false, 3);
                double sq_bump = 0.0, sq_exp = 0.0;
                for (std::uint32_t r = 0; r < replicates; ++r) {
                    double sb = 0.0, se = 0.0;
                    for (std::uint32_t k = 0; k < spp; ++k) {
                        const glm::vec2& u = p[static_cast<std::size_t>(r) * spp + k];
                        double x = u.x, y = u.y;
                        sb += f_bump(x, y);
                        se += std::exp(x * y);
                    }
                    sq_bump += (sb / spp - bump) * (sb / spp - bump);
                    sq_exp += (se / spp - exp_xy) * (se / spp - exp_xy);
                }
                mse_bump.push_back(sq_bump / replicates);
                mse_exp.push_back(sq_exp / replicates);
            }
            double slope_bump = loglog_slope(spps, mse_bump), slope_exp = loglog_slope(spps, mse_exp);
            std::printf("  %-15s dims %2u,%2u: log-log MSE slope: bump %.2f (MSE %.2g at 16 spp, %.2g at 4096), "
                        "exp(xy) %.2f (%.2g, %.2g)\n",
                        sampler_name(sampler).c_str(), dim, dim + 1, slope_bump, mse_bump.front(), mse_bump.back(),
                        slope_exp, mse_exp.front(), mse_exp.back());
            const std::string what = sampler_name(sampler) + " dims " + std::to_string(dim);
            switch (sampler) {
            case SamplerType::Independent:
                EXPECT_NEAR(slope_bump, -1.0, 0.2) << what;
                EXPECT_NEAR(slope_exp, -1.0, 0.2) << what;
                break;
            case SamplerType::MultiJittered:
                EXPECT_LE(slope_bump, -1.5) << what;
                EXPECT_LE(slope_exp, -1.3) << what; // see above
                break;
            case SamplerType::Jittered:
            case SamplerType::Sobol:
            case SamplerType::Hammersley:
                EXPECT_LE(slope_bump, -1.5) << what;
                EXPECT_LE(slope_exp, -1.5) << what;
                break;
            default: // n-rooks, halton: reported only
                break;
            }
        }
}

} // namespace
} // namespace pathcl::test_sampler_convergence
