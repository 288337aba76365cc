// The dielectric layer's albedo table (host/render/layer_albedo.h), generated at build
// time, against independent computations: its integration against a brute-force
// Monte Carlo mean, the table against the integration at finer settings, and the
// smooth interface's averages against closed-form values.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include "closure/layer_table.h"
#include "render/layer_albedo.h"
#include "support/reference_bsdf.h"
#include "types.h"

namespace pathcl {
namespace {

constexpr double kPi = std::numbers::pi;

double fresnel(double c, double eta)
{
    double s2 = (1.0 - c * c) / (eta * eta);
    if (s2 >= 1.0)
        return 1.0;
    double ct = std::sqrt(1.0 - s2), rs = (c - eta * ct) / (c + eta * ct), rp = (eta * c - ct) / (eta * c + ct);
    return 0.5 * (rs * rs + rp * rp);
}

// Albedo of the GGX reflection lobe by uniform sampling of wi over the hemisphere: a
// different estimator (no visible normals, no change of variables) for the same integral.
LayerAlbedo brute_force(double mu, double roughness, double eta, int n)
{
    double a = roughness * roughness;
    glm::dvec3 wo(std::sqrt(1.0 - mu * mu), 0.0, mu);
    auto g1 = [&](const glm::dvec3& w) { return test::ggx_g1(w, a); };
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double e = 0.0, b = 0.0;
    double r0 = (eta - 1.0) / (eta + 1.0), f0 = r0 * r0;
    for (int i = 0; i < n; ++i) {
        double z = u(rng), phi = 2.0 * kPi * u(rng), r = std::sqrt(1.0 - z * z);
        glm::dvec3 wi(r * std::cos(phi), r * std::sin(phi), z);
        glm::dvec3 h = glm::normalize(wo + wi);
        double f_cos = test::ggx_d(h, a) * g1(wo) * g1(wi) / (4.0 * mu); // f cos_i, Fresnel 1
        double w = f_cos * 2.0 * kPi;                                    // / uniform pdf 1 / (2 pi)
        e += w;
        double c = glm::dot(wo, h);
        // eta 0: KHR_materials_ior's ior 0, Schlick's curve.
        b += w * (eta == 0.0 ? std::pow(1.0 - c, 5.0) : std::clamp((fresnel(c, eta) - f0) / (1.0 - f0), 0.0, 1.0));
    }
    return {e / n, b / n};
}

TEST(LayerAlbedo, IntegrationAgreesWithABruteForceEstimate)
{
    // Rough lobes only (a uniform estimator cannot resolve narrow ones in 4e6 samples).
    for (double mu : {0.2, 0.6, 0.95})
        for (double r : {0.5, 0.8, 1.0}) {
            for (double eta : {1.5, 0.0}) {
                LayerAlbedo q = integrate_layer_albedo(mu, r, eta);
                LayerAlbedo m = brute_force(mu, r, eta, 4000000);
                EXPECT_NEAR(q.e_ss, m.e_ss, 3e-3) << "mu " << mu << " roughness " << r;
                EXPECT_NEAR(q.b, m.b, 1e-3) << "mu " << mu << " roughness " << r << " eta " << eta;
            }
        }
}

// Energy albedo of a rough dielectric interface estimated as Walter et al. (2007) sample
// it: a facet normal from D(m) cos(m) (all facets, not the visible ones), reflection with
// probability F at it and refraction otherwise; the weight is G1(wo) G1(wi) |wo.m| /
// (cos_o cos_m). A different estimator for the same integral. Returns mean and error.
std::pair<double, double> walter_estimate(double mu, double roughness, double eta, int n)
{
    double a = roughness * roughness, a2 = a * a;
    glm::dvec3 wo(std::sqrt(1.0 - mu * mu), 0.0, mu);
    auto g1 = [&](const glm::dvec3& w) { return test::ggx_g1(w, a); };
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double sum = 0.0, sum_sq = 0.0;
    for (int i = 0; i < n; ++i) {
        // GGX: tan^2(theta_m) = a2 u / (1 - u), phi uniform.
        double v = u(rng), t2 = a2 * v / (1.0 - v), cm = 1.0 / std::sqrt(1.0 + t2), sm = std::sqrt(1.0 - cm * cm);
        double phi = 2.0 * kPi * u(rng);
        glm::dvec3 m(sm * std::cos(phi), sm * std::sin(phi), cm);
        double c = glm::dot(wo, m);
        if (c <= 0.0)
            continue; // a back-facing facet: weight 0
        double f = fresnel(c, eta);
        glm::dvec3 wi;
        if (u(rng) < f) {
            wi = 2.0 * c * m - wo;
            if (wi.z <= 0.0)
                continue;
        } else {
            double s2 = (1.0 - c * c) / (eta * eta);
            wi = -wo / eta + (c / eta - std::sqrt(1.0 - s2)) * m; // F < 1: no TIR here
            if (wi.z >= 0.0)
                continue;
        }
        double w = g1(wo) * g1(wi) * c / (mu * cm);
        sum += w;
        sum_sq += w * w;
    }
    double mean = sum / n;
    return {mean, std::sqrt((sum_sq / n - mean * mean) / n)};
}

TEST(LayerAlbedo, InterfaceAlbedoAgreesWithAnIndependentEstimate)
{
    // From outside (eta 1.5) and inside (1 / 1.5), where total internal reflection sends
    // the light back: reflection plus refraction, less the energy masking loses.
    for (double eta : {1.5, 1.0 / 1.5})
        for (double mu : {0.3, 0.8})
            for (double r : {0.5, 1.0}) {
                double q = integrate_dielectric_albedo(mu, r, eta);
                auto [m, se] = walter_estimate(mu, r, eta, 2000000);
                EXPECT_LT(se, 2e-3);
                EXPECT_NEAR(q, m, 5.0 * se + 1e-4) << "eta " << eta << " mu " << mu << " roughness " << r;
                EXPECT_LT(q, 1.0);
            }
    EXPECT_NEAR(integrate_dielectric_albedo(0.5, 0.0, 1.5), 1.0, 1e-6); // smooth: nothing lost
}

TEST(LayerAlbedo, SmoothLayerAverageMatchesClosedFormAndLimits)
{
    // eta 1: no interface, nothing reflected.
    EXPECT_NEAR(smooth_layer_average(1.0), 0.0, 1e-12);
    // The cosine-weighted hemispherical average of the exact Fresnel reflectance of glass
    // (eta 1.5, from outside) is 0.091778 (a 2e5-point midpoint rule in Python, written
    // separately); s_avg = (F_avg - F0) / (1 - F0).
    double f0 = 0.04, f_avg = f0 + (1.0 - f0) * smooth_layer_average(1.5);
    EXPECT_NEAR(f_avg, 0.091778, 1e-6);
    // ior 0: Schlick's curve, 2 int mu (1 - mu)^5 dmu = 2 B(2, 6) = 1/21.
    EXPECT_NEAR(smooth_layer_average(0.0), 1.0 / 21.0, 1e-12);
}

TEST(LayerAlbedo, TableMatchesTheIntegrationAtItsGridPoints)
{
    const std::vector<float>& t = layer_albedo_table();
    ASSERT_EQ(t.size(), static_cast<std::size_t>(LAYER_TABLE_SIZE));
    // Smooth row: E_ss 1. Rough rows: E_ss in (0, 1], B in [0, E_ss].
    for (int i = 0; i < LAYER_MU_RES; ++i)
        EXPECT_EQ(t[LAYER_TABLE_ESS + i], 1.0f);
    for (int k = 0; k < LAYER_B_ROWS; ++k)
        for (int j = 0; j < LAYER_ROUGH_RES; ++j)
            for (int i = 0; i < LAYER_MU_RES; ++i) {
                float e = t[LAYER_TABLE_ESS + j * LAYER_MU_RES + i];
                float b = t[LAYER_TABLE_B + (k * LAYER_ROUGH_RES + j) * LAYER_MU_RES + i];
                ASSERT_TRUE(e > 0.0f && e <= 1.0f + 1e-6f && b >= 0.0f && b <= e + 1e-6f) << i << " " << j << " " << k;
            }
    // The interface tables: 1 for the smooth row, in (0, 1] elsewhere.
    for (int side : {LAYER_TABLE_GLASS_OUT, LAYER_TABLE_GLASS_IN})
        for (int k = 0; k < LAYER_GLASS_ETA_RES; ++k)
            for (int j = 0; j < LAYER_ROUGH_RES; ++j)
                for (int i = 0; i < LAYER_MU_RES; ++i) {
                    float g = t[side + (k * LAYER_ROUGH_RES + j) * LAYER_MU_RES + i];
                    ASSERT_TRUE(j == 0 ? g == 1.0f : (g > 0.0f && g <= 1.0f + 1e-6f)) << side << " " << i << " " << j;
                }
    // A few entries recomputed with four times the panels.
    for (int i : {3, 17, 31})
        for (int j : {1, 9, 20, 31})
            for (int k : {0, 11, 31, LAYER_ETA_RES}) { // and the Schlick row (eta 0)
                double mu = std::max(std::pow(static_cast<double>(i) / (LAYER_MU_RES - 1), 2.0), 1e-6);
                double r = static_cast<double>(j) / (LAYER_ROUGH_RES - 1);
                double x = static_cast<double>(LAYER_X_MAX) * k / (LAYER_ETA_RES - 1);
                double eta = k == LAYER_ETA_RES ? 0.0 : (1 + x) / (1 - x);
                LayerAlbedo fine = integrate_layer_albedo(mu, r, eta, 128);
                EXPECT_NEAR(t[LAYER_TABLE_ESS + j * LAYER_MU_RES + i], fine.e_ss, 2e-4) << i << " " << j;
                EXPECT_NEAR(t[LAYER_TABLE_B + (k * LAYER_ROUGH_RES + j) * LAYER_MU_RES + i], fine.b, 2e-4)
                    << i << " " << j << " " << k;
            }
    for (int i : {3, 17, 31})
        for (int j : {1, 9, 20, 31})
            for (int k : {0, 7, 15}) {
                double mu = std::max(std::pow(static_cast<double>(i) / (LAYER_MU_RES - 1), 2.0), 1e-6);
                double r = static_cast<double>(j) / (LAYER_ROUGH_RES - 1);
                double x = static_cast<double>(LAYER_X_MAX) * k / (LAYER_GLASS_ETA_RES - 1), ior = (1 + x) / (1 - x);
                std::size_t at = static_cast<std::size_t>((k * LAYER_ROUGH_RES + j) * LAYER_MU_RES + i);
                EXPECT_NEAR(t[LAYER_TABLE_GLASS_OUT + at], integrate_dielectric_albedo(mu, r, ior, 64), 1e-3)
                    << i << " " << j << " " << k;
                EXPECT_NEAR(t[LAYER_TABLE_GLASS_IN + at], integrate_dielectric_albedo(mu, r, 1.0 / ior, 64), 1e-3)
                    << i << " " << j << " " << k;
            }
    // The sheen's albedo: the smoothest row at grazing, and a few more, with eight times the
    // panels (its steepest entries, at roughness 0 and cos 1e-6, included).
    for (int i : {0, 1, 3, 17, 31})
        for (int j : {0, 1, 9, 31}) {
            double mu = std::max(std::pow(static_cast<double>(i) / (LAYER_MU_RES - 1), 2.0), 1e-6);
            double r = static_cast<double>(j) / (LAYER_ROUGH_RES - 1);
            float e = t[LAYER_TABLE_SHEEN + j * LAYER_MU_RES + i];
            EXPECT_NEAR(e, integrate_sheen_albedo(mu, r, 64), 1e-4 * std::max(1.0, static_cast<double>(e)))
                << i << " " << j;
        }
}

} // namespace
} // namespace pathcl
