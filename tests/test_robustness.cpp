// Geometric hard cases (gaps, slivers, far lights, terminators) that need only diffuse
// surfaces and area lights. Each test
// names the naive variant it catches.
#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include "bvh/bvh_builder.h"
#include "image/image_compare.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/device_fixture.h"
#include "support/gltf_builder.h"
#include "support/leaf_triangles.h"
#include "support/test_options.h"
#include "types.h"

namespace pathcl::test_robustness {
namespace {

// Renders scene at size x size pixels with spp samples and max_bounces, with the kernel
// patched (a broken variant, say), and expects no NaN/Inf sample.
RenderResult render_square(const Scene& scene, std::uint32_t size, std::uint32_t spp, std::uint32_t max_bounces,
                           const std::vector<KernelPatch>& patches = {})
{
    RenderOptions o = test::independent_options();
    o.width = o.height = size;
    o.spp = spp;
    o.max_bounces = max_bounces;
    o.kernel_patches = patches;
    RenderResult r = render(scene, o);
    EXPECT_EQ(r.stats.bad_samples, 0u);
    return r;
}

// Radiance seen by a narrow camera looking straight down at (x, 0, 0) on a floor, lit by
// a directional light at 45 degrees (towards +x), under a slab 1e-4 above the floor that
// covers x < 0. One bounce: direct light only.
std::vector<float> thin_gap_view(double x)
{
    test::GltfBuilder b;
    int floor_mat = b.add_material(glm::vec3(0.5f));
    int slab_mat = b.add_material(glm::vec3(0.5f), glm::vec3(0.0f), /*double_sided=*/true);
    auto quad = [&](std::vector<glm::vec3> q, int mat) { b.add_root(b.add_node(b.add_quad_mesh(q, mat))); };
    quad({{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}, floor_mat);                // faces +y
    quad({{-1, 1e-4f, -1}, {-1, 1e-4f, 1}, {0, 1e-4f, 1}, {0, 1e-4f, -1}}, slab_mat); // the gap's roof
    const double a = std::acos(-1.0) / 4.0;
    glm::dquat look_down(std::sqrt(0.5), -std::sqrt(0.5), 0.0, 0.0);   // node -Z to -Y
    glm::dquat q = glm::angleAxis(a, glm::dvec3(0, 0, 1)) * look_down; // then towards +x
    b.add_light_node(b.add_light("directional", glm::vec3(1.0f), 1.0), {0.0, 1.0, 0.0}, {q.x, q.y, q.z, q.w});
    b.add_camera_node(b.add_perspective_camera(0.04), {x, 1e-3, 0.0},
                      {look_down.x, look_down.y, look_down.z, look_down.w});
    RenderResult r = render_square(import_gltf(b.model, "thin-gap"), 8, 4, 1);
    return r.image.rgb;
}

TEST(Robustness, NoLightLeaksThroughA1em4Gap)
{
    // The slab's edge shadows the floor strip 0 < x < 1e-4; the camera sees 3e-5..7e-5
    // of it: exactly black. Naive variant that fails: a fixed ray epsilon larger than
    // the gap (2e-4 lifts shadow-ray origins above the slab and lights the strip).
    for (float v : thin_gap_view(5e-5))
        ASSERT_EQ(v, 0.0f) << "light leaked under the slab";
    // Control: the floor beyond the shadow is lit (rho / pi * E cos 45).
    for (float v : thin_gap_view(5e-4))
        EXPECT_NEAR(v, 0.5 / std::acos(-1.0) * std::sqrt(0.5), 1e-4);
}

TEST(Robustness, SliversAndRepeatedVerticesGiveNoNaNAndNoSpuriousHit)
{
    // Rays against a sliver (height 1e-7 over a unit base) and triangles with two
    // identical vertices: barycentrics stay finite, degenerate triangles are never hit,
    // and the sliver is hit only inside its (tiny) extent. In the watertight test a
    // degenerate triangle has t x det = 0 and is rejected by the t range check. Naive
    // variant that fails (run here too, below): Moller-Trumbore without a determinant
    // check and with "reject if outside" range checks, which let NaN through: it
    // reports hits with NaN barycentrics on the degenerate triangles.
    static cl::Program program = test::build_test_program("trace_test_kernels.cl");
    ClDevice& dev = test::test_device();
    std::vector<Triangle> tris = {
        {{0, 0, 0, 0}, {1, 0, 0, 0}, {0.5f, 1e-7f, 0, 0}}, // sliver
        {{0, 1, 0, 0}, {0, 1, 0, 0}, {1, 2, 0, 0}},        // two identical vertices
        {{2, 0, 0, 0}, {2, 0, 0, 0}, {2, 0, 0, 0}},        // a point
        {{3, 0, 0, 0}, {4, 0, 0, 0}, {5, 0, 0, 0}},        // collinear
    };
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-0.5f, 5.5f), tiny(-2e-7f, 2e-7f);
    std::vector<pcl_float4> o, d;
    for (int i = 0; i < 20000; ++i) {
        // Rays along -z through points on or right next to the degenerate shapes.
        float x = u(rng), y = (i % 2) ? tiny(rng) : u(rng) * 0.5f;
        o.push_back({x, y, 1.0f, 0});
        d.push_back({0, 0, -1, 0});
    }
    std::size_t n = o.size();
    cl::Buffer bo(dev.context, CL_MEM_COPY_HOST_PTR, n * sizeof(pcl_float4), o.data());
    cl::Buffer bd(dev.context, CL_MEM_COPY_HOST_PTR, n * sizeof(pcl_float4), d.data());
    cl::Buffer bt(dev.context, CL_MEM_COPY_HOST_PTR, tris.size() * sizeof(Triangle), tris.data());
    std::vector<TriangleBlock> singles = test::single_triangle_blocks(tris);
    cl::Buffer bs(dev.context, CL_MEM_COPY_HOST_PTR, singles.size() * sizeof(TriangleBlock), singles.data());
    cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    // Hits that break the rules: on a degenerate triangle, non-finite, at the wrong t,
    // or outside the sliver's extent.
    auto violations = [&](const char* kernel) {
        cl::Kernel k(program, kernel);
        set_kernel_args(k, bo, bd, bt, bs, static_cast<cl_uint>(tris.size()), out);
        dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
        std::vector<pcl_float4> h(n);
        dev.queue.enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(pcl_float4), h.data());
        std::size_t bad = 0;
        for (std::size_t i = 0; i < n; ++i) {
            int tri = std::bit_cast<int>(h[i].w);
            if (tri < 0)
                continue;
            bool finite = std::isfinite(h[i].x) && std::isfinite(h[i].y) && std::isfinite(h[i].z);
            bool inside = o[i].x >= 0.0f && o[i].x <= 1.0f && std::fabs(o[i].y) <= 1.01e-7f;
            bad += tri != 0 || !finite || std::fabs(h[i].x - 1.0f) > 1e-6f || !inside;
        }
        return bad;
    };
    EXPECT_EQ(violations("test_trace_brute_force"), 0u);
    EXPECT_GT(violations("test_trace_brute_force_naive"), 0u) << "the checks above must catch a naive test";
}

} // namespace
} // namespace pathcl::test_robustness

namespace pathcl::test_robustness {
namespace {

// Mean and standard error of the green channel over the central 4x4 pixels of a 16x16
// image, which see only the object in the middle.
struct CentreMean {
    double mean = 0.0, stderr_ = 0.0;
};

CentreMean centre_mean(const RenderResult& r, std::uint32_t spp)
{
    double sum = 0.0, var = 0.0;
    int n = 0;
    for (std::uint32_t y = 6; y < 10; ++y)
        for (std::uint32_t x = 6; x < 10; ++x) {
            std::size_t i = (static_cast<std::size_t>(y) * 16 + x) * 3 + 1;
            sum += r.image.rgb[i];
            var += r.image.variance[i] / static_cast<double>(spp);
            ++n;
        }
    return {sum / n, std::sqrt(var) / n};
}

TEST(Robustness, GlassSphereAndSlabInAWhiteFurnaceAreInvisible)
{
    // Solid glass (white, ior 1.5) under a constant environment of radiance 1: light
    // entering it leaves it again (radiance scaled by 1/eta^2 going in and eta^2 coming
    // out, total internal reflection in between; in the slab, seen at a slant, much of
    // it), so every pixel is 1: exactly for smooth glass (every path's weight is 1), to
    // the interface albedo table's accuracy (1e-3 here) for rough glass. Naive variants
    // seen failing: single-scattering rough glass without energy compensation (sphere
    // 0.987 at roughness 0.3 and 0.812 at 0.6, slab 0.962 and 0.623); Russian roulette
    // on the radiance throughput, which inside glass holds 1/eta^2 (smooth glass gets a
    // standard error of 3.6e-4 instead of 0).
    for (bool slab : {false, true})
        for (double roughness : {0.0, 0.3, 0.6}) {
            SCOPED_TRACE(std::string(slab ? "slab" : "sphere") + ", roughness " + std::to_string(roughness));
            test::GltfBuilder b;
            test::GltfBuilder::Pbr glass;
            glass.roughness = roughness;
            glass.transmission = 1.0;
            glass.thickness = 1.0;
            int mat = b.add_pbr_material(glass);
            if (slab) // a 2 x 0.4 x 2 slab turned 30 degrees about x, seen edge-on-ish
                b.add_root(b.add_node(b.add_box_mesh({1.0f, 0.2f, 1.0f}, mat), {}, {}, {0.2588, 0.0, 0.0, 0.9659}));
            else
                b.add_root(b.add_node(b.add_sphere_mesh(1.0, 24, 48, mat, /*inward=*/false)));
            b.add_camera_node(b.add_perspective_camera(slab ? 0.15 : 0.3), {0.0, 0.0, 5.0});
            Scene s = import_gltf(b.model, "glass-furnace");
            s.environment.present = true;
            s.environment.constant = glm::vec3(1.0f);
            const std::uint32_t spp = 1024;
            RenderResult r = render_square(s, 16, spp, 1000);
            CentreMean m = centre_mean(r, spp);
            if (roughness == 0.0) {
                EXPECT_NEAR(m.mean, 1.0, 1e-5);
                EXPECT_LT(m.stderr_, 1e-5);
            } else {
                // Sharp enough to see the uncompensated loss (2 % at roughness 0.3, 19 % at 0.6).
                EXPECT_LT(m.stderr_, roughness < 0.5 ? 0.003 : 0.02);
                EXPECT_NEAR(m.mean, 1.0, 1e-3 + 5.0 * m.stderr_);
            }
        }
}

} // namespace
} // namespace pathcl::test_robustness

namespace pathcl::test_robustness {
namespace {

// A unit sphere (stacks x slices, smooth vertex normals) lit by a directional light at a
// slant, seen by a 64x64 camera from +z: direct light only.
Image lit_sphere(int stacks, int slices)
{
    test::GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f));
    b.add_root(b.add_node(b.add_sphere_mesh(1.0, stacks, slices, mat, /*inward=*/false, /*smooth_normals=*/true)));
    // The light travels along -(cos 20 cos 10, sin 20, cos 20 sin 10): its terminator
    // crosses the facets of a UV sphere at a slant instead of following their edges.
    glm::dvec3 from(0.0, 0.0, -1.0), to = -glm::normalize(glm::dvec3(0.9254, 0.3420, 0.1632));
    glm::dvec3 axis = glm::cross(from, to);
    glm::dquat q = glm::normalize(glm::dquat(1.0 + glm::dot(from, to), axis.x, axis.y, axis.z));
    b.add_light_node(b.add_light("directional", glm::vec3(3.0f), 1.0), {3.0, 1.0, 0.5}, {q.x, q.y, q.z, q.w});
    b.add_camera_node(b.add_perspective_camera(0.6), {0.0, 0.0, 4.0});
    RenderResult r = render_square(import_gltf(b.model, "terminator"), 64, 16, 1);
    return r.image;
}

TEST(Robustness, ShadowTerminatorOfALowPolySphereMatchesAFineOne)
{
    // Smooth normals on a coarse sphere lit from the side: near the terminator the
    // shading normals still face the light where the flat facets face away from it. Rays
    // leave from the smooth surface the vertex normals describe (Hanika 2021), so the
    // coarse sphere (12 x 24) shows what a finely tessellated one (96 x 192) shows.
    // Compared over the pixels on the lit side of the terminator (radiance below an
    // eighth of the maximum), away from the silhouette, where the two spheres differ in
    // shape; the coarse one's interpolated normals leave it 2.7 % darker there (measured).
    // Naive variant that fails: reflection only above the geometric surface, no lift
    // (30 % darker: the faceted band).
    Image fine = lit_sphere(96, 192), coarse = lit_sphere(12, 24);
    float peak = *std::max_element(fine.rgb.begin(), fine.rgb.end());
    double sum_fine = 0.0, sum_coarse = 0.0;
    int n = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            // The sphere's outline has a radius of about 25 pixels around the centre.
            double dx = x - 31.5, dy = y - 31.5;
            std::size_t i = (static_cast<std::size_t>(y) * 64 + x) * 3 + 1;
            if (dx * dx + dy * dy > 18.0 * 18.0 || !(fine.rgb[i] > 0.0f) || fine.rgb[i] > peak / 8.0f)
                continue;
            sum_fine += fine.rgb[i];
            sum_coarse += coarse.rgb[i];
            ++n;
        }
    ASSERT_GT(n, 50);
    EXPECT_NEAR(sum_coarse / n, sum_fine / n, 0.05 * sum_fine / n);
}

} // namespace
} // namespace pathcl::test_robustness

namespace pathcl::test_robustness {
namespace {

TEST(Robustness, ClosedFurnaceWithGlassAndMetalsInsideStaysUniform)
{
    // A closed sphere whose inside emits 0.5 and reflects half (Lambertian): radiance 1
    // everywhere in equilibrium. Lossless objects inside (white glass, smooth and rough;
    // white metal, smooth and rough; white rough plastic) see radiance 1 from every
    // direction and so return 1 in every direction: the whole image is 1, to the layer
    // tables' accuracy. Any energy gain or loss in those BSDFs shows as a tile that is
    // not 1. Naive variant that fails: rough lobes without multiple-scattering
    // compensation (the rough glass and metal tiles darken).
    test::GltfBuilder b;
    int wall = b.add_material(glm::vec3(0.5f), glm::vec3(0.5f));
    b.add_root(b.add_node(b.add_sphere_mesh(4.0, 24, 48, wall, /*inward=*/true)));
    auto object = [&](test::GltfBuilder::Pbr pbr, std::vector<double> at) {
        int mat = b.add_pbr_material(pbr);
        b.add_root(b.add_node(b.add_sphere_mesh(0.6, 24, 48, mat, /*inward=*/false, /*smooth_normals=*/true), {}, at));
    };
    test::GltfBuilder::Pbr glass;
    glass.transmission = 1.0;
    glass.thickness = 1.0;
    object(glass, {-1.4, 0.7, 0.0});
    glass.roughness = 0.6;
    object(glass, {0.0, 0.7, 0.0});
    test::GltfBuilder::Pbr metal;
    metal.metallic = 1.0;
    object(metal, {1.4, 0.7, 0.0});
    metal.roughness = 0.6;
    object(metal, {-0.7, -0.7, 0.0});
    test::GltfBuilder::Pbr plastic;
    plastic.roughness = 0.4;
    object(plastic, {0.7, -0.7, 0.0});
    b.add_camera_node(b.add_perspective_camera(1.2), {0.0, 0.0, 3.0});
    const std::uint32_t spp = 512;
    RenderResult r = render_square(import_gltf(b.model, "closed-furnace"), 32, spp, 1000);
    // 8x8 tiles against 1, with a Šidák-corrected threshold for the 16 tiles.
    const double z_max = sidak_z_threshold(0.01, 16);
    for (int ty = 0; ty < 4; ++ty)
        for (int tx = 0; tx < 4; ++tx) {
            double sum = 0.0, var = 0.0;
            for (int y = ty * 8; y < ty * 8 + 8; ++y)
                for (int x = tx * 8; x < tx * 8 + 8; ++x) {
                    std::size_t i = (static_cast<std::size_t>(y) * 32 + x) * 3 + 1;
                    sum += r.image.rgb[i];
                    var += r.image.variance[i] / static_cast<double>(spp);
                }
            double mean = sum / 64.0, se = std::sqrt(var) / 64.0;
            EXPECT_LT(se, 0.01) << "tile " << tx << "," << ty;
            EXPECT_LE(std::abs(mean - 1.0), z_max * se + 1e-3) << "tile " << tx << "," << ty << ": " << mean;
        }
}

} // namespace
} // namespace pathcl::test_robustness

namespace pathcl::test_robustness {
namespace {

TEST(Robustness, AnOccluderRightNextToADistantPointLightCastsItsShadow)
{
    // A point light 100 above a plane and a small shade 5e-3 below the light (5e-5 of the
    // way): the point under it is in shadow. Naive variant that fails: shadow rays cut
    // short by a fixed 1e-4 of their length (1 cm here), which skips the shade entirely.
    test::GltfBuilder b;
    int floor_mat = b.add_material(glm::vec3(0.5f));
    int shade_mat = b.add_material(glm::vec3(0.5f), glm::vec3(0.0f), /*double_sided=*/true);
    auto quad = [&](std::vector<glm::vec3> q, int mat) { b.add_root(b.add_node(b.add_quad_mesh(q, mat))); };
    quad({{-200, 0, -200}, {-200, 0, 200}, {200, 0, 200}, {200, 0, -200}}, floor_mat);
    quad({{-0.01f, 99.995f, -0.01f}, {-0.01f, 99.995f, 0.01f}, {0.01f, 99.995f, 0.01f}, {0.01f, 99.995f, -0.01f}},
         shade_mat);
    b.add_light_node(b.add_light("point", glm::vec3(1.0f), 1e4), {0.0, 100.0, 0.0});
    const std::vector<double> look_down = {-std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)};
    b.add_camera_node(b.add_perspective_camera(1e-3), {0.0, 3.0, 0.0}, look_down);
    RenderResult r = render_square(import_gltf(b.model, "lamp-shade"), 4, 1, 1);
    for (float v : r.image.rgb)
        EXPECT_EQ(v, 0.0f) << "light passed the shade";
}

} // namespace
} // namespace pathcl::test_robustness

namespace pathcl::test_robustness {
namespace {

// Two concentric Lambertian spheres of radius 1 and 1 + 1e-4 (the same 12 x 24 UV
// tessellation, so their facets are parallel 1e-4 apart, with smooth vertex normals)
// and 18 point lights in the gap, 5e-5 from both, on vertex directions on both sides of
// z = 0. Seen from outside (a camera on +z) or from the centre (looking along -z) no
// light can arrive: both shells are closed. `shells`: 1 inner only, 2 outer only, 3 both.
Image concentric_spheres_view(bool from_inside, int shells, const std::vector<KernelPatch>& patches)
{
    test::GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.8f), glm::vec3(0.0f), /*double_sided=*/true);
    if (shells & 1)
        b.add_root(b.add_node(b.add_sphere_mesh(1.0, 12, 24, mat, /*inward=*/false, /*smooth_normals=*/true)));
    if (shells & 2)
        b.add_root(b.add_node(b.add_sphere_mesh(1.0 + 1e-4, 12, 24, mat, /*inward=*/false, /*smooth_normals=*/true)));
    int light = b.add_light("point", glm::vec3(1.0f), 1.0);
    for (int i : {3, 6, 9})
        for (int j : {3, 6, 9, 15, 18, 21}) {
            double theta = std::numbers::pi * i / 12, phi = 2.0 * std::numbers::pi * j / 24, r = 1.0 + 5e-5;
            b.add_light_node(
                light, {r * std::sin(theta) * std::cos(phi), r * std::cos(theta), r * std::sin(theta) * std::sin(phi)});
        }
    if (from_inside)
        b.add_camera_node(b.add_perspective_camera(1.6), {0.0, 0.0, 0.0});
    else
        b.add_camera_node(b.add_perspective_camera(0.6), {0.0, 0.0, 4.0});
    RenderResult r = render_square(import_gltf(b.model, "concentric-spheres"), 32, 16, 2, patches);
    return r.image;
}

// A naive renderer: the shading normal alone decides on which side a direction leaves
// (no lift onto the smooth surface), and rays start pushed to their direction's side.
std::vector<KernelPatch> shading_normal_only()
{
    return {{"geom/surface_point.cl", "    sp.material = sh.material;\n",
             "    sp.p_smooth = sp.p;\n    sp.lifted = false;\n    sp.material = sh.material;\n"},
            {"geom/ray_offset.cl", "return cos_ig > 0.0f || sp->lifted;", "return true;"},
            {"geom/ray_offset.cl", "        return offset_ray_origin(sp->p_smooth, sp->p_error, sp->ng, sp->ng);\n",
             "        return offset_ray_origin(sp->p, sp->p_error, sp->ng, w);\n"}};
}

std::size_t lit_pixels(const Image& im)
{
    std::size_t n = 0;
    for (std::size_t i = 0; i < im.rgb.size(); i += 3)
        n += im.rgb[i] > 0.0f || im.rgb[i + 1] > 0.0f || im.rgb[i + 2] > 0.0f;
    return n;
}

TEST(Robustness, NoLightLeaksAcrossA1em4GapBetweenConcentricSpheres)
{
    // Smooth vertex normals tilt by up to 7.5 degrees from the facets, so from a point
    // on a shell, lights in the gap a little way off lie above the shading normal's
    // horizon although they are behind the facet. Naive variant that fails
    // (shading_normal_only(), both views): the shading normal alone decides
    // whether a direction is reflected, and rays start 1e-4 along their direction, which
    // puts shadow rays inside the gap.
    for (bool inside : {false, true}) {
        SCOPED_TRACE(inside ? "seen from the centre" : "seen from outside");
        EXPECT_EQ(lit_pixels(concentric_spheres_view(inside, 3, {})), 0u) << "light leaked across the gap";
        EXPECT_GT(lit_pixels(concentric_spheres_view(inside, 3, shading_normal_only())), 10u)
            << "the naive renderer should leak here";
    }
    // Control: without the inner shell, the lights are seen lighting the outer one from
    // the centre. (From outside, the inner shell alone is lit only within about 0.01 of
    // each light: 5e-5 above a vertex is below the smooth sphere's horizon elsewhere.)
    EXPECT_GT(lit_pixels(concentric_spheres_view(true, 2, {})), 500u);
}

} // namespace
} // namespace pathcl::test_robustness
