// bsdf_eval of kernels/closure/ (through tests/kernels/bsdf_test_kernels.cl): f cos and
// pdf equal the independent double-precision reference (tests/support/reference_bsdf.h)
// over the whole sphere, from both sides, and reflection is reciprocal. Next to each
// test: the broken variant seen to fail it.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
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

using test::dielectric;
using test::eval_bsdf;
using test::full_program;
using test::make_material;
using test::MaterialSpec;
using test::near_rel;
using test::reflective_materials;

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

} // namespace
} // namespace pathcl
