// The delta lobes of kernels/closure/ (through tests/kernels/bsdf_test_kernels.cl):
// smooth glass split by the exact Fresnel factor, glass of ior 1, which materials skip
// light sampling, and the roughness sweep converging onto the ideal mirror and glass
// without NaN. Next to each test: the broken variant seen to fail it.
#include <cmath>
#include <cstddef>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "support/bsdf_harness.h"
#include "support/device_fixture.h"
#include "tables/layer_albedo.h"

namespace pathcl::test_bsdf_delta {
namespace {

using test::Albedo;
using test::conductor;
using test::dielectric;
using test::directional_albedo;
using test::full_program;
using test::incident;
using test::lambertian;
using test::layer_buffer;
using test::make_material;
using test::MaterialSpec;
using test::sample_bsdf;
using test::Samples;
using test::xyz;

TEST(BsdfDelta, SmoothGlassSplitsByExactFresnelAndConservesEnergy)
{
    // Ideal glass: reflection with probability F (exact Fresnel), refraction by Snell's
    // law otherwise, weights 1 and 1/eta^2 (radiance compressed into the denser medium),
    // so every energy-corrected weight is exactly 1. From inside beyond the critical
    // angle every sample reflects. Broken variant seen failing: Schlick's (1 - c)^5 in
    // place of the normalized exact Fresnel curve (the split and the TIR weights).
    MaterialSpec glass = dielectric(0.0f);
    for (bool front : {true, false})
        for (double c : {1.0, 0.8, 0.5, 0.3, 0.05}) {
            SCOPED_TRACE(std::string(front ? "outside" : "inside") + " cos " + std::to_string(c));
            Material m = make_material(glass);
            double eta = front ? 1.5 : 1.0 / 1.5;
            glm::dvec3 wo = incident(c);
            const std::size_t n = 100000;
            Samples s = sample_bsdf(full_program(), m, wo, front, n, 5);
            double fresnel = fresnel_dielectric(c, eta);
            std::size_t reflected = 0, bad_dir = 0, bad_weight = 0, not_delta = 0;
            double sin2_t = (1.0 - c * c) / (eta * eta);
            glm::dvec3 refl(-wo.x, -wo.y, wo.z);
            glm::dvec3 refr =
                sin2_t < 1.0 ? glm::dvec3(-wo.x / eta, -wo.y / eta, -std::sqrt(1.0 - sin2_t)) : glm::dvec3(0.0);
            for (std::size_t i = 0; i < n; ++i) {
                glm::dvec3 d = xyz(s.dir_pdf[i]), w = xyz(s.weight[i]);
                not_delta += s.weight[i].w != 1.0f;
                bool is_refl = d.z > 0.0;
                reflected += is_refl;
                bad_dir += glm::length(d - (is_refl ? refl : refr)) > 1e-5;
                double expected_w = is_refl ? 1.0 : 1.0 / (eta * eta);
                bad_weight += std::abs(w.x - expected_w) > 1e-5 * expected_w;
            }
            EXPECT_EQ(not_delta, 0u);
            EXPECT_EQ(bad_dir, 0u);
            EXPECT_EQ(bad_weight, 0u);
            double frac = static_cast<double>(reflected) / n, sigma = std::sqrt(fresnel * (1.0 - fresnel) / n);
            EXPECT_NEAR(frac, fresnel, 5.0 * sigma + 1e-9);
        }
}

TEST(BsdfDelta, GlassOfIorOneIsInvisibleAndMirrorsSkipLightSampling)
{
    // ior 1: no reflection, every ray passes straight on with weight 1.
    Material m = make_material(dielectric(0.0f, 1.0f));
    glm::dvec3 wo = incident(0.4);
    Samples s = sample_bsdf(full_program(), m, wo, true, 10000);
    for (std::size_t i = 0; i < s.dir_pdf.size(); ++i) {
        ASSERT_LT(glm::length(xyz(s.dir_pdf[i]) + wo), 1e-6);
        ASSERT_NEAR(s.weight[i].x, 1.0f, 1e-6);
    }
    // Light sampling is skipped exactly where every lobe is a delta function.
    ClDevice& dev = test::test_device();
    auto is_delta = [&](const MaterialSpec& spec) {
        cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, sizeof(cl_int));
        cl::Kernel k(full_program(), "test_bsdf_is_delta");
        set_kernel_args(k, make_material(spec), layer_buffer(), out);
        dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(1));
        cl_int v = 0;
        dev.queue.enqueueReadBuffer(out, CL_TRUE, 0, sizeof v, &v);
        return v != 0;
    };
    MaterialSpec coated = lambertian(glm::vec3(0.5f));
    coated.specular = 1.0f;
    coated.roughness = 0.0f;
    EXPECT_TRUE(is_delta(conductor(0.0f)));
    EXPECT_TRUE(is_delta(dielectric(0.0f)));
    EXPECT_FALSE(is_delta(conductor(0.1f)));
    EXPECT_FALSE(is_delta(coated)); // the diffuse base still gets light samples
}

TEST(BsdfRoughness, SweepConvergesToTheDeltaLobesWithoutNaN)
{
    // alpha from 1e-1 down to 1e-7 (below 1e-3 the lobes are delta functions): the
    // albedo and the mean direction move continuously onto the ideal mirror and glass,
    // and nothing is ever NaN or infinite, down to cos 0.05. Broken variant seen
    // failing: an ideal mirror whose Fresnel factor is taken at normal incidence (the
    // delta lobe no longer the limit of the rough one: the gap grows as alpha shrinks).
    auto metal = [](float r) { return conductor(r, {0.9f, 0.6f, 0.3f}); };
    auto glass = [](float r) { return dielectric(r); };
    for (double c : {0.8, 0.3, 0.05})
        for (int kind = 0; kind < 3; ++kind) {
            bool front = kind != 2;
            auto make = [&](float r) { return kind == 0 ? metal(r) : glass(r); };
            SCOPED_TRACE("kind " + std::to_string(kind) + " cos " + std::to_string(c));
            Albedo delta = directional_albedo(full_program(), make(0.0f), c, front, true, 20000);
            double previous_gap = 1e30;
            for (double alpha : {1e-1, 1e-2, 1.01e-3}) {
                Albedo a = directional_albedo(full_program(), make(static_cast<float>(std::sqrt(alpha))), c, front,
                                              true, 100000);
                EXPECT_EQ(a.not_finite, 0u) << "alpha " << alpha;
                double gap = std::abs(a.mean.x - delta.mean.x);
                EXPECT_LE(gap, previous_gap + 5.0 * a.stderr_.x) << "alpha " << alpha;
                previous_gap = gap;
            }
            EXPECT_LT(previous_gap, 0.01 + 5.0 * delta.stderr_.x) << "alpha 1e-3 vs delta";
            for (double alpha : {9.9e-4, 1e-5, 1e-7}) {
                Albedo a = directional_albedo(full_program(), make(static_cast<float>(std::sqrt(alpha))), c, front,
                                              true, 20000);
                EXPECT_EQ(a.not_finite, 0u) << "alpha " << alpha;
            }
        }
}

} // namespace
} // namespace pathcl::test_bsdf_delta
