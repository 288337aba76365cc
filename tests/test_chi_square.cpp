// The chi-square harness itself, on host samplers with known densities: it must accept
// correct sampler/pdf pairs and reject wrong ones, or the sampling tests built on it
// prove nothing.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "support/chi_square.h"

namespace pathcl::test::test_chi_square {
namespace {

constexpr double pi = std::numbers::pi;
constexpr std::size_t sample_count = 1000000;

// count directions from sampler(u1, u2), u uniform in [0, 1).
template <class Sampler>
std::vector<glm::dvec3> draw(std::uint32_t seed, std::size_t count, Sampler sampler)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<glm::dvec3> out;
    out.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        double u1 = uniform(rng), u2 = uniform(rng);
        out.push_back(sampler(u1, u2));
    }
    return out;
}

glm::dvec3 uniform_sphere(double u1, double u2)
{
    double z = 1.0 - 2.0 * u1, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * pi * u2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

glm::dvec3 cosine_hemisphere(double u1, double u2)
{
    double r = std::sqrt(u1), phi = 2.0 * pi * u2;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1))};
}

// Local (tangent, bitangent, n) coordinates to world.
glm::dvec3 to_world(const glm::dvec3& n, const glm::dvec3& local)
{
    glm::dvec3 a = std::abs(n.x) > 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    glm::dvec3 t = glm::normalize(glm::cross(a, n)), b = glm::cross(n, t);
    return local.x * t + local.y * b + local.z * n;
}

double uniform_sphere_pdf(const glm::dvec3&)
{
    return 1.0 / (4.0 * pi);
}
double cosine_pdf(const glm::dvec3& d)
{
    return std::max(0.0, d.z) / pi;
}

TEST(ChiSquare, UniformSpherePasses)
{
    auto r = chi_square_directions(draw(1, sample_count, uniform_sphere), uniform_sphere_pdf);
    EXPECT_TRUE(r.passed) << r.summary();
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-9);
    EXPECT_EQ(r.degrees_of_freedom, 199);
}

TEST(ChiSquare, CosineHemispherePasses)
{
    auto r = chi_square_directions(draw(2, sample_count, cosine_hemisphere), cosine_pdf);
    EXPECT_TRUE(r.passed) << r.summary();
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-9);
}

TEST(ChiSquare, TiltedCosineHemispherePasses)
{
    // The horizon now cuts through cells, where the pdf has a kink the quadrature must follow.
    const glm::dvec3 n = glm::normalize(glm::dvec3(1, 2, 3));
    auto samples = draw(3, sample_count, [&](double u1, double u2) { return to_world(n, cosine_hemisphere(u1, u2)); });
    auto r = chi_square_directions(samples, [&](const glm::dvec3& d) { return std::max(0.0, glm::dot(d, n)) / pi; });
    EXPECT_TRUE(r.passed) << r.summary();
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-6);
}

TEST(ChiSquare, FailingSamplerWithScaledPdfPasses)
{
    auto samples = draw(4, sample_count, [](double u1, double u2) {
        // No sample 10% of the time; u1 rescaled so the kept samples stay uniform.
        return u1 < 0.1 ? glm::dvec3(0.0) : uniform_sphere((u1 - 0.1) / 0.9, u2);
    });
    auto r = chi_square_directions(samples, [](const glm::dvec3&) { return 0.9 / (4.0 * pi); });
    EXPECT_TRUE(r.passed) << r.summary();
    EXPECT_NEAR(r.pdf_integral, 0.9, 1e-3);
    // Binomial(1e6, 0.1): standard deviation 300.
    EXPECT_NEAR(static_cast<double>(r.samples_discarded), 1e5, 1500.0);
    EXPECT_EQ(r.samples_used + r.samples_discarded, sample_count);
}

TEST(ChiSquare, CosineSamplesFailAgainstUniformHemispherePdf)
{
    auto r = chi_square_directions(draw(5, sample_count, cosine_hemisphere),
                                   [](const glm::dvec3& d) { return d.z > 0.0 ? 1.0 / (2.0 * pi) : 0.0; });
    EXPECT_FALSE(r.passed) << r.summary();
    EXPECT_LT(r.p_value, 1e-100);
    EXPECT_NE(r.summary().find("disagree most"), std::string::npos) << r.summary();
}

TEST(ChiSquare, OctantBiasIsDetected)
{
    // The pdf claims 5% more density in the octant x, y, z > 0 than uniform sampling gives.
    // Noncentrality ~ n * delta^2 * 7/64 = 273 against 199 dof: the statistic lands near 470
    // where the 1% critical value is 249, so a miss is a > 5 sigma event (power > 0.99999).
    // A 1% bias (noncentrality 11) would be caught only ~3% of the time with 1e6 samples.
    constexpr double delta = 0.05;
    auto pdf = [&](const glm::dvec3& d) {
        bool octant = d.x > 0.0 && d.y > 0.0 && d.z > 0.0;
        return (octant ? 1.0 + delta : 1.0) / (4.0 * pi * (1.0 + delta / 8.0));
    };
    auto r = chi_square_directions(draw(6, sample_count, uniform_sphere), pdf);
    EXPECT_FALSE(r.passed) << r.summary();
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-9);
}

TEST(ChiSquare, SamplesWhereThePdfIsZeroFailOutright)
{
    auto r = chi_square_directions(draw(7, 100000, uniform_sphere),
                                   [](const glm::dvec3& d) { return d.z > 0.0 ? 1.0 / (2.0 * pi) : 0.0; });
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.diagnosis.find("pdf integrates to 0"), std::string::npos) << r.summary();
}

TEST(ChiSquare, SamplesOnTheHorizonAreNotAFailure)
{
    // Float directions can land exactly on (or a rounding error below) the edge of the
    // pdf's support; that must not count as a sample where the pdf is zero.
    auto samples = draw(8, 100000, cosine_hemisphere);
    samples.emplace_back(1.0, 0.0, 0.0);
    samples.push_back(glm::normalize(glm::dvec3(-1.0, 0.5, -1e-7)));
    auto r = chi_square_directions(samples, cosine_pdf);
    EXPECT_TRUE(r.passed) << r.summary();
    EXPECT_GE(r.samples_moved, 1u);
}

TEST(ChiSquare, InvalidSamplesAreDiscarded)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<glm::dvec3> samples = {{0, 0, 0}, {nan, 0, 0}, {0, 0, 1.01}, {0, 0, 1.0005}, {0, 0, -1}, {1, 0, 0}};
    auto r = chi_square_directions(samples, uniform_sphere_pdf);
    EXPECT_EQ(r.samples_discarded, 3u);
    EXPECT_EQ(r.samples_used, 3u);
    EXPECT_FALSE(r.passed); // far too few samples for a verdict
}

TEST(ChiSquare, SidakCorrectionLowersTheThreshold)
{
    auto r = chi_square_directions(draw(9, 10000, uniform_sphere), uniform_sphere_pdf, 4, 8, 0.01, 10);
    EXPECT_NEAR(r.threshold, 1.0 - std::pow(0.99, 0.1), 1e-15);
    EXPECT_TRUE(r.passed) << r.summary();
}

TEST(ChiSquare, IncompleteGammaKnownValues)
{
    for (double x : {0.01, 0.5, 1.0, 2.0, 7.5, 40.0})
        EXPECT_NEAR(regularized_gamma_q(1.0, x), std::exp(-x), 1e-14 * std::exp(-x) + 1e-15) << x;
    for (double x : {0.1, 1.0, 3.0}) // Q(1/2, x) = erfc(sqrt(x))
        EXPECT_NEAR(regularized_gamma_q(0.5, x), std::erfc(std::sqrt(x)), 1e-13) << x;
    EXPECT_EQ(regularized_gamma_q(3.0, 0.0), 1.0);
    // Chi-square table values: both branches (series below a + 1, continued fraction above).
    EXPECT_NEAR(chi_square_survival(18.307, 10), 0.05, 1e-4);
    EXPECT_NEAR(chi_square_survival(3.841, 1), 0.05, 1e-4);
    EXPECT_NEAR(chi_square_survival(3.940, 10), 0.95, 1e-4);
    EXPECT_NEAR(chi_square_survival(135.807, 100), 0.01, 1e-5);
    EXPECT_NEAR(chi_square_survival(124.342, 100), 0.05, 1e-5);
    EXPECT_NEAR(chi_square_survival(5.0, 2), std::exp(-2.5), 1e-14);
}

} // namespace
} // namespace pathcl::test::test_chi_square
