// Renders with textures, compared statistically (host/image/image_compare.h): constant
// textures give the Cornell box's committed reference, a flat normal map gives the same
// image as none, a textured emitter gives the same image by every light-sampling
// strategy, scenes/textured.gltf matches its committed reference, and normal maps that
// point into the surface neither go black nor make NaN. Every render has zero NaN/Inf
// samples. Next to each test: the deliberately broken variant that was seen to fail it.
#include <cmath>
#include <iostream>
#include <numbers>

#include <gtest/gtest.h>

#include "compile/texture_lookup.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/render_checks.h"
#include "support/test_options.h"
#include "types.h"
#include <tiny_gltf.h>

namespace pathcl::test_render_textures {
namespace {

const std::string kSource = PATHCL_SOURCE_DIR;
constexpr int kNearest = 9728, kLinear = 9729, kRepeat = 10497, kMirror = 33648;

RenderOptions small_options(std::uint32_t size, std::uint32_t spp, std::uint32_t seed)
{
    RenderOptions o = test::independent_options();
    o.width = o.height = size;
    o.spp = spp;
    o.seed = seed;
    return o;
}

// Adds a zero TEXCOORD_0 to every primitive that lacks one.
void add_texcoords_everywhere(test::GltfBuilder& b)
{
    for (tinygltf::Mesh& mesh : b.model.meshes)
        for (tinygltf::Primitive& prim : mesh.primitives)
            if (!prim.attributes.count("TEXCOORD_0")) {
                std::size_t n = b.model.accessors[static_cast<std::size_t>(prim.attributes.at("POSITION"))].count;
                prim.attributes["TEXCOORD_0"] = b.add_texcoords(std::vector<glm::vec2>(n, glm::vec2(0.3f, 0.6f)));
            }
}

// The smallest 8-bit sRGB value that decodes to at least `linear` (so factor = linear /
// decoded stays within [0, 1]).
std::uint8_t srgb_byte_at_least(float linear)
{
    for (int b = 0; b < 256; ++b)
        if (srgb8_to_linear(static_cast<std::uint8_t>(b)) >= linear)
            return static_cast<std::uint8_t>(b);
    return 255;
}

TEST(RenderTextures, ConstantTexturesRenderTheCornellBoxReference)
{
    // Every base colour of the Cornell box moved into a 1 x 1 sRGB texture (factor =
    // colour / decoded texel), the light's radiance split the same way between
    // emissiveFactor and an emissive texture, and a constant metallic-roughness texture:
    // the same materials, so the committed reference must match. Broken variants seen to
    // fail: base-colour texels used without sRGB decoding; the emissive texture applied to
    // hits but not to light samples.
    tinygltf::TinyGLTF loader;
    tinygltf::Model cornell;
    std::string err, warning;
    ASSERT_TRUE(loader.LoadASCIIFromFile(&cornell, &err, &warning, kSource + "/scenes/cornell-box.gltf")) << err;
    test::GltfBuilder b;
    b.model = cornell; // (tinygltf appends to a model it loads into, so not into the builder's)
    add_texcoords_everywhere(b);
    for (tinygltf::Material& m : b.model.materials) {
        std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
        std::vector<std::uint8_t> texel = {0, 0, 0, 255};
        for (std::size_t c = 0; c < 3; ++c) {
            texel[c] = srgb_byte_at_least(static_cast<float>(f[c]));
            f[c] = f[c] / srgb8_to_linear(texel[c]);
        }
        m.pbrMetallicRoughness.baseColorTexture.index = b.add_texture(b.add_png_image(1, 1, texel));
        m.pbrMetallicRoughness.metallicRoughnessTexture.index = b.add_texture(b.add_png_image(1, 1, {0, 255, 0, 255}));
        if (m.emissiveFactor.size() == 3 && m.emissiveFactor[0] > 0.0) {
            const std::vector<std::uint8_t> emissive = {200, 180, 90, 255};
            for (std::size_t c = 0; c < 3; ++c)
                m.emissiveFactor[c] /= srgb8_to_linear(emissive[c]);
            m.emissiveTexture.index = b.add_texture(b.add_png_image(1, 1, emissive));
        }
    }
    Scene scene = import_gltf(b.model, "textured cornell-box.gltf");
    RenderOptions o = small_options(64, 64, 7); // the settings of Render.CornellBoxMatchesCommittedReference
    RenderResult r = render(scene, o);
    EXPECT_EQ(r.stats.bad_samples, 0u);
    EXPECT_GT(r.stats.texel_bytes, 0u);
    CompareReport cmp = compare_images(r.image, read_image(kSource + "/tests/references/cornell-box-64.exr"));
    std::cout << cmp.summary();
    EXPECT_TRUE(cmp.passed) << cmp.summary();
}

// A smooth-shaded coarse sphere (normals from the centre, texture coordinates u around,
// v down) on a floor under an emissive quad; with a 1 x 1 16-bit normal texture
// `normal_texel` on the sphere when given.
Scene sphere_scene(const std::vector<std::uint16_t>& normal_texel)
{
    test::GltfBuilder b;
    std::vector<glm::vec3> p, n;
    std::vector<glm::vec2> uv;
    const int stacks = 6, slices = 12;
    for (int i = 0; i <= stacks; ++i)
        for (int j = 0; j <= slices; ++j) {
            double th = std::numbers::pi * i / stacks, ph = 2.0 * std::numbers::pi * j / slices;
            glm::dvec3 d(std::sin(th) * std::cos(ph), std::cos(th), -std::sin(th) * std::sin(ph));
            p.push_back(glm::vec3(d));
            n.push_back(glm::vec3(d));
            uv.push_back(glm::vec2(glm::dvec2(double(j) / slices, double(i) / stacks)));
        }
    std::vector<std::uint32_t> idx;
    const std::uint32_t w = slices + 1;
    for (std::uint32_t i = 0; i < stacks; ++i)
        for (std::uint32_t j = 0; j < slices; ++j) {
            std::uint32_t a = i * w + j, bb = (i + 1) * w + j, c = (i + 1) * w + j + 1, d = i * w + j + 1;
            if (i != 0)
                idx.insert(idx.end(), {a, bb, d});
            if (i != stacks - 1)
                idx.insert(idx.end(), {bb, c, d});
        }
    test::GltfBuilder::Pbr pbr;
    pbr.base_color = glm::vec3(0.8f, 0.5f, 0.3f);
    pbr.metallic = 0.0;
    pbr.roughness = 0.4;
    int sphere_mat = b.add_pbr_material(pbr);
    int sphere = b.add_mesh(b.add_positions(p), b.add_indices(idx, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT), sphere_mat, 4,
                            b.add_normals(n));
    b.set_attribute(sphere, "TEXCOORD_0", b.add_texcoords(uv));
    if (!normal_texel.empty())
        b.model.materials.back().normalTexture.index = b.add_texture(b.add_png_image16(1, 1, normal_texel));
    b.add_root(b.add_node(sphere, {}, {0.0, 1.0, 0.0}));
    int floor_mat = b.add_material(glm::vec3(0.6f));
    int floor = b.add_quad_mesh({{-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}}, floor_mat);
    b.add_root(b.add_node(floor));
    int light_mat = b.add_material(glm::vec3(0.0f), glm::vec3(6.0f));
    int light = b.add_quad_mesh({{-1, 3, -1}, {1, 3, -1}, {1, 3, 1}, {-1, 3, 1}}, light_mat);
    b.add_root(b.add_node(light, {}, {1.0, 0.0, 1.0}));
    b.add_camera_node(b.add_perspective_camera(0.7), {0.0, 1.2, 4.0});
    return import_gltf(b.model, "sphere.gltf");
}

TEST(RenderTextures, FlatNormalMapMatchesNoNormalMap)
{
    // The 16-bit texel (32768, 32768, 65535) is the flat normal up to 2^-15 (0.002
    // degrees): the coarse smooth-shaded sphere must render as without a normal map. (The
    // 8-bit (128, 128, 255) tilts it by 0.3 degrees, which brightens this image by 0.5 %:
    // a real difference, seen at 512 spp.) Broken variants seen to fail: the tangent frame
    // built around the geometric normal (facets appear); the bitangent and normal swapped
    // (also with the 16-bit texel).
    Scene plain = sphere_scene({});
    Scene mapped = sphere_scene({32768, 32768, 65535, 65535});
    RenderResult a = render(plain, small_options(48, 128, 1));
    RenderResult b = render(mapped, small_options(48, 128, 2));
    EXPECT_EQ(a.stats.bad_samples, 0u);
    EXPECT_EQ(b.stats.bad_samples, 0u);
    CompareReport cmp = compare_images(b.image, a.image);
    std::cout << cmp.summary();
    EXPECT_TRUE(cmp.passed) << cmp.summary();
}

// A diffuse floor under a 2 x 2 m emissive panel whose texture is a high-contrast 4 x 4
// checker (nearest, with a KHR_texture_transform), both in view.
Scene textured_emitter_scene()
{
    test::GltfBuilder b;
    int floor_mat = b.add_material(glm::vec3(0.7f));
    int floor = b.add_quad_mesh({{-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}}, floor_mat);
    b.add_root(b.add_node(floor));
    int light_mat = b.add_material(glm::vec3(0.0f), glm::vec3(1.0f), false, 4.0);
    std::vector<glm::vec3> lp = {{-1, 1.5, 1}, {-1, 1.5, -1}, {1, 1.5, -1}, {1, 1.5, 1}}; // faces down
    int light = b.add_quad_mesh(lp, light_mat);
    b.set_attribute(light, "TEXCOORD_0", b.add_texcoords({{0, 0}, {0, 1}, {1, 1}, {1, 0}}));
    std::vector<std::uint8_t> checker;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            bool on = (x + y) % 2 == 0;
            checker.insert(checker.end(),
                           {static_cast<std::uint8_t>(on ? 255 : 10), static_cast<std::uint8_t>(on ? 230 : 10),
                            static_cast<std::uint8_t>(on ? 120 : 40), 255});
        }
    tinygltf::TextureInfo& info = b.model.materials.back().emissiveTexture;
    info.index = b.add_texture(b.add_png_image(4, 4, checker), b.add_sampler(kNearest, kRepeat, kMirror));
    tinygltf::Value::Object t;
    t["rotation"] = tinygltf::Value(0.4);
    t["scale"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(1.5), tinygltf::Value(1.5)});
    info.extensions["KHR_texture_transform"] = tinygltf::Value(t);
    b.add_root(b.add_node(light));
    b.add_camera_node(b.add_perspective_camera(1.2), {0.0, 0.9, 3.0}, {-0.1305, 0.0, 0.0, 0.9914});
    return import_gltf(b.model, "textured-emitter.gltf");
}

TEST(RenderTextures, TexturedEmitterGivesTheSameImageByEveryStrategy)
{
    // Light sampling (nee), its MIS combination with BSDF sampling (mis) and the
    // one-sample mixture must all converge to what BSDF sampling alone finds by hitting
    // the emitter (which never uses the light sampler). Broken variants seen to fail: light
    // samples carrying the bare emissiveFactor (all three, |z| > 200); the MIS weight of a
    // BSDF-found hit computed with twice the pmf the light sampler uses (one-sample |z|
    // 6.9, mis 3.2: MIS is forgiving, the one-sample mixture is not).
    Scene scene = textured_emitter_scene();
    RenderOptions o = small_options(32, 1024, 11);
    o.max_bounces = 3;
    test::expect_same_image_by_strategies(scene, o, {Strategy::Nee, Strategy::OneSample, Strategy::Mis}, 256, 20);
}

TEST(RenderTextures, TexturedSceneMatchesItsCommittedReference)
{
    // scenes/textured.gltf (tools/make_textured_scene.py) against its 8192-spp reference
    // (tools/make_references.sh); 256 spp like the light-type scenes, for the glossy
    // floor's caustic paths. Broken variants seen to fail: normal maps ignored; the
    // texture transform ignored; vertex colours ignored.
    Scene scene = load_gltf(kSource + "/scenes/textured.gltf");
    RenderOptions o = small_options(64, 256, 7);
    o.max_bounces = 8;
    RenderResult r = render(scene, o);
    EXPECT_EQ(r.stats.bad_samples, 0u);
    CompareReport cmp = compare_images(r.image, read_image(kSource + "/tests/references/textured-64.exr"));
    std::cout << cmp.summary();
    EXPECT_TRUE(cmp.passed) << cmp.summary();
}

// A 2 x 2 plane facing +z under a constant white environment, seen from the front, with
// a 1 x 1 normal texture (scale `scale`) on a material that is Lambertian (albedo 0.5) or
// rough metal.
Scene plane_with_normal_map(const std::vector<std::uint8_t>& texel, double scale, bool metal)
{
    test::GltfBuilder b;
    test::GltfBuilder::Pbr pbr;
    pbr.base_color = glm::vec3(0.5f);
    pbr.metallic = metal ? 1.0 : 0.0;
    pbr.roughness = metal ? 0.3 : 1.0;
    pbr.specular = metal ? 1.0 : 0.0;
    int mat = b.add_pbr_material(pbr);
    int mesh = b.add_mesh(b.add_positions({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}),
                          b.add_indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT), mat, 4,
                          b.add_normals({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}}));
    b.set_attribute(mesh, "TEXCOORD_0", b.add_texcoords({{0, 1}, {1, 1}, {1, 0}, {0, 0}}));
    tinygltf::NormalTextureInfo& info = b.model.materials.back().normalTexture;
    info.index = b.add_texture(b.add_png_image(1, 1, texel));
    info.scale = scale;
    b.add_root(b.add_node(mesh));
    b.add_camera_node(b.add_perspective_camera(0.6), {0.3, 0.2, 2.0});
    Scene s = import_gltf(b.model, "bent.gltf");
    s.environment.present = true;
    s.environment.constant = glm::vec3(1.0f);
    return s;
}

TEST(RenderTextures, NormalMapsIntoTheSurfaceNeitherGoBlackNorNaN)
{
    // n_t = (0, 0, -1) (scale 0) points straight into the surface: bent back it is the
    // geometric normal, and a Lambertian plane of albedo 0.5 under a white sky shows
    // exactly 0.5. A normal at 45 degrees below the surface (texel (255, 128, 0)), on
    // Lambertian and on rough metal: finite and never black. Broken variant seen to fail:
    // no bending (the first plane renders black: no direction lies above both normals).
    struct Case {
        std::vector<std::uint8_t> texel;
        double scale;
        bool metal;
    };
    for (const Case& c : {Case{{128, 128, 0, 255}, 0.0, false}, Case{{255, 128, 0, 255}, 1.0, false},
                          Case{{255, 128, 0, 255}, 1.0, true}}) {
        SCOPED_TRACE(std::string(c.metal ? "metal" : "Lambertian") + " texel " + std::to_string(c.texel[0]) + "," +
                     std::to_string(c.texel[1]) + "," + std::to_string(c.texel[2]));
        RenderOptions o = small_options(16, 64, 5);
        o.max_bounces = 1;
        RenderResult r = render(plane_with_normal_map(c.texel, c.scale, c.metal), o);
        EXPECT_EQ(r.stats.bad_samples, 0u);
        float darkest = 1e30f;
        double sum = 0.0;
        for (std::size_t i = 0; i < r.image.rgb.size(); i += 3) {
            darkest = std::min(darkest, r.image.rgb[i]);
            sum += r.image.rgb[i];
        }
        EXPECT_GT(darkest, 0.05f) << "a black pixel";
        if (c.scale == 0.0) {
            double mean = sum / static_cast<double>(r.image.rgb.size() / 3);
            EXPECT_NEAR(mean, 0.5, 0.01) << "albedo 0.5 under a white sky";
        }
    }
}

} // namespace
} // namespace pathcl::test_render_textures
