// Energy of the BSDFs of kernels/closure/ (through tests/kernels/bsdf_test_kernels.cl):
// white furnaces (lossless white materials reflect everything, to the layer tables'
// accuracy), no material scattering more than it receives, and a deliberately gaining
// diffuse weight caught. Next to each test: the broken variant seen to fail it.
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "features.h"
#include "support/bsdf_harness.h"
#include "support/device_fixture.h"
#include "tables/layer_albedo.h"

namespace pathcl::test_bsdf_energy {
namespace {

using test::Albedo;
using test::conductor;
using test::dielectric;
using test::directional_albedo;
using test::full_program;
using test::lambertian;
using test::lambertian_program;
using test::MaterialSpec;
using test::reflective_materials;

const std::vector<double> kFurnaceAngles = {1.0, 0.7, 0.3, 0.05, 1e-4};

// The diffuse base of a rough dielectric is weighted by the layer albedo table, whose
// interpolation moves a white plastic's albedo by up to 3e-4 (measured against a 4e6
// sample estimate and a 2000 x 2000 quadrature of the reference, from cos 0.9 to 0.05).
constexpr double kLayerTableError = 5e-4;

// The anisotropic tables (E_aniso, B_aniso) have coarser grids: their interpolants fall up
// to 6.1e-3 below the integrals at cos theta < 0.1 and 2.4e-3 elsewhere
// (LayerAlbedo.Anisotropic* tests), which a white brushed plastic gains as much as (times
// the part of E that B makes up).
constexpr double kAnisoTableError = 4e-3;

MaterialSpec white_plastic(float roughness)
{
    MaterialSpec s = lambertian(glm::vec3(1.0f));
    s.specular = 1.0f;
    s.roughness = roughness;
    return s;
}

// White base under a specular-glossiness layer (ior 0: F0 is the specular colour).
MaterialSpec white_spec_gloss(float roughness)
{
    MaterialSpec s = white_plastic(roughness);
    s.ior = 0.0f;
    s.specular_color = glm::vec3(0.25f);
    return s;
}

TEST(BsdfEnergy, WhiteMaterialsWithoutLossReflectEverything)
{
    // White Lambertian (both programs), white smooth conductor and white smooth plastic
    // (diffuse under a delta coat): every sample's weight is 1, so the albedo is 1 to
    // float rounding at every angle down to cos 1e-4. White rough plastic: the diffuse
    // base gets exactly what the rough coat does not reflect. White rough metal, glass
    // (from both sides) and thin sheets: the energy single scattering loses to masking is
    // restored. Those are 1 to the tables' accuracy.
    for (double c : kFurnaceAngles) {
        SCOPED_TRACE("cos " + std::to_string(c));
        Albedo lam = directional_albedo(lambertian_program(), lambertian(glm::vec3(1.0f)), c, true, false);
        Albedo lam_full = directional_albedo(full_program(), lambertian(glm::vec3(1.0f)), c, true, false);
        Albedo mirror = directional_albedo(full_program(), conductor(0.0f), c, true, false);
        Albedo coated = directional_albedo(full_program(), white_plastic(0.0f), c, true, false);
        Albedo coated_sg = directional_albedo(full_program(), white_spec_gloss(0.0f), c, true, false);
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_NEAR(lam.mean[ch], 1.0, 1e-5);
            EXPECT_NEAR(lam_full.mean[ch], 1.0, 1e-5);
            EXPECT_NEAR(mirror.mean[ch], 1.0, 1e-5);
            EXPECT_NEAR(coated.mean[ch], 1.0, 5.0 * coated.stderr_[ch] + 1e-5);
            EXPECT_NEAR(coated_sg.mean[ch], 1.0, 5.0 * coated_sg.stderr_[ch] + 1e-5) << "specular-glossiness";
        }
        EXPECT_EQ(lam.not_finite + lam_full.not_finite + mirror.not_finite + coated.not_finite, 0u);
        if (c < 0.01)
            continue; // at grazing incidence rough microfacets mask light away
        for (float r : {0.3f, 0.7f}) {
            SCOPED_TRACE("roughness " + std::to_string(r));
            Albedo plastic = directional_albedo(full_program(), white_plastic(r), c, true, false);
            EXPECT_NEAR(plastic.mean.x, 1.0, 5.0 * plastic.stderr_.x + kLayerTableError) << "plastic";
            Albedo sg = directional_albedo(full_program(), white_spec_gloss(r), c, true, false);
            EXPECT_NEAR(sg.mean.x, 1.0, 5.0 * sg.stderr_.x + kLayerTableError) << "specular-glossiness";
            // Rough conductors and interfaces with their multiple scattering restored.
            Albedo metal = directional_albedo(full_program(), conductor(r), c, true, false);
            EXPECT_NEAR(metal.mean.x, 1.0, 5.0 * metal.stderr_.x + kLayerTableError) << "metal";
            for (bool front : {true, false}) {
                Albedo glass = directional_albedo(full_program(), dielectric(r), c, front, true);
                EXPECT_NEAR(glass.mean.x, 1.0, 5.0 * glass.stderr_.x + kLayerTableError) << "glass " << front;
            }
            Albedo sheet = directional_albedo(full_program(), dielectric(r, 1.5f, true), c, true, true);
            EXPECT_NEAR(sheet.mean.x, 1.0, 5.0 * sheet.stderr_.x + kLayerTableError) << "thin sheet";
        }
    }
}

TEST(BsdfEnergy, GltfOwnDiffuseWeightGainsEnergyAndIsCaught)
{
    // glTF appendix B weights the diffuse base by 1 - max(F(wo.h)). Patched in on purpose,
    // a white rough plastic reflects 1.30 times what it receives at cos 0.05: the energy
    // tests above must see that.
    const KernelPatch gltf_diffuse_weight{"closure/bsdf_eval.cl", "        diffuse_eval(p, wi, &e);\n",
                                          R"(        diffuse_eval(p, wi, &e);
        if (!p->inside) {
            float3 hf = normalize(wo + wi);
            e.f_cos = p->base_color * ((1.0f - p->metallic) * (1.0f - p->transmission) *
                                       (1.0f - max3(fresnel_specular_layer(p, fabs(dot(wo, hf))))) * INV_PI * wi.z);
        }
)"};
    static cl::Program faulty =
        test::build_test_program("bsdf_test_kernels.cl", FEATURE_GLOSSY | FEATURE_TRANSMISSION, {gltf_diffuse_weight});
    Albedo a = directional_albedo(faulty, white_plastic(0.3f), 0.05, true, false);
    EXPECT_GT(a.mean.x, 1.0 + 5.0 * a.stderr_.x + kLayerTableError + 0.1);
}

TEST(BsdfEnergy, NoMaterialScattersMoreThanItReceives)
{
    // Albedo <= 1 for every material and angle, glass and thin sheets included (radiance
    // crossing into a solid is compressed by 1/eta^2; that is undone here), and finite
    // at cos 1e-4. Rough single-scattering microfacets lose some energy (masking), so
    // only the bound holds for them. Broken variant seen failing: a transmission lobe
    // without its (1 - F) factor (rough glass: up to 1.05).
    std::vector<std::pair<MaterialSpec, bool>> cases;
    for (const MaterialSpec& s : reflective_materials())
        cases.emplace_back(s, true);
    for (float r : {0.2f, 0.5f, 0.9f}) {
        cases.emplace_back(dielectric(r), true);
        cases.emplace_back(dielectric(r), false);
        cases.emplace_back(dielectric(r, 1.5f, true), true);
    }
    cases.emplace_back(white_plastic(0.3f), true);
    MaterialSpec half_glass = white_plastic(0.4f);
    half_glass.transmission = 0.5f;
    half_glass.thin = false;
    cases.emplace_back(half_glass, true);
    cases.emplace_back(half_glass, false);
    for (std::size_t k = 0; k < cases.size(); ++k)
        for (double c : kFurnaceAngles) {
            Albedo a = directional_albedo(full_program(), cases[k].first, c, cases[k].second, true);
            EXPECT_EQ(a.not_finite, 0u) << "case " << k << " cos " << c;
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_LE(a.mean[ch], 1.0 + 5.0 * a.stderr_[ch] + kLayerTableError) << "case " << k << " cos " << c;
        }
}

TEST(BsdfEnergy, ClearcoatTakesOnlyWhatTheBaseWouldReflect)
{
    // A white mirror under a smooth coat reflects c F(cos_o) by the coat and
    // (1 - c F(cos_o)) by the mirror (same cosine): exactly 1, for any c. A white
    // Lambertian under a coat reflects no more than 1 and (with the max in the base's
    // scale) loses what the coat's internal reflections would return: measured 0.948
    // (smooth coat, normal incidence) to 1 over these angles and roughnesses. Broken
    // variant seen failing: the base not scaled by the coat (both materials above 1).
    for (double c : kFurnaceAngles) {
        SCOPED_TRACE("cos " + std::to_string(c));
        for (float coat : {0.5f, 1.0f}) {
            MaterialSpec mirror = conductor(0.0f);
            mirror.clearcoat = coat;
            Albedo a = directional_albedo(full_program(), mirror, c, true, false);
            EXPECT_NEAR(a.mean.x, 1.0, 1e-5) << "coated mirror, coat " << coat;
            EXPECT_EQ(a.not_finite, 0u);
        }
        if (c < 0.01)
            continue; // at grazing incidence a rough coat's microfacets mask light away
        for (float coat_roughness : {0.0f, 0.3f, 0.7f}) {
            MaterialSpec white = lambertian(glm::vec3(1.0f));
            white.specular = 0.0f; // an exactly Lambertian base
            white.clearcoat = 1.0f;
            white.clearcoat_roughness = coat_roughness;
            Albedo a = directional_albedo(full_program(), white, c, true, false);
            SCOPED_TRACE("coat roughness " + std::to_string(coat_roughness));
            EXPECT_LE(a.mean.x, 1.0 + 5.0 * a.stderr_.x + kLayerTableError);
            EXPECT_GE(a.mean.x, 0.94);
            std::printf("white Lambertian under a coat of roughness %.1f, cos %.2f: albedo %.4f +- %.4f\n",
                        coat_roughness, c, a.mean.x, a.stderr_.x);
        }
    }
}

// A KHR_materials_sheen lobe alone: colour 1 over a black, exactly Lambertian base.
MaterialSpec sheen_alone(float roughness)
{
    MaterialSpec s = lambertian(glm::vec3(0.0f));
    s.sheen = glm::vec3(1.0f);
    s.sheen_roughness = roughness;
    return s;
}

TEST(BsdfEnergy, SheenReflectsItsAlbedoAndNeverMoreThanItReceives)
{
    // Where the lobe's albedo E_s stays below 1 (sheenRoughness 0.3 and above) a white sheen
    // alone reflects exactly E_s(cos_o): its samples' mean equals the host's quadrature of
    // the extension's lobe (not the table). Smoother sheens reflect up to 8x what they
    // receive at grazing angles as written; divided by max(1, E_s) they reflect at most 1.
    // A white sheen over a white Lambertian reflects at most 1. Broken variants seen
    // failing: the lobe's 1 / (4 cos_o) as 1 / (4 cos_o cos_i) (the albedos differ from the
    // quadrature), the base not scaled by the sheen (white on white above 1).
    for (double c : {1.0, 0.7, 0.3, 0.05, 0.01}) {
        SCOPED_TRACE("cos " + std::to_string(c));
        for (float r : {0.05f, 0.1f, 0.3f, 0.6f, 1.0f}) {
            SCOPED_TRACE("sheen roughness " + std::to_string(r));
            Albedo a = directional_albedo(full_program(), sheen_alone(r), c, true, false);
            EXPECT_EQ(a.not_finite, 0u);
            EXPECT_LE(a.mean.x, 1.0 + 5.0 * a.stderr_.x + kLayerTableError);
            if (r >= 0.3f) {
                EXPECT_NEAR(a.mean.x, integrate_sheen_albedo(c, r), 5.0 * a.stderr_.x + 1e-4);
            }
            MaterialSpec on_white = sheen_alone(r);
            on_white.base = glm::vec3(1.0f);
            Albedo w = directional_albedo(full_program(), on_white, c, true, false);
            EXPECT_LE(w.mean.x, 1.0 + 5.0 * w.stderr_.x + kLayerTableError) << "on white";
        }
    }
}

TEST(BsdfEnergy, SheenAsWrittenGainsEnergyAndIsCaught)
{
    // The extension's lobe without the division by max(1, E_s), patched in on purpose: a
    // white sheen of roughness 0.05 reflects about 3x what it receives at cos 0.01 (the
    // quadrature's E_s is 3.15), which the bound above must see.
    const KernelPatch undivided{"closure/sheen.cl",
                                "    e->f_cos += p->sheen * (f / fmax(fmax(p->sheen_e_o, e_i), 1.0f));\n",
                                "    e->f_cos += p->sheen * f;\n"};
    static cl::Program faulty = test::build_test_program(
        "bsdf_test_kernels.cl", FEATURE_GLOSSY | FEATURE_TRANSMISSION | FEATURE_SHEEN, {undivided});
    Albedo a = directional_albedo(faulty, sheen_alone(0.05f), 0.01, true, false);
    EXPECT_GT(a.mean.x, 2.0);
    EXPECT_NEAR(integrate_sheen_albedo(0.01, 0.05), a.mean.x, 5.0 * a.stderr_.x + 1e-3);
}

TEST(BsdfEnergy, AnisotropicWhiteMetalReflectsEverything)
{
    // KHR_materials_anisotropy's conductor with its multiple scattering restored from the
    // E_aniso table: a white brushed metal reflects 1 from along, across and between the
    // direction, within the energy tests' noise and table bound (measured: 0.995 to 1.002
    // over this grid; single-scattering it reflected as little as 0.49). Broken variants
    // seen to fail: no compensation for anisotropic lobes; E_aniso read at the azimuth
    // from the bitangent.
    for (float r : {0.0f, 0.1f, 0.3f, 0.6f, 0.9f})
        for (float a : {0.2f, 0.5f, 1.0f})
            for (double c : {1.0, 0.3, 0.05})
                for (double turn : {0.0, 0.7, 1.5707963}) { // wo's azimuth (0.3) from the direction
                    MaterialSpec metal = conductor(r);
                    metal.anisotropy = a;
                    Albedo m = directional_albedo(full_program(), metal, c, true, false, 200000,
                                                  glm::dvec3(std::cos(0.3 - turn), std::sin(0.3 - turn), 0.0));
                    EXPECT_NEAR(m.mean.x, 1.0, 5.0 * m.stderr_.x + kLayerTableError)
                        << "roughness " << r << " strength " << a << " cos " << c << " azimuth " << turn;
                }
}

TEST(BsdfEnergy, AnisotropicWhitePlasticAndSheetReflectEverything)
{
    // KHR_materials_anisotropy on a dielectric: the layer's lobe is the anisotropic one and
    // the diffuse base under it is weighted by the anisotropic layer's albedo (E_aniso and
    // B_aniso), so a white brushed plastic reflects 1; a thin white sheet's lobe pair is
    // divided by the anisotropic lobe's albedo, so it scatters 1. Over roughness 0-0.9,
    // strength 0.2-1, cos theta 1-0.05 and three azimuths, measured: plastic 0.9987 to
    // 1.0035 (the most at cos 0.05, where the tables' interpolants fall furthest below
    // their integrals), sheet 0.9978 to 1.0021 (noisier). Broken variants seen to fail:
    // the isotropic table read under the anisotropic lobe (as little as 0.29); B_aniso
    // read at a linear ior coordinate instead of its square-root grid (up to 1.069).
    for (float r : {0.0f, 0.1f, 0.3f, 0.6f, 0.9f})
        for (float a : {0.2f, 0.5f, 1.0f})
            for (double c : {1.0, 0.3, 0.05})
                for (double turn : {0.0, 0.7, 1.5707963}) { // wo's azimuth (0.3) from the direction
                    SCOPED_TRACE("roughness " + std::to_string(r) + " strength " + std::to_string(a) + " cos " +
                                 std::to_string(c) + " azimuth " + std::to_string(turn));
                    const glm::dvec3 tangent(std::cos(0.3 - turn), std::sin(0.3 - turn), 0.0);
                    MaterialSpec plastic = white_plastic(r);
                    plastic.anisotropy = a;
                    Albedo p = directional_albedo(full_program(), plastic, c, true, false, 200000, tangent);
                    EXPECT_NEAR(p.mean.x, 1.0, 5.0 * p.stderr_.x + kAnisoTableError) << "plastic";
                    MaterialSpec sheet = dielectric(r, 1.5f, true);
                    sheet.anisotropy = a;
                    Albedo t = directional_albedo(full_program(), sheet, c, true, true, 200000, tangent);
                    EXPECT_NEAR(t.mean.x, 1.0, 5.0 * t.stderr_.x + kAnisoTableError) << "sheet";
                    EXPECT_EQ(p.not_finite + t.not_finite, 0u);
                }
}

} // namespace
} // namespace pathcl::test_bsdf_energy
