// The BSDFs of kernels/closure/, through test kernels that call the real code
// (tests/kernels/bsdf_test_kernels.cl): chi-square tests of every sampling routine
// against an independent double-precision pdf (tests/support/reference_bsdf.h), eval and
// pdf against that reference, weight = f cos / pdf, reciprocity, white furnaces, the
// delta lobes (mirror, glass, TIR, ior 1), and the roughness sweep towards them.
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "render/layer_albedo.h"
#include "support/chi_square.h"
#include "support/device_fixture.h"
#include "support/reference_bsdf.h"

namespace pathcl {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::size_t kChiSquareSamples = 1000000;
// Chi-square tests run by this file, for the Šidák correction: Lambertian 1, conductor
// 9, dielectric 4, mixtures 4. Each also checks every sample's pdf, f and weight.
constexpr int kChiSquareTests = 18;

const cl::Program& full_program()
{
    static cl::Program p = test::build_test_program("bsdf_test_kernels.cl", FEATURE_GLOSSY | FEATURE_TRANSMISSION);
    return p;
}

// The program a scene of Lambertian materials only gets (no glossy or transmission code).
const cl::Program& lambertian_program()
{
    static cl::Program p = test::build_test_program("bsdf_test_kernels.cl");
    return p;
}

struct MaterialSpec {
    glm::vec3 base{1.0f};
    float metallic = 0.0f, roughness = 1.0f, transmission = 0.0f, ior = 1.5f;
    bool thin = true;
    float specular = 1.0f;
    glm::vec3 specular_color{1.0f};
};

Material make_material(const MaterialSpec& s)
{
    Material m{};
    m.base_color = {s.base.x, s.base.y, s.base.z, 1.0f};
    m.specular_color = {s.specular_color.x, s.specular_color.y, s.specular_color.z, s.specular};
    m.metallic = s.metallic;
    m.roughness = s.roughness;
    m.transmission = s.transmission;
    m.ior = s.ior;
    m.flags = s.thin ? MATERIAL_THIN_WALLED : 0u;
    m.normal_scale = 1.0f;
    for (pcl_int& t : m.textures)
        t = TEXTURE_NONE;
    m.smooth_layer_average = static_cast<float>(smooth_layer_average(s.ior));
    return m;
}

MaterialSpec conductor(float roughness, glm::vec3 base = glm::vec3(1.0f))
{
    MaterialSpec s;
    s.base = base;
    s.metallic = 1.0f;
    s.roughness = roughness;
    return s;
}

MaterialSpec dielectric(float roughness, float ior = 1.5f, bool thin = false)
{
    MaterialSpec s;
    s.roughness = roughness;
    s.transmission = 1.0f;
    s.ior = ior;
    s.thin = thin;
    return s;
}

MaterialSpec lambertian(glm::vec3 base)
{
    MaterialSpec s;
    s.base = base;
    s.specular = 0.0f;
    return s;
}

// wo at angle theta from +Z with cos theta = c, in the xz plane turned by 0.3 rad about Z
// (so nothing lines up with the chi-square grid's cell edges).
glm::dvec3 incident(double c)
{
    double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    return {s * std::cos(0.3), s * std::sin(0.3), c};
}

// The layer albedo tables, uploaded once.
const cl::Buffer& layer_buffer()
{
    static cl::Buffer b(test::test_device().context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                        layer_albedo_table().size() * sizeof(float), const_cast<float*>(layer_albedo_table().data()));
    return b;
}

struct Samples {
    std::vector<pcl_float4> dir_pdf, weight, eval;
};

pcl_float4 f4(const glm::dvec3& v)
{
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0.0f};
}

Samples sample_bsdf(const cl::Program& program, const Material& m, const glm::dvec3& wo, bool front_face,
                    std::size_t n, std::uint32_t seed = 17, glm::dvec3 normal = {0, 0, 1})
{
    ClDevice& dev = test::test_device();
    cl::Buffer dir_pdf(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Buffer weight(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Buffer eval(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Kernel k(program, "test_bsdf_sample");
    set_kernel_args(k, m, f4(normal), f4(wo), static_cast<cl_uint>(front_face), seed, layer_buffer(), dir_pdf, weight,
                    eval);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    Samples s;
    s.dir_pdf.resize(n);
    s.weight.resize(n);
    s.eval.resize(n);
    dev.queue.enqueueReadBuffer(dir_pdf, CL_TRUE, 0, n * sizeof(pcl_float4), s.dir_pdf.data());
    dev.queue.enqueueReadBuffer(weight, CL_TRUE, 0, n * sizeof(pcl_float4), s.weight.data());
    dev.queue.enqueueReadBuffer(eval, CL_TRUE, 0, n * sizeof(pcl_float4), s.eval.data());
    return s;
}

// bsdf_eval (f_cos, pdf) for each pair.
std::vector<pcl_float4> eval_bsdf(const cl::Program& program, const Material& m, bool front_face,
                                  const std::vector<glm::dvec3>& wo, const std::vector<glm::dvec3>& wi,
                                  glm::dvec3 normal = {0, 0, 1})
{
    ClDevice& dev = test::test_device();
    std::vector<pcl_float4> o, i;
    for (std::size_t k = 0; k < wo.size(); ++k) {
        o.push_back(f4(wo[k]));
        i.push_back(f4(wi[k]));
    }
    std::size_t n = wo.size();
    cl::Buffer ob(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * sizeof(pcl_float4), o.data());
    cl::Buffer ib(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * sizeof(pcl_float4), i.data());
    cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Kernel k(program, "test_bsdf_eval");
    set_kernel_args(k, m, f4(normal), static_cast<cl_uint>(front_face), layer_buffer(), ob, ib, out);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<pcl_float4> r(n);
    dev.queue.enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(pcl_float4), r.data());
    return r;
}

glm::dvec3 xyz(const pcl_float4& v)
{
    return {v.x, v.y, v.z};
}

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

bool near_rel(double a, double b, double rel, double abs_floor = 0.0)
{
    return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)) + abs_floor;
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
            w_ok = w_ok && near_rel(wf, ef / e.w, 1e-4);
        }
        bad_pdf += !pdf_ok;
        bad_f += !f_ok;
        bad_weight += !w_ok;
        if ((!pdf_ok || !f_ok || !w_ok) && first_bad.empty())
            first_bad = "wi (" + std::to_string(wi.x) + ", " + std::to_string(wi.y) + ", " + std::to_string(wi.z) +
                        "): sample pdf " + std::to_string(d.w) + ", eval pdf " + std::to_string(e.w) + ", reference pdf " +
                        std::to_string(host_pdf) + "; eval f_cos.r " + std::to_string(e.x) + ", reference " +
                        std::to_string(host_f.x) + "; weight.r " + std::to_string(w.x);
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

    MaterialSpec coated = lambertian({0.6f, 0.6f, 0.6f});
    coated.specular = 1.0f;
    coated.roughness = 0.0f; // diffuse plus a delta coat: only the diffuse part is tested here
    expect_sampling_matches(full_program(), coated, 0.5, true, "diffuse under a smooth coat");
}

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

std::vector<MaterialSpec> reflective_materials()
{
    MaterialSpec plastic = lambertian({0.3f, 0.6f, 0.9f});
    plastic.specular = 1.0f;
    plastic.roughness = 0.4f;
    MaterialSpec tinted = plastic;
    tinted.specular = 0.5f;
    tinted.specular_color = {2.0f, 1.0f, 0.2f};
    MaterialSpec half = conductor(0.7f, {0.9f, 0.5f, 0.1f});
    half.metallic = 0.3f;
    return {lambertian({0.5f, 0.6f, 0.7f}), conductor(0.2f), conductor(0.8f, {0.9f, 0.6f, 0.3f}), plastic, tinted,
            half};
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
            std::vector<pcl_float4> r = eval_bsdf(full_program(), m, front, wo_world, wi_world, normal);
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

struct Albedo {
    glm::dvec3 mean{0.0}, stderr_{0.0};
    std::size_t not_finite = 0;
};

// Directional albedo E[weight] from wo. Radiance crossing into a denser medium is
// scaled by 1/eta^2 (and out of it by eta^2); `energy` undoes that so the result is the
// fraction of energy scattered, which must not exceed 1.
Albedo directional_albedo(const cl::Program& program, const MaterialSpec& spec, double cos_o, bool front_face,
                          bool energy, std::size_t n = 200000)
{
    Material m = make_material(spec);
    test::ReferenceBsdf ref = test::ReferenceBsdf::from_material(m, front_face);
    Samples s = sample_bsdf(program, m, incident(cos_o), front_face, n, 99);
    Albedo a;
    glm::dvec3 sum(0.0), sum_sq(0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const pcl_float4 &d = s.dir_pdf[i], &w = s.weight[i];
        glm::dvec3 v(0.0);
        if (d.w > 0.0f) {
            v = xyz(w);
            if (energy && d.z < 0.0f && !ref.thin)
                v *= ref.eta * ref.eta;
        }
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(d.w)) {
            ++a.not_finite;
            continue;
        }
        sum += v;
        sum_sq += v * v;
    }
    a.mean = sum / static_cast<double>(n);
    glm::dvec3 var = sum_sq / static_cast<double>(n) - a.mean * a.mean;
    a.stderr_ = glm::sqrt(glm::max(var, glm::dvec3(0.0)) / static_cast<double>(n));
    return a;
}

const std::vector<double> kFurnaceAngles = {1.0, 0.7, 0.3, 0.05, 1e-4};

// The diffuse base of a rough dielectric is weighted by the layer albedo table, whose
// interpolation moves a white plastic's albedo by up to 3e-4 (measured against a 4e6
// sample estimate and a 2000 x 2000 quadrature of the reference, from cos 0.9 to 0.05).
constexpr double kLayerTableError = 5e-4;

MaterialSpec white_plastic(float roughness)
{
    MaterialSpec s = lambertian(glm::vec3(1.0f));
    s.specular = 1.0f;
    s.roughness = roughness;
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
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_NEAR(lam.mean[ch], 1.0, 1e-5);
            EXPECT_NEAR(lam_full.mean[ch], 1.0, 1e-5);
            EXPECT_NEAR(mirror.mean[ch], 1.0, 1e-5);
            EXPECT_NEAR(coated.mean[ch], 1.0, 5.0 * coated.stderr_[ch] + 1e-5);
        }
        EXPECT_EQ(lam.not_finite + lam_full.not_finite + mirror.not_finite + coated.not_finite, 0u);
        if (c < 0.01)
            continue; // at grazing incidence rough microfacets mask light away
        for (float r : {0.3f, 0.7f}) {
            SCOPED_TRACE("roughness " + std::to_string(r));
            Albedo plastic = directional_albedo(full_program(), white_plastic(r), c, true, false);
            EXPECT_NEAR(plastic.mean.x, 1.0, 5.0 * plastic.stderr_.x + kLayerTableError) << "plastic";
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
    const KernelPatch gltf_diffuse_weight{"closure/bsdf_eval.cl",
                                          "            e.f_cos = p->diffuse_scale * k * wi.z;\n",
                                          R"(            float3 hf = normalize(wo + wi);
            e.f_cos = p->base_color * ((1.0f - p->metallic) * (1.0f - p->transmission) *
                                       (1.0f - max3(fresnel_specular_layer(p, fabs(dot(wo, hf))))) * INV_PI * wi.z);
)"};
    static cl::Program faulty = test::build_test_program("bsdf_test_kernels.cl", FEATURE_GLOSSY | FEATURE_TRANSMISSION,
                                                         {gltf_diffuse_weight});
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
            glm::dvec3 refr = sin2_t < 1.0 ? glm::dvec3(-wo.x / eta, -wo.y / eta, -std::sqrt(1.0 - sin2_t)) : glm::dvec3(0.0);
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
                Albedo a = directional_albedo(full_program(), make(static_cast<float>(std::sqrt(alpha))), c, front, true,
                                              100000);
                EXPECT_EQ(a.not_finite, 0u) << "alpha " << alpha;
                double gap = std::abs(a.mean.x - delta.mean.x);
                EXPECT_LE(gap, previous_gap + 5.0 * a.stderr_.x) << "alpha " << alpha;
                previous_gap = gap;
            }
            EXPECT_LT(previous_gap, 0.01 + 5.0 * delta.stderr_.x) << "alpha 1e-3 vs delta";
            for (double alpha : {9.9e-4, 1e-5, 1e-7}) {
                Albedo a = directional_albedo(full_program(), make(static_cast<float>(std::sqrt(alpha))), c, front, true,
                                              20000);
                EXPECT_EQ(a.not_finite, 0u) << "alpha " << alpha;
            }
        }
}

} // namespace
} // namespace pathcl
