// Camera rays on the device, checked against what the projection predicts: a thin lens
// focused on a plane of thin emissive stripes sees it as sharp as a pinhole does; a plane
// off focus is blurred by exactly the predicted circle of confusion; aperture 0 is the
// pinhole image bit for bit; an orthographic camera images a rectangle at its true size
// at any depth. Emission only (max bounces 0): a sample is 1 where its ray hits a stripe
// and 0 elsewhere, so every expectation is a coverage fraction.
#include <cmath>
#include <iostream>
#include <numbers>

#include <gtest/gtest.h>

#include "image/image_compare.h"
#include "render/renderer.h"
#include "scene/camera_overrides.h"
#include "scene/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/test_options.h"
#include "types.h"

namespace pathcl::test_camera_render {
namespace {

// Image 64 x 32; the pinhole camera at the origin looks down -Z with tan(yfov / 2) =
// 0.25, so the plane z = -4 shows x in [-2, 2], y in [-1, 1], 1/16 per pixel.
constexpr std::uint32_t kW = 64, kH = 32;
constexpr double kPlaneDepth = 4.0, kPixel = 1.0 / 16.0;

// Vertical emissive stripes on z = -4, in pixel columns from the left image border
// (x = -2): widths from 0.55 to 8 pixels, edges never on a pixel border.
const std::vector<std::pair<double, double>> kStripes = {{4.3, 4.85},  {8.3, 9.6},    {13.2, 16.7}, {21.4, 29.4},
                                                         {35.6, 36.4}, {40.25, 43.1}, {50.7, 51.9}, {55.5, 59.2}};

Scene stripes_scene()
{
    test::GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.0f), glm::vec3(1.0f));
    std::vector<glm::vec3> v;
    const float z = -static_cast<float>(kPlaneDepth), y0 = -3.0f, y1 = 3.0f;
    for (auto [a, c] : kStripes) {
        float xa = static_cast<float>(-2.0 + a * kPixel), xb = static_cast<float>(-2.0 + c * kPixel);
        v.insert(v.end(), {{xa, y0, z}, {xb, y0, z}, {xb, y1, z}, {xa, y0, z}, {xb, y1, z}, {xa, y1, z}});
    }
    b.add_root(b.add_node(b.add_mesh(b.add_positions(v), -1, mat)));
    b.add_camera_node(b.add_perspective_camera(2.0 * std::atan(0.25)), {0.0, 0.0, 0.0});
    return import_gltf(b.model, "stripes");
}

// The part of the unit disk with x < t.
double disk_fraction_below(double t)
{
    if (t <= -1.0)
        return 0.0;
    if (t >= 1.0)
        return 1.0;
    return 0.5 + (t * std::sqrt(1.0 - t * t) + std::asin(t)) / std::numbers::pi;
}

// Length of the overlap of [a, b) and [c, d).
double overlap(double a, double b, double c, double d)
{
    return std::max(0.0, std::min(b, d) - std::max(a, c));
}

// Expected value of image column `col`: the mean over the column's footprint (box
// filter) of the fraction of a disk of radius r (pixels; 0: a point) around each film
// position that the stripes cover. Exact for r = 0; midpoint rule on a smooth
// integrand (error < 1e-6) otherwise.
double expected_column(int col, double r)
{
    double sum = 0.0;
    if (r == 0.0) {
        for (auto [a, b] : kStripes)
            sum += overlap(col, col + 1.0, a, b);
        return sum;
    }
    const int steps = 400;
    for (int i = 0; i < steps; ++i) {
        double x = col + (i + 0.5) / steps;
        for (auto [a, b] : kStripes)
            sum += disk_fraction_below((b - x) / r) - disk_fraction_below((a - x) / r);
    }
    return sum / steps;
}

struct ColumnCheck {
    int failures = 0; // columns more than 5 standard errors (1e-6 where exact) off
    double worst_z = 0.0;
};

// Column means of the image (all rows and samples) against expected_column(r). A sample
// is 1 or 0, so with expectation E per column a sample's variance is at most E (1 - E)
// (equal when the coverage is the same across the pixel): the standard error uses that
// bound (conservative; never zero where 0 < E < 1, unlike a measured variance when no
// sample happened to hit).
ColumnCheck check_columns(const Image& img, double r)
{
    ColumnCheck c;
    for (std::uint32_t x = 0; x < img.width; ++x) {
        double mean = 0.0;
        for (std::uint32_t y = 0; y < img.height; ++y)
            mean += img.rgb[(static_cast<std::size_t>(y) * img.width + x) * 3];
        mean /= img.height;
        double e = expected_column(static_cast<int>(x), r);
        double se = std::sqrt(e * (1.0 - e) / (static_cast<double>(img.spp) * img.height));
        double diff = std::abs(mean - e);
        double z = se > 1e-9 ? diff / se : (diff > 1e-6 ? INFINITY : 0.0);
        c.worst_z = std::max(c.worst_z, z);
        if (z > 5.0)
            ++c.failures;
    }
    return c;
}

RenderOptions stripe_options(SamplerType sampler = SamplerType::Independent)
{
    RenderOptions o = test::independent_options();
    o.width = kW;
    o.height = kH;
    o.spp = 256;
    o.max_bounces = 0;
    o.seed = 21;
    o.sampler = sampler;
    return o;
}

Scene with_lens(double aperture, double focus_distance)
{
    Scene s = stripes_scene();
    CameraOverrides o;
    o.aperture = aperture;
    o.focus_distance = focus_distance;
    apply_camera_overrides(s, o);
    return s;
}

TEST(ThinLens, PlaneAtTheFocusDistanceStaysAsSharpAsThePinholeImage)
{
    // Lens radius 0.2 (3.2 pixels of blur on this plane were it off focus), focus on the
    // plane: every lens ray through a film position meets the plane where the pinhole
    // ray does. The column means match the sharp (r = 0) expectation and the image
    // matches a pinhole render pixel by pixel (statistical comparison, separate
    // variances). Broken variant seen to fail: the focus point taken at distance D along
    // the normalized pinhole direction (a sphere of focus, not a plane).
    RenderResult pinhole = render(stripes_scene(), stripe_options());
    RenderResult lens = render(with_lens(0.2, kPlaneDepth), stripe_options());
    EXPECT_EQ(lens.stats.bad_samples, 0u);
    ColumnCheck sharp = check_columns(lens.image, 0.0);
    EXPECT_EQ(sharp.failures, 0) << "worst |z| " << sharp.worst_z;
    EXPECT_EQ(check_columns(pinhole.image, 0.0).failures, 0);
    CompareOptions co;
    co.pooled_variance = false;
    CompareReport cmp = compare_images(lens.image, pinhole.image, co);
    EXPECT_TRUE(cmp.passed) << cmp.summary();
}

TEST(ThinLens, PlaneOffFocusIsBlurredByThePredictedCircleOfConfusion)
{
    // A lens of radius R focused at D sees a point of the plane at depth Z spread over a
    // disk of radius R |Z - D| / D on that plane (uniform: the lens is sampled uniformly
    // by area). R = 0.125, D = 2: 0.125 = 2 pixels; D = 8: 1 pixel. Each column mean is
    // z-tested against the box-filtered coverage of that disk (5 standard errors); the
    // same image must fail against the sharp expectation and against a circle of half or
    // twice the radius, which shows the test can tell. Independent and Sobol samplers
    // (the per-pixel variance overestimates Sobol's error: conservative). Broken
    // variants seen to fail: the lens radius used as a diameter; a square lens (no
    // concentric disk map).
    for (SamplerType sampler : {SamplerType::Independent, SamplerType::Sobol})
        for (double focus : {2.0, 8.0}) {
            SCOPED_TRACE("sampler " + sampler_name(sampler) + " focus distance " + std::to_string(focus));
            const double aperture = 0.125;
            const double r_pixels = aperture * std::abs(kPlaneDepth - focus) / focus / kPixel;
            RenderResult lens = render(with_lens(aperture, focus), stripe_options(sampler));
            EXPECT_EQ(lens.stats.bad_samples, 0u);
            ColumnCheck blurred = check_columns(lens.image, r_pixels);
            EXPECT_EQ(blurred.failures, 0)
                << "circle of confusion " << r_pixels << " px, worst |z| " << blurred.worst_z;
            EXPECT_GT(check_columns(lens.image, 0.0).failures, 10);
            EXPECT_GT(check_columns(lens.image, 0.5 * r_pixels).failures, 5);
            EXPECT_GT(check_columns(lens.image, 2.0 * r_pixels).failures, 5);
        }
}

TEST(ThinLens, ApertureZeroIsExactlyThePinholeImage)
{
    // Bit for bit: aperture 0 compiles no lens code and makes the same rays. The Cornell
    // box (radiance varies continuously with the ray, unlike the stripes), the camera
    // moved off the render-space origin (--look-from), where a lens ray of radius 0
    // would round differently from the pinhole ray. Broken variant seen to fail:
    // sending aperture 0 through the thin-lens code.
    RenderOptions o = test::independent_options();
    o.width = o.height = 32;
    o.spp = 4;
    CameraOverrides moved;
    moved.look_from = glm::dvec3(0.27, 0.3, -0.75);
    moved.look_at = glm::dvec3(0.28, 0.27, 0.3);
    Scene pinhole_scene = load_gltf(std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box.gltf");
    apply_camera_overrides(pinhole_scene, moved);
    Scene zero_scene = pinhole_scene;
    CameraOverrides zero;
    zero.aperture = 0.0;
    zero.focus_distance = 1.0;
    apply_camera_overrides(zero_scene, zero);
    Image pinhole = render(pinhole_scene, o).image;
    Image lens = render(zero_scene, o).image;
    EXPECT_EQ(pinhole.rgb, lens.rgb);
    EXPECT_EQ(pinhole.variance, lens.variance);
}

// An orthographic camera (ymag 1) at z = 0 looking down -Z and one emissive rectangle
// at depth `depth` whose edges cut pixels at 0.4 to 0.6 of their width.
constexpr double kRectX0 = -1.5 + 16.5 / 16, kRectX1 = -1.5 + 32.6 / 16;
constexpr double kRectY0 = 1.0 - 20.55 / 16, kRectY1 = 1.0 - 6.6 / 16;

Scene orthographic_scene(double depth)
{
    test::GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.0f), glm::vec3(1.0f));
    float z = -static_cast<float>(depth);
    auto x0 = static_cast<float>(kRectX0), x1 = static_cast<float>(kRectX1);
    auto y0 = static_cast<float>(kRectY0), y1 = static_cast<float>(kRectY1);
    std::vector<glm::vec3> v = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y0, z}, {x1, y1, z}, {x0, y1, z}};
    b.add_root(b.add_node(b.add_mesh(b.add_positions(v), -1, mat)));
    tinygltf::Camera cam;
    cam.type = "orthographic";
    cam.orthographic.xmag = 7.0; // ignored: the image's aspect ratio sets the width
    cam.orthographic.ymag = 1.0;
    cam.orthographic.znear = 0.01;
    cam.orthographic.zfar = 100.0;
    b.model.cameras.push_back(cam);
    b.add_camera_node(static_cast<int>(b.model.cameras.size()) - 1, {0.0, 0.0, 0.0});
    return import_gltf(b.model, "orthographic");
}

TEST(OrthographicCamera, ImagesARectangleAtItsTrueSizeAtAnyDepth)
{
    // 48 x 32 pixels: ymag 1 keeps y in [-1, 1], the width follows the image: x in
    // [-1.5, 1.5]; each pixel is 1/16 square. Every pixel's mean is z-tested (5
    // standard errors, from the bound E (1 - E) on a 0/1 sample's variance; exact where
    // the pixel is fully in or out) against the fraction of its footprint the rectangle
    // covers, at depth 2 and at depth 50. Broken variant seen to fail: the perspective
    // mapping (film offset on the direction).
    for (double depth : {2.0, 50.0}) {
        RenderOptions o = test::independent_options();
        o.width = 48;
        o.height = 32;
        o.spp = 256;
        o.max_bounces = 0;
        o.seed = 4;
        Image img = render(orthographic_scene(depth), o).image;
        int failures = 0;
        for (std::uint32_t y = 0; y < o.height; ++y)
            for (std::uint32_t x = 0; x < o.width; ++x) {
                double x0 = -1.5 + x / 16.0, y1 = 1.0 - y / 16.0; // pixel footprint, y down the image
                double e = overlap(x0, x0 + 1.0 / 16.0, kRectX0, kRectX1) *
                           overlap(y1 - 1.0 / 16.0, y1, kRectY0, kRectY1) * 256.0;
                std::size_t i = (static_cast<std::size_t>(y) * o.width + x) * 3;
                double se = std::sqrt(e * (1.0 - e) / o.spp);
                double diff = std::abs(img.rgb[i] - e);
                if (se > 1e-9 ? diff > 5.0 * se : diff > 1e-6)
                    ++failures;
            }
        EXPECT_EQ(failures, 0) << "depth " << depth;
    }
}

} // namespace
} // namespace pathcl::test_camera_render
