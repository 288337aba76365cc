#include "support/bsdf_harness.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "features.h"
#include "support/device_fixture.h"
#include "support/reference_bsdf.h"
#include "tables/layer_albedo.h"

namespace pathcl::test {

namespace {

pcl_float4 f4(const glm::dvec3& v)
{
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0.0f};
}

std::vector<pcl_float4> f4s(const std::vector<glm::dvec3>& v)
{
    std::vector<pcl_float4> out;
    for (const glm::dvec3& x : v)
        out.push_back(f4(x));
    return out;
}

} // namespace

const cl::Program& full_program()
{
    static cl::Program p =
        test::build_test_program("bsdf_test_kernels.cl", FEATURE_GLOSSY | FEATURE_TRANSMISSION | FEATURE_SCHLICK_LAYER |
                                                             FEATURE_CLEARCOAT | FEATURE_SHEEN | FEATURE_ANISOTROPY);
    return p;
}

const cl::Program& lambertian_program()
{
    static cl::Program p = test::build_test_program("bsdf_test_kernels.cl");
    return p;
}

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
    m.clearcoat = s.clearcoat;
    m.clearcoat_roughness = s.clearcoat_roughness;
    m.sheen = {s.sheen.x, s.sheen.y, s.sheen.z, s.sheen_roughness};
    m.anisotropy = {s.anisotropy, 1.0f, 0.0f, 0.0f};
    return m;
}

MaterialSpec conductor(float roughness, glm::vec3 base)
{
    MaterialSpec s;
    s.base = base;
    s.metallic = 1.0f;
    s.roughness = roughness;
    return s;
}

MaterialSpec dielectric(float roughness, float ior, bool thin)
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
    // KHR_materials_pbrSpecularGlossiness as pathcl reads it: ior 0, the specular colour
    // is F0 (Schlick's curve).
    MaterialSpec spec_gloss = lambertian({0.4f, 0.3f, 0.2f});
    spec_gloss.specular = 1.0f;
    spec_gloss.specular_color = {0.5f, 0.3f, 0.1f};
    spec_gloss.ior = 0.0f;
    spec_gloss.roughness = 0.5f;
    // KHR_materials_clearcoat: a rough coat over a plastic, a smoother part coat over a
    // rough metal, and a smooth (delta) coat over a rough plastic.
    MaterialSpec coated_plastic = plastic;
    coated_plastic.clearcoat = 1.0f;
    coated_plastic.clearcoat_roughness = 0.3f;
    MaterialSpec coated_metal = conductor(0.6f, {0.9f, 0.6f, 0.3f});
    coated_metal.clearcoat = 0.6f;
    coated_metal.clearcoat_roughness = 0.15f;
    MaterialSpec lacquer = plastic;
    lacquer.clearcoat = 0.8f;
    // KHR_materials_sheen: velvet (a dark Lambertian base), a smooth sheen over a plastic and
    // a smoother one over a rough metal (both with albedos above 1 near grazing, so the
    // lobe's division by max(1, E) is exercised), and a rough sheen under a clear coat.
    MaterialSpec velvet = lambertian({0.3f, 0.05f, 0.05f});
    velvet.sheen = {0.9f, 0.9f, 0.9f};
    velvet.sheen_roughness = 0.3f;
    MaterialSpec sheen_plastic = plastic;
    sheen_plastic.sheen = {1.0f, 0.8f, 0.6f};
    sheen_plastic.sheen_roughness = 0.1f;
    MaterialSpec sheen_metal = conductor(0.5f, {0.9f, 0.6f, 0.3f});
    sheen_metal.sheen = {0.6f, 0.6f, 1.0f};
    sheen_metal.sheen_roughness = 0.05f;
    MaterialSpec coated_sheen = coated_plastic;
    coated_sheen.sheen = {0.5f, 0.5f, 1.0f};
    coated_sheen.sheen_roughness = 0.6f;
    // KHR_materials_anisotropy: brushed metal, a part metal over a plastic, a smooth
    // metal made rough along one axis alone (alpha 1e-3 across it), a brushed plastic
    // (the dielectric layer anisotropic over the diffuse base), and a smooth tinted
    // plastic made rough along one axis.
    MaterialSpec brushed = conductor(0.3f, {0.95f, 0.9f, 0.85f});
    brushed.anisotropy = 0.8f;
    MaterialSpec aniso_half = half;
    aniso_half.anisotropy = 0.5f;
    MaterialSpec streak = conductor(0.0f, {0.9f, 0.6f, 0.3f});
    streak.anisotropy = 0.6f;
    MaterialSpec brushed_plastic = plastic;
    brushed_plastic.anisotropy = 0.7f;
    MaterialSpec streak_plastic = tinted;
    streak_plastic.roughness = 0.0f;
    streak_plastic.anisotropy = 0.5f;
    return {lambertian({0.5f, 0.6f, 0.7f}),
            conductor(0.2f),
            conductor(0.8f, {0.9f, 0.6f, 0.3f}),
            plastic,
            tinted,
            half,
            spec_gloss,
            coated_plastic,
            coated_metal,
            lacquer,
            velvet,
            sheen_plastic,
            sheen_metal,
            coated_sheen,
            brushed,
            aniso_half,
            streak,
            brushed_plastic,
            streak_plastic};
}

glm::dvec3 incident(double c)
{
    double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    return {s * std::cos(0.3), s * std::sin(0.3), c};
}

const cl::Buffer& layer_buffer()
{
    static cl::Buffer b(test::test_device().context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                        layer_albedo_table().size() * sizeof(float), const_cast<float*>(layer_albedo_table().data()));
    return b;
}

Samples sample_bsdf(const cl::Program& program, const Material& m, const glm::dvec3& wo, bool front_face, std::size_t n,
                    std::uint32_t seed, glm::dvec3 tangent)
{
    ClDevice& dev = test::test_device();
    cl::Buffer dir_pdf(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Buffer weight(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Buffer eval(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Kernel k(program, "test_bsdf_sample");
    set_kernel_args(k, m, f4(glm::dvec3(0, 0, 1)), f4(tangent), f4(wo), static_cast<cl_uint>(front_face), seed,
                    layer_buffer(), dir_pdf, weight, eval);
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

std::vector<pcl_float4> eval_bsdf(const cl::Program& program, const Material& m, bool front_face,
                                  const std::vector<glm::dvec3>& wo, const std::vector<glm::dvec3>& wi,
                                  glm::dvec3 normal, glm::dvec3 tangent)
{
    ClDevice& dev = test::test_device();
    std::size_t n = wo.size();
    cl::Buffer ob = upload(f4s(wo)), ib = upload(f4s(wi));
    cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Kernel k(program, "test_bsdf_eval");
    set_kernel_args(k, m, f4(normal), f4(tangent), static_cast<cl_uint>(front_face), layer_buffer(), ob, ib, out);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<pcl_float4> r(n);
    dev.queue.enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(pcl_float4), r.data());
    return r;
}

ShortcutRun lambertian_shortcut(const Material& m, bool front_face, const std::vector<glm::dvec3>& wo,
                                const std::vector<glm::dvec3>& wi)
{
    ClDevice& dev = test::test_device();
    std::size_t n = wo.size();
    cl::Buffer ob = upload(f4s(wo)), ib = upload(f4s(wi));
    cl::Buffer a(dev.context, CL_MEM_WRITE_ONLY, 4 * n * sizeof(pcl_float4));
    cl::Buffer b(dev.context, CL_MEM_WRITE_ONLY, 4 * n * sizeof(pcl_float4));
    cl::Kernel k(full_program(), "test_bsdf_lambertian_shortcut");
    set_kernel_args(k, m, static_cast<cl_uint>(front_face), static_cast<cl_uint>(5), layer_buffer(), ob, ib, a, b);
    // PoCL's own work-group size for this many work-items failed to launch; 64 divides n.
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n), cl::NDRange(64));
    return {read_back<pcl_float4>(a, 4 * n), read_back<pcl_float4>(b, 4 * n)};
}

ParamsShortcutRun params_shortcut(const Material& m, bool front_face, bool ideal, const std::vector<glm::dvec3>& wo,
                                  std::uint32_t seed)
{
    ClDevice& dev = test::test_device();
    std::size_t n = wo.size();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<pcl_float4> numbers(n);
    for (pcl_float4& v : numbers)
        v = {unit(rng), unit(rng), unit(rng), 0.0f};
    cl::Buffer ob = upload(f4s(wo)), ub = upload(numbers);
    cl::Buffer params(dev.context, CL_MEM_WRITE_ONLY, 3 * n * sizeof(pcl_float4));
    cl::Buffer shortcut(dev.context, CL_MEM_WRITE_ONLY, 3 * n * sizeof(pcl_float4));
    cl::Buffer general(dev.context, CL_MEM_WRITE_ONLY, 3 * n * sizeof(pcl_float4));
    cl::Buffer flags(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(float));
    cl::Buffer samples(dev.context, CL_MEM_WRITE_ONLY, 4 * n * sizeof(pcl_float4));
    cl::Kernel k(full_program(), "test_bsdf_params_shortcut");
    set_kernel_args(k, m, static_cast<cl_uint>(front_face), static_cast<cl_uint>(ideal), layer_buffer(), ob, ub, params,
                    shortcut, general, flags, samples);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n), cl::NDRange(64));
    return {read_back<pcl_float4>(params, 3 * n), read_back<pcl_float4>(shortcut, 3 * n),
            read_back<pcl_float4>(general, 3 * n), read_back<pcl_float4>(samples, 4 * n), read_back<float>(flags, n)};
}

glm::dvec3 xyz(const pcl_float4& v)
{
    return {v.x, v.y, v.z};
}

bool near_rel(double a, double b, double rel, double abs_floor)
{
    return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)) + abs_floor;
}

Albedo directional_albedo(const cl::Program& program, const MaterialSpec& spec, double cos_o, bool front_face,
                          bool energy, std::size_t n, glm::dvec3 tangent)
{
    Material m = make_material(spec);
    test::ReferenceBsdf ref = test::ReferenceBsdf::from_material(m, front_face);
    Samples s = sample_bsdf(program, m, incident(cos_o), front_face, n, 99, tangent);
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

} // namespace pathcl::test
