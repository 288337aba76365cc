// Chi-square tests of every sampling routine of kernels/closure/ (through
// tests/kernels/bsdf_test_kernels.cl) against an independent double-precision pdf
// (tests/support/reference_bsdf.h), with each sample's pdf, f cos and weight = f cos / pdf
// checked against it. Next to each test: the broken variants seen to fail it.
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "support/bsdf_harness.h"
#include "support/chi_square.h"
#include "support/reference_bsdf.h"

namespace pathcl::test_bsdf_sampling {
namespace {

using test::conductor;
using test::dielectric;
using test::full_program;
using test::incident;
using test::lambertian;
using test::lambertian_program;
using test::make_material;
using test::MaterialSpec;
using test::near_rel;
using test::sample_bsdf;
using test::Samples;
using test::xyz;

constexpr std::size_t kChiSquareSamples = 1000000;
// Chi-square tests run by this file, for the Šidák correction: Lambertian 1, conductor
// 9, dielectric 4, mixtures 5, clear coat 6, sheen 5, anisotropy 5. Each also checks every
// sample's pdf, f and weight.
constexpr int kChiSquareTests = 35;

// Sampled non-delta directions; delta samples and failures are zero vectors, which the
// chi-square harness counts as "no sample" (the pdf integrates to 1 minus their share).
std::vector<glm::dvec3> continuous_directions(const Samples& s)
{
    std::vector<glm::dvec3> d(s.dir_pdf.size(), glm::dvec3(0.0));
    for (std::size_t i = 0; i < d.size(); ++i)
        if (s.dir_pdf[i].w > 0.0f && s.weight[i].w == 0.0f)
            d[i] = xyz(s.dir_pdf[i]);
    return d;
}

// Chi-square of the kernel's sampler against the reference pdf, and the kernel's own
// sample pdf, eval pdf and weight checked sample by sample: sample pdf = eval pdf = the
// reference pdf, weight = eval f_cos / eval pdf, f_cos = the reference's.
void expect_sampling_matches(const cl::Program& program, const MaterialSpec& spec, double cos_o, bool front_face,
                             const std::string& what, int theta_res = 20, int phi_res = 40)
{
    SCOPED_TRACE(what);
    Material m = make_material(spec);
    test::ReferenceBsdf ref = test::ReferenceBsdf::from_material(m, front_face);
    glm::dvec3 wo = incident(cos_o);
    Samples s = sample_bsdf(program, m, wo, front_face, kChiSquareSamples);
    auto pdf = [&](const glm::dvec3& wi) { return ref.pdf(wo, wi); };
    test::ChiSquareResult r =
        test::chi_square_directions(continuous_directions(s), pdf, theta_res, phi_res, 0.01, kChiSquareTests);
    EXPECT_TRUE(r.passed) << r.summary();

    std::size_t checked = 0, bad_pdf = 0, bad_weight = 0, bad_f = 0, not_finite = 0, near_critical = 0;
    std::string first_bad;
    for (std::size_t i = 0; i < s.dir_pdf.size(); ++i) {
        const pcl_float4 &d = s.dir_pdf[i], &w = s.weight[i], &e = s.eval[i];
        if (!(d.w > 0.0f) || w.w != 0.0f)
            continue;
        if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z) || !std::isfinite(d.w)) {
            ++not_finite;
            continue;
        }
        ++checked;
        glm::dvec3 wi = glm::normalize(xyz(d));
        double host_pdf = ref.pdf(wo, wi);
        glm::dvec3 host_f = ref.f_cos(wo, wi);
        // Refraction out of a solid within ~1e-5 of the critical angle (wi nearly tangent
        // to the microfacet): 1 - F, which weighs both f and the refraction's share of the
        // pdf, changes by percents with the last float bit of the microfacet's cosine, so
        // float and double legitimately differ there.
        bool ill_conditioned = false;
        if (wi.z < 0.0 && !ref.thin) {
            glm::dvec3 facet = glm::normalize(wi * ref.eta + wo);
            ill_conditioned = std::abs(glm::dot(wi, facet)) < 0.02;
        }
        near_critical += ill_conditioned;
        bool pdf_ok = near_rel(d.w, e.w, 1e-5) && (ill_conditioned || near_rel(d.w, host_pdf, 2e-3));
        bool f_ok = true, w_ok = true;
        for (int c = 0; c < 3; ++c) {
            double ef = (&e.x)[c], wf = (&w.x)[c];
            f_ok = f_ok && (ill_conditioned || near_rel(ef, host_f[c], 2e-3, 1e-7 * host_pdf));
            // (A floor: the sheen's pow(sin^2 theta_h, 1 / (2 alpha)) turns the rounding of a
            // nearly cancelling wo + wi into relative differences of tiny values.)
            w_ok = w_ok && near_rel(wf, ef / e.w, 1e-4, 1e-6);
        }
        bad_pdf += !pdf_ok;
        bad_f += !f_ok;
        bad_weight += !w_ok;
        if ((!pdf_ok || !f_ok || !w_ok) && first_bad.empty())
            first_bad = "wi (" + std::to_string(wi.x) + ", " + std::to_string(wi.y) + ", " + std::to_string(wi.z) +
                        "): sample pdf " + std::to_string(d.w) + ", eval pdf " + std::to_string(e.w) +
                        ", reference pdf " + std::to_string(host_pdf) + "; eval f_cos.r " + std::to_string(e.x) +
                        ", reference " + std::to_string(host_f.x) + "; weight.r " + std::to_string(w.x);
    }
    EXPECT_GT(checked, s.dir_pdf.size() / 10);
    EXPECT_LT(near_critical, checked / 1000 + 1) << "too many samples near the critical angle to skip";
    EXPECT_EQ(not_finite, 0u);
    EXPECT_EQ(bad_pdf, 0u) << "of " << checked << "; first: " << first_bad;
    EXPECT_EQ(bad_f, 0u) << "of " << checked << "; first: " << first_bad;
    EXPECT_EQ(bad_weight, 0u) << "of " << checked << "; first: " << first_bad;
}

TEST(BsdfSampling, LambertianMatchesCosineDensity)
{
    // The Lambertian-only program (what a diffuse scene compiles). Broken variant seen
    // failing: uniform instead of cosine hemisphere sampling (X^2 = 9e5, 399 dof).
    expect_sampling_matches(lambertian_program(), lambertian({0.7f, 0.5f, 0.3f}), 0.6, true, "lambertian");
}

TEST(BsdfSampling, RoughConductorMatchesVisibleNormalDensity)
{
    // Broken variants seen failing: visible normals sampled without the alpha stretch of
    // wo (chi-square, X^2 from 2.6e4 to 1.1e6); a pdf without the 1/(4 wo.h) Jacobian (the
    // sample-by-sample pdf check).
    for (float alpha : {0.05f, 0.25f, 0.7f})
        for (double c : {0.9, 0.5, 0.05})
            expect_sampling_matches(full_program(), conductor(std::sqrt(alpha), {0.9f, 0.6f, 0.3f}), c, true,
                                    "conductor alpha " + std::to_string(alpha) + " cos " + std::to_string(c));
}

TEST(BsdfSampling, RoughDielectricFromOutsideInsideAndUnderTotalInternalReflection)
{
    // A solid (KHR_materials_volume) rough glass, alpha 0.25. From inside eta = 1/1.5:
    // at cos 0.8 part of the microfacets reflect totally, at cos 0.3 (beyond the 41.8
    // degree critical angle) most do. Broken variants seen failing: refraction with eta
    // inverted (chi-square); the transmission Jacobian with (wi.m + wo.m) in place of
    // (wi.m + wo.m / eta) (the pdf check).
    MaterialSpec glass = dielectric(0.5f);
    expect_sampling_matches(full_program(), glass, 0.6, true, "rough glass from outside");
    expect_sampling_matches(full_program(), glass, 0.05, true, "rough glass from outside, grazing");
    expect_sampling_matches(full_program(), glass, 0.8, false, "rough glass from inside");
    expect_sampling_matches(full_program(), glass, 0.3, false, "rough glass from inside, mostly TIR");
}

TEST(BsdfSampling, GltfMixturesMatchTheirPdf)
{
    // Several lobes at once: the lobe choice probabilities must be in the pdf. Broken
    // variant seen failing: a diffuse pdf without its lobe probability (the pdf check).
    MaterialSpec half_metal = conductor(0.6f, {0.8f, 0.4f, 0.2f});
    half_metal.metallic = 0.5f;
    expect_sampling_matches(full_program(), half_metal, 0.7, true, "metallic 0.5, roughness 0.6");

    MaterialSpec plastic;
    plastic.base = {0.2f, 0.5f, 0.8f};
    plastic.metallic = 0.0f;
    plastic.roughness = 0.35f;
    plastic.specular = 0.7f;
    plastic.specular_color = {1.0f, 0.5f, 2.0f};
    expect_sampling_matches(full_program(), plastic, 0.4, true, "dielectric with coloured specular");

    MaterialSpec sheet = dielectric(0.45f, 1.4f, /*thin=*/true);
    sheet.transmission = 0.6f;
    sheet.base = {0.9f, 0.8f, 0.7f};
    expect_sampling_matches(full_program(), sheet, 0.5, true, "thin-walled rough transmission 0.6");

    MaterialSpec spec_gloss = plastic; // KHR_materials_ior 0: Schlick's curve from the specular colour
    spec_gloss.ior = 0.0f;
    spec_gloss.specular = 1.0f;
    spec_gloss.specular_color = {0.6f, 0.4f, 0.2f};
    expect_sampling_matches(full_program(), spec_gloss, 0.6, true, "specular-glossiness (ior 0)");

    MaterialSpec coated = lambertian({0.6f, 0.6f, 0.6f});
    coated.specular = 1.0f;
    coated.roughness = 0.0f; // diffuse plus a delta coat: only the diffuse part is tested here
    expect_sampling_matches(full_program(), coated, 0.5, true, "diffuse under a smooth coat");
}

TEST(BsdfSampling, ClearcoatMatchesItsPdf)
{
    // The coat is a fourth lobe, sampled in the same frame here: its selection
    // probability and the base's scaled ones must be in the pdf. Broken variant seen
    // failing: the coat's pdf left out of bsdf_eval (chi-square and pdf checks).
    MaterialSpec plastic = lambertian({0.7f, 0.3f, 0.1f});
    plastic.specular = 1.0f;
    plastic.roughness = 0.5f;
    plastic.clearcoat = 1.0f;
    plastic.clearcoat_roughness = 0.2f;
    expect_sampling_matches(full_program(), plastic, 0.6, true, "rough coat over a plastic");
    expect_sampling_matches(full_program(), plastic, 0.1, true, "rough coat over a plastic, grazing");

    MaterialSpec metal = conductor(0.4f, {0.95f, 0.7f, 0.4f});
    metal.clearcoat = 0.5f;
    metal.clearcoat_roughness = 0.6f;
    expect_sampling_matches(full_program(), metal, 0.8, true, "part coat over a rough metal");

    MaterialSpec glass = dielectric(0.4f);
    glass.clearcoat = 1.0f;
    glass.clearcoat_roughness = 0.25f;
    expect_sampling_matches(full_program(), glass, 0.7, true, "rough coat over rough glass, outside");
    expect_sampling_matches(full_program(), glass, 0.7, false, "rough coat over rough glass, inside");

    MaterialSpec lacquer = plastic; // a delta coat: only the base is sampled continuously
    lacquer.clearcoat_roughness = 0.0f;
    expect_sampling_matches(full_program(), lacquer, 0.5, true, "smooth coat over a plastic");
}

TEST(BsdfSampling, SheenMatchesItsPdf)
{
    // The sheen is sampled uniformly over the hemisphere as one more lobe; the base lobes'
    // selection is scaled by what the sheen passes. Broken variant seen failing: the
    // sheen's pdf left out of bsdf_eval.
    MaterialSpec velvet = lambertian({0.5f, 0.1f, 0.1f});
    velvet.sheen = {0.9f, 0.8f, 0.9f};
    velvet.sheen_roughness = 0.4f;
    expect_sampling_matches(full_program(), velvet, 0.7, true, "velvet");
    expect_sampling_matches(full_program(), velvet, 0.05, true, "velvet, grazing");

    MaterialSpec metal = conductor(0.3f, {0.9f, 0.6f, 0.3f});
    metal.sheen = {1.0f, 1.0f, 1.0f};
    metal.sheen_roughness = 0.08f; // albedo above 1 near grazing: the lobe is divided
    expect_sampling_matches(full_program(), metal, 0.1, true, "smooth sheen over a rough metal");

    MaterialSpec coated = velvet; // under a rough coat
    coated.specular = 1.0f;
    coated.roughness = 0.5f;
    coated.clearcoat = 1.0f;
    coated.clearcoat_roughness = 0.3f;
    expect_sampling_matches(full_program(), coated, 0.4, true, "sheen under a rough coat");

    MaterialSpec glass = dielectric(0.4f); // from inside the sheen only scales the base
    glass.sheen = {0.7f, 0.7f, 0.7f};
    glass.sheen_roughness = 0.5f;
    expect_sampling_matches(full_program(), glass, 0.7, false, "sheen over rough glass, inside");
}

TEST(BsdfSampling, AnisotropyMatchesItsPdf)
{
    // KHR_materials_anisotropy: the visible normals of the stretched distribution, for the
    // conductor and the dielectric layer alike (and a thin sheet's lobe pair); a solid's
    // transmitting interface stays isotropic. wo's azimuth is 0.3 rad from the direction.
    // Broken variants seen failing: the visible-normal stretch with alpha_b along x
    // (chi-square); G1 with the isotropic alpha (the pdf check); the dielectric layer's
    // facets sampled isotropically under its anisotropic lobe (brushed plastic).
    MaterialSpec brushed = conductor(0.3f, {0.95f, 0.9f, 0.85f});
    brushed.anisotropy = 0.8f;
    expect_sampling_matches(full_program(), brushed, 0.7, true, "brushed metal");
    expect_sampling_matches(full_program(), brushed, 0.1, true, "brushed metal, grazing");

    MaterialSpec streak = conductor(0.0f, {0.9f, 0.6f, 0.3f}); // alpha 1e-3 across, 0.36 along
    streak.anisotropy = 0.6f;
    expect_sampling_matches(full_program(), streak, 0.5, true, "smooth metal made rough along one axis");

    MaterialSpec half = conductor(0.4f, {0.9f, 0.5f, 0.2f}); // with a rough dielectric layer over a diffuse base
    half.metallic = 0.5f;
    half.anisotropy = 0.7f;
    expect_sampling_matches(full_program(), half, 0.6, true, "half metal, half plastic");

    MaterialSpec coated = brushed; // under a clear coat
    coated.clearcoat = 1.0f;
    coated.clearcoat_roughness = 0.2f;
    expect_sampling_matches(full_program(), coated, 0.5, true, "brushed metal under a rough coat");

    MaterialSpec plastic = lambertian({0.2f, 0.4f, 0.8f}); // the dielectric layer anisotropic
    plastic.specular = 1.0f;
    plastic.roughness = 0.15f;
    plastic.anisotropy = 0.7f;
    expect_sampling_matches(full_program(), plastic, 0.6, true, "brushed plastic");
    expect_sampling_matches(full_program(), plastic, 0.1, true, "brushed plastic, grazing");

    MaterialSpec lacquer = plastic; // smooth, made rough along one axis
    lacquer.roughness = 0.0f;
    lacquer.anisotropy = 0.5f;
    expect_sampling_matches(full_program(), lacquer, 0.5, true, "smooth plastic made rough along one axis");

    MaterialSpec sheet = dielectric(0.2f, 1.5f, true); // a thin sheet's anisotropic lobe pair
    sheet.transmission = 0.8f;
    sheet.anisotropy = 0.6f;
    expect_sampling_matches(full_program(), sheet, 0.7, true, "brushed thin sheet");

    MaterialSpec glass = dielectric(0.3f); // a solid: its interface stays isotropic
    glass.anisotropy = 0.6f;
    expect_sampling_matches(full_program(), glass, 0.7, true, "brushed glass, isotropic interface");
}

} // namespace
} // namespace pathcl::test_bsdf_sampling
