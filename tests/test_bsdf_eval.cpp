// bsdf_eval of kernels/closure/ (through tests/kernels/bsdf_test_kernels.cl): f cos and
// pdf equal the independent double-precision reference (tests/support/reference_bsdf.h)
// over the whole sphere, from both sides, and reflection is reciprocal. Next to each
// test: the broken variant seen to fail it.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "support/bsdf_harness.h"
#include "support/reference_bsdf.h"

namespace pathcl {
namespace {

using test::conductor;
using test::dielectric;
using test::diffuse_only_params;
using test::DiffuseOnlyRun;
using test::eval_bsdf;
using test::full_program;
using test::lambertian;
using test::lambertian_shortcut;
using test::make_material;
using test::MaterialSpec;
using test::near_rel;
using test::reflective_materials;
using test::ShortcutRun;

constexpr double kPi = std::numbers::pi;

// Uniform random directions on the sphere, or on the upper hemisphere.
std::vector<glm::dvec3> random_directions(std::size_t n, std::uint32_t seed, bool upper_only)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<glm::dvec3> out;
    while (out.size() < n) {
        double z = upper_only ? u(rng) : 2.0 * u(rng) - 1.0, phi = 2.0 * kPi * u(rng);
        double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        if (z == 0.0)
            continue;
        out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
    return out;
}

TEST(BsdfEval, AgreesWithTheReferenceModelEverywhere)
{
    // Random pairs over the whole sphere (reflection and transmission), from both sides
    // of a solid: the kernel's f cos and pdf equal the double-precision reference. The
    // normal is tilted so the kernels' basis code is exercised. Broken variant seen
    // failing: Schlick's (1 - c)^5 in place of the normalized exact Fresnel curve.
    std::vector<MaterialSpec> materials = reflective_materials();
    materials.push_back(dielectric(0.5f));
    materials.push_back(dielectric(0.2f, 1.33f));
    MaterialSpec sheet = dielectric(0.6f, 1.5f, true);
    sheet.transmission = 0.5f;
    materials.push_back(sheet);
    // KHR_materials_anisotropy on transmission: a thin sheet (its lobe pair anisotropic)
    // and a solid (its interface isotropic, in the anisotropic frame).
    MaterialSpec brushed_sheet = dielectric(0.2f, 1.5f, true);
    brushed_sheet.transmission = 0.7f;
    brushed_sheet.anisotropy = 0.6f;
    materials.push_back(brushed_sheet);
    MaterialSpec brushed_glass = dielectric(0.3f);
    brushed_glass.anisotropy = 0.6f;
    materials.push_back(brushed_glass);
    const glm::dvec3 normal = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
    glm::dvec3 t = glm::normalize(glm::cross(normal, glm::dvec3(1, 0, 0))), b = glm::cross(normal, t);
    auto to_world = [&](const glm::dvec3& v) { return v.x * t + v.y * b + v.z * normal; };
    std::vector<glm::dvec3> wo = random_directions(20000, 5, true), wi = random_directions(20000, 6, false);
    std::vector<glm::dvec3> wo_world, wi_world;
    for (std::size_t i = 0; i < wo.size(); ++i) {
        wo_world.push_back(to_world(wo[i]));
        wi_world.push_back(to_world(wi[i]));
    }
    for (std::size_t k = 0; k < materials.size(); ++k)
        for (bool front : {true, false}) {
            Material m = make_material(materials[k]);
            test::ReferenceBsdf ref = test::ReferenceBsdf::from_material(m, front);
            std::vector<pcl_float4> r = eval_bsdf(full_program(), m, front, wo_world, wi_world, normal, t);
            std::size_t bad = 0;
            std::string first;
            for (std::size_t i = 0; i < wo.size(); ++i) {
                // Local coordinates lose a few float ulps in the kernel's basis change:
                // compare away from where the lobes switch on and off (the horizon).
                if (std::abs(wi[i].z) < 1e-3 || wo[i].z < 1e-3)
                    continue;
                glm::dvec3 f = ref.f_cos(wo[i], wi[i]);
                double p = ref.pdf(wo[i], wi[i]);
                bool ok = near_rel(r[i].w, p, 2e-3, 1e-6);
                for (int c = 0; c < 3; ++c)
                    ok = ok && near_rel((&r[i].x)[c], f[c], 2e-3, 1e-6);
                if (!ok && first.empty())
                    first = "wo.z " + std::to_string(wo[i].z) + " wi.z " + std::to_string(wi[i].z) + ": kernel (" +
                            std::to_string(r[i].x) + ", pdf " + std::to_string(r[i].w) + ") reference (" +
                            std::to_string(f.x) + ", pdf " + std::to_string(p) + ")";
                bad += !ok;
            }
            EXPECT_EQ(bad, 0u) << "material " << k << (front ? " front" : " back") << ": " << first;
        }
}

TEST(BsdfEval, ReflectionIsReciprocal)
{
    // f(wo, wi) = f(wi, wo) for every reflective material (f = f_cos / cos theta_i).
    // Broken variant seen failing: the albedo-scaled diffuse weight with E(cos_o) in both
    // factors instead of E(cos_o) and E(cos_i).
    std::vector<glm::dvec3> a = random_directions(20000, 8, true), b = random_directions(20000, 9, true);
    for (std::size_t k = 0; auto spec : reflective_materials()) {
        Material m = make_material(spec);
        std::vector<pcl_float4> ab = eval_bsdf(full_program(), m, true, a, b);
        std::vector<pcl_float4> ba = eval_bsdf(full_program(), m, true, b, a);
        std::size_t bad = 0;
        for (std::size_t i = 0; i < a.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                double f1 = (&ab[i].x)[c] / b[i].z, f2 = (&ba[i].x)[c] / a[i].z;
                bad += !near_rel(f1, f2, 1e-4, 1e-7);
            }
        EXPECT_EQ(bad, 0u) << "material " << k;
        ++k;
    }
}

// Materials one step from exactly Lambertian (a black base, a specular layer, a coat, a
// sheen, a little metal) and two far from it: none may take a Lambertian shortcut.
std::vector<MaterialSpec> nearly_lambertian()
{
    MaterialSpec black = lambertian(glm::vec3(0.0f));
    MaterialSpec plastic = lambertian(glm::vec3(0.5f));
    plastic.specular = 0.5f;
    MaterialSpec coated = lambertian(glm::vec3(0.5f));
    coated.clearcoat = 0.5f;
    MaterialSpec velvet = lambertian(glm::vec3(0.5f));
    velvet.sheen = {0.5f, 0.5f, 0.5f};
    velvet.sheen_roughness = 0.5f;
    MaterialSpec part_metal = lambertian(glm::vec3(0.5f));
    part_metal.metallic = 0.1f;
    return {black, plastic, coated, velvet, part_metal, dielectric(0.3f), conductor(0.5f)};
}

TEST(BsdfEval, TheLambertianShortcutGivesEveryLobesValuesBitForBit)
{
    // A program with glossy code evaluates and samples an exactly Lambertian material
    // through bsdf_eval_lambertian and bsdf_sample_lambertian instead of every lobe's code
    // (renders are bit-identical across the change): the two must give the same bits for
    // the sample's direction, pdf and weight and for f cos and the pdf at any wi, from
    // either side, and no other material may take the shortcut. Broken variants seen
    // failing: the sample's weight as the Lambertian program's (the base colour); f cos
    // as base x (cos / pi); the predicate without the diffuse lobe's probability of 1
    // (a black base then takes it).
    const std::size_t n = 4096;
    std::vector<glm::dvec3> wo = random_directions(n, 21, false), wi = random_directions(n, 22, false);
    for (glm::vec3 base : {glm::vec3(0.8f), glm::vec3(0.9f, 0.35f, 0.05f), glm::vec3(0.01f, 0.02f, 0.5f)})
        for (bool front : {true, false}) {
            ShortcutRun r = lambertian_shortcut(make_material(lambertian(base)), front, wo, wi);
            std::size_t taken = 0, sampled = 0, lit = 0, differ = 0;
            for (std::size_t k = 0; k < n; ++k) {
                taken += r.shortcut[4 * k + 3].x == 1.0f;
                sampled += r.shortcut[4 * k].w > 0.0f;
                lit += r.shortcut[4 * k + 2].w > 0.0f;
                differ += std::memcmp(&r.shortcut[4 * k], &r.lobes[4 * k], 3 * sizeof(pcl_float4)) != 0;
            }
            EXPECT_EQ(taken, n) << "base " << base.x << " " << base.y << " " << base.z;
            EXPECT_EQ(differ, 0u) << "base " << base.x << " " << base.y << " " << base.z
                                  << (front ? " front" : " back");
            // Not vacuous: most samples exist, and half the wi are above the surface.
            EXPECT_GT(sampled, n * 9 / 10);
            EXPECT_GT(lit, n * 4 / 10);
        }
    std::vector<MaterialSpec> others = nearly_lambertian();
    MaterialSpec brushed = lambertian(glm::vec3(0.5f));
    brushed.roughness = 0.5f;
    brushed.anisotropy = 0.5f;
    others.push_back(brushed); // its frame is the anisotropy's
    for (std::size_t k = 0; const MaterialSpec& spec : others) {
        ShortcutRun r = lambertian_shortcut(make_material(spec), true, wo, wi);
        std::size_t taken = 0;
        for (std::size_t i = 0; i < n; ++i)
            taken += r.shortcut[4 * i + 3].x != 0.0f;
        EXPECT_EQ(taken, 0u) << "material " << k;
        ++k;
    }
}

TEST(BsdfEval, TheDiffuseOnlyParamsAreTheGeneralOnesBitForBit)
{
    // bsdf_params sets an exactly Lambertian material's layer albedo, diffuse scale and
    // lobe choice without the general code (bsdf_params_base_diffuse; renders are
    // bit-identical across the change): for every material bsdf_params_diffuse_only
    // admits, from either side, the fields must be the general code's bits, and
    // bsdf_params must have taken them; no other material may be admitted. The anisotropic
    // one is admitted (no layer, so its anisotropy changes none of these fields) though
    // bsdf_lambertian turns it away. Broken variants seen failing: the diffuse scale as
    // base / pi; the predicate without the specular weight (the plastic is admitted).
    const std::size_t n = 1024;
    std::vector<glm::dvec3> wo = random_directions(n, 23, false);
    MaterialSpec brushed = lambertian(glm::vec3(0.5f, 0.25f, 0.125f));
    brushed.roughness = 0.5f;
    brushed.anisotropy = 0.5f;
    std::vector<MaterialSpec> admitted_specs = {lambertian(glm::vec3(0.8f)), lambertian(glm::vec3(1.0f)),
                                                lambertian(glm::vec3(1e-30f, 0.0f, 0.0f)), brushed};
    std::mt19937 rng(24); // base colours whose products with 1 / pi round every way
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int j = 0; j < 16; ++j)
        admitted_specs.push_back(lambertian(glm::vec3(unit(rng), unit(rng), unit(rng))));
    for (std::size_t k = 0; const MaterialSpec& spec : admitted_specs) {
        for (bool front : {true, false}) {
            DiffuseOnlyRun r = diffuse_only_params(make_material(spec), front, wo);
            std::size_t admitted = 0, differ = 0, taken = 0;
            for (std::size_t i = 0; i < n; ++i) {
                admitted += r.diffuse_only[i] == 1.0f;
                differ += std::memcmp(&r.diffuse[3 * i], &r.general[3 * i], 3 * sizeof(pcl_float4)) != 0;
                taken += std::memcmp(&r.params[3 * i], &r.diffuse[3 * i], 3 * sizeof(pcl_float4)) == 0;
            }
            EXPECT_EQ(admitted, n) << "material " << k;
            EXPECT_EQ(differ, 0u) << "material " << k << (front ? " front" : " back");
            EXPECT_EQ(taken, n) << "material " << k;
        }
        ++k;
    }
    for (std::size_t k = 0; const MaterialSpec& spec : nearly_lambertian()) {
        DiffuseOnlyRun r = diffuse_only_params(make_material(spec), true, wo);
        std::size_t admitted = 0;
        for (std::size_t i = 0; i < n; ++i)
            admitted += r.diffuse_only[i] != 0.0f;
        EXPECT_EQ(admitted, 0u) << "material " << k;
        ++k;
    }
}

} // namespace
} // namespace pathcl
