// bsdf_eval of kernels/closure/ (through tests/kernels/bsdf_test_kernels.cl): f cos and
// pdf equal the independent double-precision reference (tests/support/reference_bsdf.h)
// over the whole sphere, from both sides, and reflection is reciprocal. Next to each
// test: the broken variant seen to fail it.
#include <algorithm>
#include <array>
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

namespace pathcl::test_bsdf_eval {
namespace {

using test::conductor;
using test::dielectric;
using test::eval_bsdf;
using test::full_program;
using test::lambertian;
using test::lambertian_shortcut;
using test::make_material;
using test::MaterialSpec;
using test::near_rel;
using test::params_shortcut;
using test::ParamsShortcutRun;
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

// No material of `specs` may take the bsdf_params shortcut (the Lambertian one, or the
// ideal mirror and glass one), from the front, at any wo.
void expect_none_admitted(const std::vector<MaterialSpec>& specs, bool ideal, const std::vector<glm::dvec3>& wo)
{
    for (std::size_t k = 0; const MaterialSpec& spec : specs) {
        ParamsShortcutRun r = params_shortcut(make_material(spec), true, ideal, wo);
        std::size_t admitted = 0;
        for (float a : r.admitted)
            admitted += a != 0.0f;
        EXPECT_EQ(admitted, 0u) << "material " << k;
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
            ParamsShortcutRun r = params_shortcut(make_material(spec), front, false, wo);
            std::size_t admitted = 0, differ = 0, taken = 0;
            for (std::size_t i = 0; i < n; ++i) {
                admitted += r.admitted[i] == 1.0f;
                differ += std::memcmp(&r.shortcut[3 * i], &r.general[3 * i], 3 * sizeof(pcl_float4)) != 0;
                taken += std::memcmp(&r.params[3 * i], &r.shortcut[3 * i], 3 * sizeof(pcl_float4)) == 0;
            }
            EXPECT_EQ(admitted, n) << "material " << k;
            EXPECT_EQ(differ, 0u) << "material " << k << (front ? " front" : " back");
            EXPECT_EQ(taken, n) << "material " << k;
        }
        ++k;
    }
    expect_none_admitted(nearly_lambertian(), false, wo);
}

// The lobe choice's bits in write_base_fields' three float4: diffuse, conductor, interface,
// sheen, coat.
std::array<float, 5> lobe_choice(const pcl_float4* f)
{
    return {f[0].w, f[1].w, f[2].x, f[2].y, f[2].z};
}

TEST(BsdfEval, TheIdealMirrorAndGlassParamsChooseTheGeneralLobesBitForBit)
{
    // bsdf_params makes an ideal mirror's or ideal glass's lobe choice without the general
    // code (bsdf_params_base_ideal; renders are bit-identical across the change): for
    // every material bsdf_params_ideal_only admits, from either side, the lobe choice must
    // be the general code's bits and what bsdf_params returned, and bsdf_sample must give
    // the same bits from the shortcut's fields as from the general ones (it reads neither
    // the layer's albedo nor the diffuse scale there); no other material may be admitted.
    // Broken variants seen failing: the mirror's lobe taken with probability 1 when its
    // estimate is 0 (the black mirror at normal incidence); the predicate without the
    // coat check (the coated mirror is admitted).
    const std::size_t n = 1024;
    std::vector<glm::dvec3> wo = random_directions(n - 2, 26, false);
    wo.push_back({0.0, 0.0, 1.0}); // normal incidence: a black mirror's estimate is 0 there
    wo.push_back({0.0, 0.0, -1.0});
    std::vector<MaterialSpec> admitted_specs = {
        conductor(0.0f),       conductor(0.0f, glm::vec3(0.0f)), conductor(0.02f, glm::vec3(1.0f, 0.78f, 0.34f)),
        dielectric(0.0f),      dielectric(0.0f, 1.33f, true),    dielectric(0.0f, 1.0f),
        dielectric(0.0f, 0.0f)};
    MaterialSpec tinted = dielectric(0.0f, 1.7f);
    tinted.specular = 0.5f;
    tinted.specular_color = {0.0f, 0.5f, 2.0f};
    MaterialSpec faint = dielectric(0.0f);
    faint.base = glm::vec3(0x1.0p-90f, 0.0f, 0.0f);
    MaterialSpec plain_mirror = conductor(0.0f, glm::vec3(0.5f));
    plain_mirror.specular = 0.0f;
    admitted_specs.insert(admitted_specs.end(), {tinted, faint, plain_mirror});
    std::mt19937 rng(27); // bases whose Schlick means and glass tints round every way
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int j = 0; j < 6; ++j) {
        admitted_specs.push_back(conductor(0.0f, glm::vec3(unit(rng), unit(rng), unit(rng))));
        MaterialSpec glass = dielectric(0.0f, 1.0f + unit(rng), j % 2 == 0);
        glass.base = glm::vec3(unit(rng), unit(rng), unit(rng));
        admitted_specs.push_back(glass);
    }
    std::size_t sampled = 0, delta = 0;
    for (std::size_t k = 0; const MaterialSpec& spec : admitted_specs) {
        for (bool front : {true, false}) {
            ParamsShortcutRun r = params_shortcut(make_material(spec), front, true, wo);
            std::size_t admitted = 0, differ = 0, taken = 0, samples_differ = 0;
            for (std::size_t i = 0; i < n; ++i) {
                admitted += r.admitted[i] == 1.0f;
                std::array<float, 5> a = lobe_choice(&r.shortcut[3 * i]), b = lobe_choice(&r.general[3 * i]);
                std::array<float, 5> p = lobe_choice(&r.params[3 * i]);
                differ += std::memcmp(a.data(), b.data(), sizeof(a)) != 0;
                taken += std::memcmp(p.data(), a.data(), sizeof(a)) == 0;
                samples_differ += std::memcmp(&r.samples[4 * i], &r.samples[4 * i + 2], 2 * sizeof(pcl_float4)) != 0;
                sampled += r.samples[4 * i].w > 0.0f;
                delta += r.samples[4 * i + 1].w > 0.0f;
            }
            std::string what = "material " + std::to_string(k) + (front ? " front" : " back");
            EXPECT_EQ(admitted, n) << what;
            EXPECT_EQ(differ, 0u) << what;
            EXPECT_EQ(taken, n) << what;
            EXPECT_EQ(samples_differ, 0u) << what;
        }
        ++k;
    }
    // Not vacuous: over a third of the directions give a sample (a mirror gives none from
    // below its surface), each a delta one.
    EXPECT_GT(sampled, admitted_specs.size() * 2 * n / 3);
    EXPECT_EQ(delta, sampled);

    MaterialSpec part_metal = conductor(0.0f);
    part_metal.metallic = 0.999f;
    MaterialSpec part_glass = dielectric(0.0f);
    part_glass.transmission = 0.999f;
    MaterialSpec coated = conductor(0.0f);
    coated.clearcoat = 0.5f;
    MaterialSpec velvet = dielectric(0.0f);
    velvet.sheen = {0.5f, 0.5f, 0.5f};
    MaterialSpec brushed = conductor(0.0f);
    brushed.anisotropy = 0.5f;
    MaterialSpec black_glass = dielectric(0.0f);
    black_glass.base = glm::vec3(0.0f);
    MaterialSpec bright_glass = dielectric(0.0f);
    bright_glass.base = glm::vec3(1.5f, 1.0f, 1.0f);
    std::vector<MaterialSpec> others = {part_metal,
                                        part_glass,
                                        coated,
                                        velvet,
                                        brushed,
                                        black_glass,
                                        bright_glass,
                                        conductor(0.04f),
                                        dielectric(0.04f),
                                        lambertian(glm::vec3(0.5f))};
    expect_none_admitted(others, true, wo);
}

} // namespace
} // namespace pathcl::test_bsdf_eval
