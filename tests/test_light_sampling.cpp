// Light sampling against its pdf, through the kernels' own light_sample: chi-square tests
// of the sampled directions (tests/support/chi_square.h) against an independent host pdf,
// and the kernel's reported pdf against the same host pdf at the sampled directions.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "compile/light_distribution.h"
#include "light/light_pick.h"
#include "light/triangle_sampling.h"
#include "support/chi_square.h"
#include "support/device_fixture.h"

namespace pathcl::test_light_sampling {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kTests = 5; // chi-square tests in this file (Šidák correction)

const cl::Program& light_program()
{
    static cl::Program program =
        test::build_test_program("trace_test_kernels.cl", FEATURE_AREA_LIGHTS | FEATURE_SPHERE_LIGHTS);
    return program;
}

// Lights of equal power (each picked with probability 1 / n).
SceneArrays equal_power(const std::vector<Light>& lights)
{
    SceneArrays a;
    a.lights = lights;
    a.light_distribution = build_light_distribution(std::vector<double>(lights.size(), 1.0));
    return a;
}

std::vector<pcl_float4> sample_lights(const std::vector<Light>& lights, glm::vec3 ref, std::size_t n)
{
    return test::sample_lights_on_device(light_program(), equal_power(lights), ref, 1234u, n);
}

// Checks the kernel's pdf against the host pdf at each sampled direction.
void expect_kernel_pdf_matches(const std::vector<pcl_float4>& s, const std::function<double(const glm::dvec3&)>& pdf)
{
    std::size_t bad = 0;
    for (const pcl_float4& v : s) {
        if (v.w == 0.0f)
            continue;
        double host = pdf(glm::normalize(glm::dvec3(v.x, v.y, v.z)));
        if (!(std::fabs(v.w - host) <= 1e-3 * host))
            ++bad;
    }
    EXPECT_EQ(bad, 0u) << "samples whose kernel pdf differs from the host pdf by > 0.1%";
}

Light sphere_light(glm::vec3 centre, float radius)
{
    Light l{};
    l.type = LIGHT_SPHERE;
    l.data.sphere.centre = {centre.x, centre.y, centre.z, 0.0f};
    l.data.sphere.radius = radius;
    l.radiance = {1, 1, 1, 0};
    return l;
}

// Uniform over the cone the sphere subtends from ref.
std::function<double(const glm::dvec3&)> sphere_cone_pdf(glm::dvec3 centre, double r, glm::dvec3 ref)
{
    glm::dvec3 axis = centre - ref;
    double dc = glm::length(axis);
    double cos_max = std::sqrt(1.0 - r * r / (dc * dc));
    axis /= dc;
    return
        [=](const glm::dvec3& w) { return glm::dot(w, axis) >= cos_max ? 1.0 / (2.0 * kPi * (1.0 - cos_max)) : 0.0; };
}

TEST(LightSampling, SphereFromOutsideIsUniformOverItsCone)
{
    glm::vec3 c(0.3f, 0.2f, 1.5f);
    auto pdf = sphere_cone_pdf(c, 0.8, glm::dvec3(0.0));
    auto s = sample_lights({sphere_light(c, 0.8f)}, glm::vec3(0.0f), 1000000);
    test::ChiSquareResult r = test::chi_square_directions(test::to_directions(s), pdf, 10, 20, 0.01, kTests);
    EXPECT_TRUE(r.passed) << r.summary();
    expect_kernel_pdf_matches(s, pdf);
}

TEST(LightSampling, SphereFromJustOutsideItsSurface)
{
    // 1% above the surface the cone is almost a hemisphere.
    glm::vec3 c(0.0f, 0.0f, 1.01f);
    auto pdf = sphere_cone_pdf(c, 1.0, glm::dvec3(0.0));
    auto s = sample_lights({sphere_light(c, 1.0f)}, glm::vec3(0.0f), 1000000);
    test::ChiSquareResult r = test::chi_square_directions(test::to_directions(s), pdf, 10, 20, 0.01, kTests);
    EXPECT_TRUE(r.passed) << r.summary();
    expect_kernel_pdf_matches(s, pdf);
}

TEST(LightSampling, SphereSamplesCarryItsRadiance)
{
    // Weight = radiance / pdf: every sample of a sphere carries exactly its radiance.
    Light l = sphere_light(glm::vec3(0.0f, 0.0f, 3.0f), 1.0f);
    l.radiance = {2.5f, 1.5f, 0.5f, 0.0f};
    std::vector<pcl_float4> radiance;
    auto s = test::sample_lights_on_device(light_program(), equal_power({l}), glm::vec3(0.0f), 5u, 10000, &radiance);
    for (std::size_t i = 0; i < s.size(); ++i) {
        ASSERT_GT(s[i].w, 0.0f);
        ASSERT_EQ(radiance[i].x, 2.5f);
        ASSERT_EQ(radiance[i].y, 1.5f);
        ASSERT_EQ(radiance[i].z, 0.5f);
    }
}

TEST(LightSampling, FromInsideASphereThereIsNoSample)
{
    auto s = sample_lights({sphere_light(glm::vec3(0.0f), 1.0f)}, glm::vec3(0.1f, 0.2f, 0.0f), 1000);
    for (const pcl_float4& v : s)
        ASSERT_EQ(v.w, 0.0f);
}

Light triangle_light(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2)
{
    Light l{};
    l.type = LIGHT_TRIANGLE;
    l.data.triangle.v0 = {p0.x, p0.y, p0.z, 0};
    l.data.triangle.v1 = {p1.x, p1.y, p1.z, 0};
    l.data.triangle.v2 = {p2.x, p2.y, p2.z, 0};
    l.data.triangle.area = 0.5f * glm::length(glm::cross(p1 - p0, p2 - p0));
    l.data.triangle.texture = TEXTURE_NONE;
    l.radiance = {1, 1, 1, 0};
    return l;
}

// Where the ray from the origin along w meets the front of triangle p0 p1 p2 (emission
// leaves the front only): its distance, or 0.
double front_hit_distance(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& w)
{
    const glm::dvec3 nn = glm::cross(p1 - p0, p2 - p0), n = glm::normalize(nn);
    const double denom = glm::dot(w, n);
    if (!(denom < 0.0))
        return 0.0; // facing away
    const double t = glm::dot(p0, n) / denom;
    const glm::dvec3 p = t * w;
    const glm::dvec3 c0 = glm::cross(p1 - p0, p - p0), c1 = glm::cross(p2 - p1, p - p1),
                     c2 = glm::cross(p0 - p2, p - p2);
    if (t <= 0.0 || glm::dot(c0, nn) < 0.0 || glm::dot(c1, nn) < 0.0 || glm::dot(c2, nn) < 0.0)
        return 0.0;
    return t;
}

// Solid-angle pdf of uniform area sampling seen from the origin: t^2 / (A cos).
double triangle_area_pdf(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& w)
{
    const double t = front_hit_distance(p0, p1, p2, w);
    if (t == 0.0)
        return 0.0;
    const glm::dvec3 nn = glm::cross(p1 - p0, p2 - p0);
    return t * t / (0.5 * glm::length(nn) * -glm::dot(w, glm::normalize(nn)));
}

TEST(LightSampling, TwoTrianglesAndASphereByAreaAndCone)
{
    // Selection (equal power: pmf 1/3 each) times each light's own solid-angle pdf. A
    // triangle facing away from ref contributes nothing and must never be sampled.
    glm::vec3 a0(-1, -1, 2), a1(1, -1, 2), a2(0, 1, 2.5f); // faces -z... towards ref? see below
    glm::vec3 b0(1, 2, -1), b1(2, 2, 1), b2(1, 3, 0);
    glm::vec3 sc(-1.5f, 0.0f, -1.0f);
    auto sphere = sphere_cone_pdf(sc, 0.5, glm::dvec3(0.0));
    auto pdf = [&](const glm::dvec3& w) {
        return (triangle_area_pdf(a0, a1, a2, w) + triangle_area_pdf(b0, b1, b2, w) + sphere(w)) / 3.0;
    };
    auto s = sample_lights({sphere_light(sc, 0.5f), triangle_light(a0, a1, a2), triangle_light(b0, b1, b2)},
                           glm::vec3(0.0f), 1000000);
    test::ChiSquareResult r = test::chi_square_directions(test::to_directions(s), pdf, 10, 20, 0.01, kTests);
    EXPECT_TRUE(r.passed) << r.summary();
    EXPECT_LT(r.pdf_integral, 1.0) << "one triangle faces away, so some samples must fail";
}

// The solid angle of triangle p0 p1 p2 seen from the origin (Van Oosterom and Strackee).
double solid_angle(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2)
{
    const glm::dvec3 a = glm::normalize(p0), b = glm::normalize(p1), c = glm::normalize(p2);
    return 2.0 *
           std::atan2(std::fabs(glm::dot(a, glm::cross(b, c))), 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a));
}

// A program with --triangle-sampling solid-angle, its source changed by `patches`.
cl::Program solid_angle_program(const std::vector<KernelPatch>& patches = {})
{
    return test::build_test_program("trace_test_kernels.cl", FEATURE_AREA_LIGHTS | FEATURE_SOLID_ANGLE_TRIANGLES,
                                    patches);
}

// A triangle facing the origin, large seen from there (area / distance^2 to its centroid
// about 5, far above TRIANGLE_SOLID_ANGLE_MIN), moved away by `shift` along z.
struct NearTriangle {
    glm::dvec3 p0, p1, p2;
};
NearTriangle near_triangle(double shift)
{
    return {{-0.6, -0.5, 0.4 + shift}, {0.1, 0.8, 0.3 + shift}, {0.7, -0.4, 0.5 + shift}};
}

// What the kernel compares with TRIANGLE_SOLID_ANGLE_MIN: area over the squared distance
// from the origin to the centroid.
double area_over_distance2(const NearTriangle& t)
{
    const glm::dvec3 centroid = (t.p0 + t.p1 + t.p2) / 3.0;
    return 0.5 * glm::length(glm::cross(t.p1 - t.p0, t.p2 - t.p0)) / glm::dot(centroid, centroid);
}

TEST(LightSampling, ANearTriangleIsSampledUniformlyWithinItsSolidAngle)
{
    // Arvo's construction (light/spherical_triangle.cl): every direction within the
    // spherical triangle with pdf 1 / omega, none outside. Broken variants seen to fail:
    // the arc's cosine drawn with u.y squared (below), and Arvo's formulas as written,
    // whose sine of the arc from a to c' (a square root of 1 - cos) put 26 of these 10^6
    // samples outside the triangle (the pdf check).
    const NearTriangle t = near_triangle(0.0);
    const double omega = solid_angle(t.p0, t.p1, t.p2);
    ASSERT_GT(area_over_distance2(t), TRIANGLE_SOLID_ANGLE_MIN);
    ASSERT_LT(omega, TRIANGLE_SOLID_ANGLE_MAX);
    auto pdf = [&](const glm::dvec3& w) { return front_hit_distance(t.p0, t.p1, t.p2, w) > 0.0 ? 1.0 / omega : 0.0; };
    std::vector<pcl_float4> radiance;
    auto s = test::sample_lights_on_device(solid_angle_program(), equal_power({triangle_light(t.p0, t.p1, t.p2)}),
                                           glm::vec3(0.0f), 1234u, 1000000, &radiance);
    test::ChiSquareResult r = test::chi_square_directions(test::to_directions(s), pdf, 10, 20, 0.01, kTests);
    EXPECT_TRUE(r.passed) << r.summary();
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-3);
    expect_kernel_pdf_matches(s, pdf);
    for (std::size_t i = 0; i < s.size(); i += 997)
        EXPECT_EQ(radiance[i].x, s[i].w > 0.0f ? 1.0f : 0.0f) << "sample " << i;

    const std::vector<KernelPatch> broken = {{"light/spherical_triangle.cl",
                                              "float one_minus_z = u.y * 0.5f * dot(d, d);",
                                              "float one_minus_z = u.y * u.y * 0.5f * dot(d, d);"}};
    auto b = test::sample_lights_on_device(solid_angle_program(broken), equal_power({triangle_light(t.p0, t.p1, t.p2)}),
                                           glm::vec3(0.0f), 1234u, 1000000);
    EXPECT_FALSE(test::chi_square_directions(test::to_directions(b), pdf, 10, 20, 0.01, kTests).passed);
}

TEST(LightSampling, AFarTriangleIsSampledByAreaUnderSolidAngleSampling)
{
    // The same triangle 3 units further: area / distance^2 about 0.07, below
    // TRIANGLE_SOLID_ANGLE_MIN, so its samples keep the area pdf t^2 / (A cos).
    const NearTriangle t = near_triangle(3.0);
    ASSERT_LT(area_over_distance2(t), TRIANGLE_SOLID_ANGLE_MIN);
    auto pdf = [&](const glm::dvec3& w) { return triangle_area_pdf(t.p0, t.p1, t.p2, w); };
    auto s = test::sample_lights_on_device(solid_angle_program(), equal_power({triangle_light(t.p0, t.p1, t.p2)}),
                                           glm::vec3(0.0f), 1234u, 200000);
    expect_kernel_pdf_matches(s, pdf);
    // And the near one's samples do not (the pdf is a property of the strategy, not only
    // of the direction).
    const NearTriangle n = near_triangle(0.0);
    auto near = test::sample_lights_on_device(solid_angle_program(), equal_power({triangle_light(n.p0, n.p1, n.p2)}),
                                              glm::vec3(0.0f), 1234u, 1000);
    std::size_t area_like = 0;
    for (const pcl_float4& v : near)
        if (v.w > 0.0f && std::fabs(v.w - triangle_area_pdf(n.p0, n.p1, n.p2,
                                                            glm::normalize(glm::dvec3(v.x, v.y, v.z)))) <= 1e-3 * v.w)
            ++area_like;
    EXPECT_LT(area_like, near.size() / 10);
}

// light_pick on the device (tests/kernels/trace_test_kernels.cl) for each of `u`, with one
// alias coin and one step jitter: the lights picked and the numbers rescaled.
struct Picks {
    std::vector<cl_int> light;
    std::vector<float> u;
};
Picks pick_on_device(const std::vector<LightAliasEntry>& dist, std::vector<float> u, float coin, float jitter)
{
    ClDevice& dev = test::test_device();
    const std::size_t n = u.size();
    cl::Buffer d_dist(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, dist.size() * sizeof(LightAliasEntry),
                      const_cast<LightAliasEntry*>(dist.data()));
    cl::Buffer d_u(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * sizeof(float), u.data());
    cl::Buffer d_picked(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(cl_int));
    cl::Buffer d_out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(float));
    cl::Kernel k(light_program(), "test_light_pick");
    set_kernel_args(k, d_dist, static_cast<cl_uint>(dist.size()), d_u, coin, jitter, d_picked, d_out);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    Picks p{std::vector<cl_int>(n), std::vector<float>(n)};
    dev.queue.enqueueReadBuffer(d_picked, CL_TRUE, 0, n * sizeof(cl_int), p.light.data());
    dev.queue.enqueueReadBuffer(d_out, CL_TRUE, 0, n * sizeof(float), p.u.data());
    return p;
}

TEST(LightSampling, ThePointsFirstNumberPicksTheSlotAndStaysStratifiedWithinIt)
{
    // light_pick takes the slot from the light point's first number and rescales that
    // number within the slot's steps (light/light_pick.cl): n evenly spaced numbers
    // give each slot's light numbers evenly spaced over [0, 1) again, one in each of its
    // strata, in the same order. Broken variants seen to fail: the number left as it was,
    // and rescaled by the slot's width without its first step.
    const std::vector<LightAliasEntry> dist = build_light_distribution({1.0, 2.0, 5.0});
    const auto count = static_cast<cl_uint>(dist.size());
    const std::size_t n = 3 * 4096;
    std::vector<float> u(n);
    for (std::size_t i = 0; i < n; ++i)
        u[i] = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
    for (float coin : {0.1f, 0.9f}) {
        SCOPED_TRACE("alias coin " + std::to_string(coin));
        const Picks p = pick_on_device(dist, u, coin, 0.5f);
        const std::vector<cl_int>& picked = p.light;
        const std::vector<float>& out = p.u;
        std::vector<std::vector<float>> by_slot(count);
        for (std::size_t i = 0; i < n; ++i) {
            const auto step = static_cast<pcl_uint>(u[i] * static_cast<float>(LIGHT_PICK_GRID));
            const pcl_uint slot = light_pick_slot(step, count);
            const auto coin_step = static_cast<pcl_uint>(coin * static_cast<float>(LIGHT_PICK_GRID));
            const int light = coin_step < dist[slot].alias_threshold ? static_cast<int>(slot) : dist[slot].alias;
            ASSERT_EQ(picked[i], light) << "u " << u[i];
            ASSERT_GE(out[i], 0.0f);
            ASSERT_LT(out[i], 1.0f);
            by_slot[slot].push_back(out[i]);
        }
        for (pcl_uint j = 0; j < count; ++j) {
            const std::vector<float>& v = by_slot[j];
            ASSERT_FALSE(v.empty());
            for (std::size_t m = 0; m < v.size(); ++m) { // in u's order, one per stratum
                const auto stratum =
                    static_cast<std::size_t>(static_cast<double>(v[m]) * static_cast<double>(v.size()));
                ASSERT_EQ(stratum, m) << "slot " << j << ", number " << v[m] << " of " << v.size();
            }
        }
    }
}

TEST(LightSampling, TheStepJitterPlacesTheRescaledNumberInsideItsStep)
{
    // The samplers' numbers are multiples of 2^-24: with 2^20 lights a slot has 16 steps,
    // and without the jitter the rescaled number would take only 16 values. Broken
    // variant seen to fail: the jitter ignored (the number's own fraction in the step,
    // zero here, taken instead).
    const cl_uint count = 1u << 20;
    const std::vector<LightAliasEntry> dist = build_light_distribution(std::vector<double>(count, 1.0));
    const pcl_uint slot = 5, step = 3;
    const float u = static_cast<float>(light_pick_first_step(slot, count) + step) / static_cast<float>(LIGHT_PICK_GRID);
    for (float jitter : {0.0f, 0.25f, 0.75f}) {
        const Picks p = pick_on_device(dist, {u}, 0.5f, jitter);
        EXPECT_EQ(p.light[0], static_cast<cl_int>(slot));
        EXPECT_EQ(p.u[0], (static_cast<float>(step) + jitter) / 16.0f) << "jitter " << jitter;
    }
}

} // namespace
} // namespace pathcl::test_light_sampling
