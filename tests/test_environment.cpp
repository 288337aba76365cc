// The environment light: a white furnace (a convex diffuse object under a constant
// environment shows exactly its albedo, for every strategy), the map seen directly,
// chi-square tests of map importance sampling through the kernels' own code (a single
// bright texel; black rows; a rotation), an all-black map, and the scene-extras form.
#include <cmath>
#include <filesystem>
#include <numbers>

#include <unistd.h>

#include <gtest/gtest.h>

#include "common/error.h"
#include "compile/environment.h"
#include "compile/light_distribution.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/chi_square.h"
#include "support/device_fixture.h"
#include "support/gltf_builder.h"
#include "support/test_options.h"

namespace pathcl::test_environment {
namespace {

constexpr double kPi = std::numbers::pi;

// A convex sphere of albedo 0.8 filling the view's centre, under a constant background.
Scene furnace(float background)
{
    test::GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.8f));
    b.add_root(b.add_node(b.add_sphere_mesh(1.0, 16, 32, mat, /*inward=*/false)));
    b.add_camera_node(b.add_perspective_camera(0.6), {0.0, 0.0, 5.0});
    Scene s = import_gltf(b.model, "env-furnace");
    s.environment.present = true;
    s.environment.constant = glm::vec3(background);
    return s;
}

TEST(Environment, WhiteFurnaceSphereShowsItsAlbedoForEveryStrategy)
{
    // Every direction from a convex surface escapes: L = albedo x background exactly.
    for (Strategy strategy : {Strategy::Bsdf, Strategy::Nee, Strategy::OneSample, Strategy::Mis}) {
        RenderOptions o = test::independent_options();
        o.width = o.height = 16;
        o.spp = 64;
        o.strategy = strategy;
        RenderResult r = render(furnace(1.0f), o);
        EXPECT_EQ(r.stats.bad_samples, 0u);
        double sum = 0.0, var = 0.0;
        int n = 0;
        for (std::uint32_t y = 6; y < 10; ++y) // the central 4x4 pixels see only the sphere
            for (std::uint32_t x = 6; x < 10; ++x) {
                std::size_t i = (static_cast<std::size_t>(y) * 16 + x) * 3 + 1;
                sum += r.image.rgb[i];
                var += r.image.variance[i] / static_cast<double>(o.spp);
                ++n;
            }
        double mean = sum / n, se = std::sqrt(var) / n;
        EXPECT_NEAR(mean, 0.8, 1e-5 + 5.0 * se) << "strategy " << strategy_name(strategy);
        // The corner pixels see the background itself: exactly 1.
        EXPECT_NEAR(r.image.rgb[1], 1.0f, 1e-6f);
    }
}

// A map of w x h texels, value(i, j) each, as the device reads it.
EnvironmentMap make_map(std::uint32_t w, std::uint32_t h,
                        const std::function<float(std::uint32_t, std::uint32_t)>& value)
{
    EnvironmentMap m;
    m.width = w;
    m.height = h;
    for (std::uint32_t j = 0; j < h; ++j)
        for (std::uint32_t i = 0; i < w; ++i) {
            float v = value(i, j);
            m.texels.push_back({v, v, v, 0.0f});
        }
    build_environment_distribution(m);
    return m;
}

// Independent host pdf: texel weight lum x sin(theta at the row centre), normalized over
// (u, v), divided by 2 pi^2 sin(theta) of the direction; the map turned by `rotation`.
std::function<double(const glm::dvec3&)> host_environment_pdf(const EnvironmentMap& m, double rotation)
{
    std::vector<double> w(m.texels.size());
    double total = 0.0;
    for (std::uint32_t j = 0; j < m.height; ++j)
        for (std::uint32_t i = 0; i < m.width; ++i) {
            std::size_t k = static_cast<std::size_t>(j) * m.width + i;
            w[k] = m.texels[k].y * std::sin(kPi * (j + 0.5) / m.height);
            total += w[k];
        }
    return [=](const glm::dvec3& world) {
        double c = std::cos(rotation), s = std::sin(rotation);
        glm::dvec3 d(c * world.x - s * world.z, world.y, s * world.x + c * world.z);
        double u = std::atan2(d.x, -d.z) / (2.0 * kPi);
        if (u < 0.0)
            u += 1.0;
        double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
        auto i = std::min<std::uint32_t>(static_cast<std::uint32_t>(u * m.width), m.width - 1);
        auto j = std::min<std::uint32_t>(static_cast<std::uint32_t>(v * m.height), m.height - 1);
        double sin_theta = std::sqrt(std::max(0.0, 1.0 - d.y * d.y));
        double p_uv = w[static_cast<std::size_t>(j) * m.width + i] / total * m.width * m.height;
        return sin_theta > 0.0 ? p_uv / (2.0 * kPi * kPi * sin_theta) : 0.0;
    };
}

std::vector<pcl_float4> sample_environment(const EnvironmentMap& m, double rotation, std::size_t n,
                                           std::vector<pcl_float4>* radiance = nullptr)
{
    static cl::Program program = test::build_test_program("trace_test_kernels.cl", FEATURE_ENVIRONMENT);
    SceneArrays a;
    Light l{};
    l.type = LIGHT_ENVIRONMENT;
    l.data.environment = {m.width, m.height, static_cast<float>(std::cos(rotation)),
                          static_cast<float>(std::sin(rotation))};
    a.lights = {l};
    a.light_distribution = build_light_distribution({1.0});
    a.env_texels = m.texels;
    a.env_marginal = m.marginal_cdf;
    a.env_conditional = m.conditional_cdf;
    return test::sample_lights_on_device(program, a, glm::vec3(0.0f), 77u, n, radiance);
}

// The texel value a world direction sees (independent of the kernel's lookup).
float host_texel(const EnvironmentMap& m, double rotation, const glm::dvec3& world)
{
    double c = std::cos(rotation), s = std::sin(rotation);
    glm::dvec3 d(c * world.x - s * world.z, world.y, s * world.x + c * world.z);
    double u = std::atan2(d.x, -d.z) / (2.0 * kPi);
    if (u < 0.0)
        u += 1.0;
    double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
    auto i = std::min<std::uint32_t>(static_cast<std::uint32_t>(u * m.width), m.width - 1);
    auto j = std::min<std::uint32_t>(static_cast<std::uint32_t>(v * m.height), m.height - 1);
    return m.texels[static_cast<std::size_t>(j) * m.width + i].y;
}

void expect_sampling_matches(const EnvironmentMap& m, double rotation, int tests)
{
    auto pdf = host_environment_pdf(m, rotation);
    std::vector<pcl_float4> radiance;
    auto s = sample_environment(m, rotation, 1000000, &radiance);
    // Weight = radiance / pdf: the radiance a sample carries is the map's value there.
    std::size_t wrong_radiance = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s[i].w > 0.0f)
            wrong_radiance +=
                radiance[i].y != host_texel(m, rotation, glm::normalize(glm::dvec3(s[i].x, s[i].y, s[i].z)));
    EXPECT_LE(wrong_radiance, s.size() / 100000) << "samples whose radiance is not the map's value in their direction";
    test::ChiSquareResult r = test::chi_square_directions(test::to_directions(s), pdf, 10, 20, 0.01, tests);
    EXPECT_TRUE(r.passed) << r.summary();
    std::size_t bad = 0;
    for (const pcl_float4& v : s)
        if (v.w > 0.0f) {
            double host = pdf(glm::normalize(glm::dvec3(v.x, v.y, v.z)));
            bad += !(std::fabs(v.w - host) <= 2e-3 * host);
        }
    // A direction on a texel edge belongs to whichever texel float (kernel) or double
    // (host) rounding says: allow 1 in 1e5 such samples, no more.
    EXPECT_LE(bad, s.size() / 100000) << "kernel pdf differs from the host pdf";
}

TEST(Environment, SamplingMatchesPdfWithBlackRowsAndRotation)
{
    EnvironmentMap m = make_map(16, 8, [](std::uint32_t i, std::uint32_t j) {
        return (j == 0 || j == 3) ? 0.0f : 0.2f + 0.1f * static_cast<float>((i * 7 + j * 3) % 11);
    });
    expect_sampling_matches(m, 0.0, 2);
    expect_sampling_matches(m, 30.0 * kPi / 180.0, 2);
}

TEST(Environment, SamplingASingleBrightTexel)
{
    // Everything black but one texel: every sample must land in that texel's region.
    EnvironmentMap m =
        make_map(8, 4, [](std::uint32_t i, std::uint32_t j) { return (i == 5 && j == 1) ? 50.0f : 0.0f; });
    expect_sampling_matches(m, 0.0, 1);
}

TEST(Environment, AllBlackMapRendersBlackAndFinite)
{
    RenderOptions o = test::independent_options();
    o.width = o.height = 8;
    o.spp = 8;
    RenderResult r = render(furnace(0.0f), o);
    EXPECT_EQ(r.stats.bad_samples, 0u);
    for (float v : r.image.rgb)
        ASSERT_EQ(v, 0.0f);
}

TEST(Environment, SceneExtrasUriMustStayInsideTheSceneDirectory)
{
    test::GltfBuilder b;
    tinygltf::Value::Object env, extras;
    env["uri"] = tinygltf::Value(std::string("../../etc/sky.exr"));
    extras["environment"] = tinygltf::Value(env);
    b.model.scenes[0].extras = tinygltf::Value(extras);
    try {
        import_gltf(b.model, "escape.gltf", "/tmp");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("leaves the scene's directory"), std::string::npos) << e.what();
    }
    // Inside the directory: the image is read when the scene is loaded (a missing one is
    // an error naming it then, not at render time).
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("pathcl-env-" + std::to_string(::getpid()));
    fs::create_directories(dir / "maps");
    env["uri"] = tinygltf::Value(std::string("maps/sky.exr"));
    extras["environment"] = tinygltf::Value(env);
    b.model.scenes[0].extras = tinygltf::Value(extras);
    try {
        import_gltf(b.model, "missing.gltf", dir.string());
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("sky.exr"), std::string::npos) << e.what();
    }
    Image sky;
    sky.width = 2;
    sky.height = 1;
    sky.spp = 1;
    sky.rgb = {0.5f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f};
    sky.variance.assign(6, 0.0f);
    write_image((dir / "maps" / "sky.exr").string(), sky);
    Scene s = import_gltf(b.model, "ok.gltf", dir.string());
    EXPECT_TRUE(s.environment.present);
    EXPECT_EQ(s.environment.path, (dir / "maps" / "sky.exr").string());
    EXPECT_EQ(s.environment.width, 2u);
    EXPECT_EQ(s.environment.height, 1u);
    EXPECT_EQ(s.environment.rgb, sky.rgb);
    fs::remove_all(dir);
}

} // namespace
} // namespace pathcl::test_environment
