// The material extensions that change how other fields are read (host only, no device):
// KHR_materials_ior's ior 0 (specular-glossiness mode),
// KHR_materials_pbrSpecularGlossiness, read as the metallic-roughness material in that
// mode, and KHR_materials_clearcoat's, _sheen's and _anisotropy's factors. Next to each
// test: a broken variant seen to fail it.
#include <algorithm>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.h"
#include "compile/kernel_features.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "support/expect_error.h"
#include "support/gltf_builder.h"
#include "support/gltf_fixtures.h"

namespace pathcl::test_gltf_material_extensions {
namespace {

using test::contains;
using test::error_of;
using test::GltfBuilder;
using test::import;
using test::json_numbers;
using test::kTilted;
using test::one_triangle;
using test::set_anisotropy;
using test::set_clearcoat;
using test::set_sheen;
using test::tilted_triangle_with;

void set_ior(tinygltf::Material& m, double ior)
{
    tinygltf::Value::Object o;
    o["ior"] = tinygltf::Value(ior);
    m.extensions["KHR_materials_ior"] = tinygltf::Value(o);
}

TEST(GltfMaterialExtensions, IorZeroIsTheSpecularGlossinessModeAndOtherIorsBelowOneAreErrors)
{
    // ior 0 is valid (the schema's special value) and compiles the Schlick layer; 0.5 and
    // -1 are errors naming the field. Broken variant seen to fail: the old check (ior >= 1).
    Scene s = import(tilted_triangle_with([](tinygltf::Material& m) { set_ior(m, 0.0); }));
    EXPECT_EQ(s.materials[0].ior, 0.0f);
    EXPECT_TRUE(kernel_features(s, RenderOptions{}).has(FEATURE_SCHLICK_LAYER));
    EXPECT_FALSE(kernel_features(import(one_triangle(kTilted)), RenderOptions{}).has(FEATURE_SCHLICK_LAYER));
    for (double bad : {0.5, -1.0}) {
        std::string e = error_of([&] { import(tilted_triangle_with([&](tinygltf::Material& m) { set_ior(m, bad); }));
    });
    EXPECT_TRUE(contains(e, "test.gltf: material 0") && contains(e, "KHR_materials_ior ior must be")) << e;
}
}

TEST(GltfMaterialExtensions, IorZeroTransmitsNothingAndSaysSo)
{
    // The Fresnel term of ior 0 is 1: transmission is dropped with one warning line.
    // Broken variant seen to fail: transmission kept (refraction at eta 0 is undefined).
    GltfBuilder b = tilted_triangle_with([](tinygltf::Material& m) {
        set_ior(m, 0.0);
        tinygltf::Value::Object t;
        t["transmissionFactor"] = tinygltf::Value(0.7);
        m.extensions["KHR_materials_transmission"] = tinygltf::Value(t);
    });
    ::testing::internal::CaptureStderr();
    Scene s = import(b);
    std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(s.materials[0].transmission, 0.0f);
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_TRUE(contains(err, "test.gltf: material 0") && contains(err, "transmission is not rendered")) << err;
}

TEST(GltfMaterialExtensions, ClearcoatFactorsAreReadAndCompileTheCoat)
{
    // A coat compiles the coat code; a material without one, or with factor 0, does not.
    // The extension is read, so it is not reported as ignored. Broken variants seen to
    // fail: the roughness read from clearcoatFactor; the feature set for factor 0.
    GltfBuilder b = tilted_triangle_with([](tinygltf::Material& m) { set_clearcoat(m, 0.7, 0.2); });
    b.model.extensionsUsed = {"KHR_materials_clearcoat"};
    ::testing::internal::CaptureStderr();
    Scene s = import(b);
    std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_TRUE(err.empty()) << err;
    EXPECT_FLOAT_EQ(s.materials[0].clearcoat, 0.7f);
    EXPECT_FLOAT_EQ(s.materials[0].clearcoat_roughness, 0.2f);
    EXPECT_TRUE(kernel_features(s, RenderOptions{}).has(FEATURE_CLEARCOAT));
    Scene none = import(tilted_triangle_with([](tinygltf::Material& m) { set_clearcoat(m, 0.0, 0.5); }));
    EXPECT_FALSE(kernel_features(none, RenderOptions{}).has(FEATURE_CLEARCOAT));
    EXPECT_FALSE(kernel_features(import(one_triangle(kTilted)), RenderOptions{}).has(FEATURE_CLEARCOAT));
}

TEST(GltfMaterialExtensions, SheenFactorsAndTexturesAreReadAndCompileTheSheen)
{
    // A sheen colour above 0 compiles the sheen code; colour 0 (the default) is no sheen,
    // whatever its roughness. Its textures fill their slots, the colour's as sRGB. The
    // extension is read, so it is not reported as ignored. Broken variants seen to fail:
    // the roughness read from the colour's first channel.
    GltfBuilder b = tilted_triangle_with([](tinygltf::Material& m) { set_sheen(m, {0.2, 0.4, 0.6}, 0.3); });
    b.model.extensionsUsed = {"KHR_materials_sheen"};
    int color = b.add_texture(b.add_png_image(1, 1, {255, 255, 255, 255}));
    int roughness = b.add_texture(b.add_png_image(1, 1, {0, 0, 0, 128}));
    tinygltf::Value::Object o = b.model.materials[0].extensions["KHR_materials_sheen"].Get<tinygltf::Value::Object>();
    o["sheenColorTexture"] = test::texture_info(color);
    o["sheenRoughnessTexture"] = test::texture_info(roughness, 1);
    b.model.materials[0].extensions["KHR_materials_sheen"] = tinygltf::Value(o);
    b.set_attribute(0, "TEXCOORD_0", b.add_texcoords({{0, 0}, {1, 0}, {0, 1}}));
    b.set_attribute(0, "TEXCOORD_1", b.add_texcoords({{0, 0}, {1, 0}, {0, 1}}));
    ::testing::internal::CaptureStderr();
    Scene s = import(b);
    std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_TRUE(err.empty()) << err;
    EXPECT_EQ(s.materials[0].sheen_color, glm::vec3(0.2f, 0.4f, 0.6f));
    EXPECT_FLOAT_EQ(s.materials[0].sheen_roughness, 0.3f);
    EXPECT_TRUE(s.materials[0].textures[TEXTURE_SLOT_SHEEN_COLOR].present());
    EXPECT_TRUE(s.materials[0].textures[TEXTURE_SLOT_SHEEN_ROUGHNESS].present());
    EXPECT_EQ(s.materials[0].textures[TEXTURE_SLOT_SHEEN_ROUGHNESS].texcoord, 1);
    EXPECT_TRUE(kernel_features(s, RenderOptions{}).has(FEATURE_SHEEN));
    Scene none = import(tilted_triangle_with([](tinygltf::Material& m) { set_sheen(m, {0.0, 0.0, 0.0}, 0.5); }));
    EXPECT_FALSE(kernel_features(none, RenderOptions{}).has(FEATURE_SHEEN));
    EXPECT_FALSE(kernel_features(import(one_triangle(kTilted)), RenderOptions{}).has(FEATURE_SHEEN));
}

TEST(GltfMaterialExtensions, SheenOutOfRangeIsAnError)
{
    // A colour channel or roughness outside [0, 1] is a one-line error naming the field.
    using Case = std::tuple<std::vector<double>, double, const char*>;
    for (const auto& [color, roughness, field] :
         {Case{{0.5, 1.5, 0.5}, 0.0, "sheenColorFactor"}, Case{{-0.1, 0.0, 0.0}, 0.0, "sheenColorFactor"},
          Case{{0.5, 0.5, 0.5}, -0.2, "sheenRoughnessFactor"}}) {
        auto edit = [&](tinygltf::Material& m) { set_sheen(m, color, roughness); };
        std::string e = error_of([&] { import(tilted_triangle_with(edit)); });
        EXPECT_TRUE(contains(e, "test.gltf: material 0") && contains(e, std::string(field) + " must lie in [0, 1]"))
            << e;
    }
}

TEST(GltfMaterialExtensions, AnisotropyIsReadWithItsTextureAndTangents)
{
    // Strength and rotation are read, the texture fills its slot, and the triangle gets
    // tangents (computed from TEXCOORD_0 here: +x for u along x); strength 0 (the default)
    // compiles nothing. Broken variants seen to fail: FEATURE_ANISOTROPY set for strength
    // 0; no tangents for an anisotropic material without a normal texture.
    GltfBuilder b = one_triangle({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    set_anisotropy(b.model.materials[0], 0.6, 0.25);
    b.model.extensionsUsed = {"KHR_materials_anisotropy"};
    tinygltf::Value::Object o =
        b.model.materials[0].extensions["KHR_materials_anisotropy"].Get<tinygltf::Value::Object>();
    o["anisotropyTexture"] = test::texture_info(b.add_texture(b.add_png_image(1, 1, {255, 128, 255, 255})));
    b.model.materials[0].extensions["KHR_materials_anisotropy"] = tinygltf::Value(o);
    b.set_attribute(0, "TEXCOORD_0", b.add_texcoords({{0, 0}, {1, 0}, {0, 1}}));
    ::testing::internal::CaptureStderr();
    Scene s = import(b);
    std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_TRUE(err.empty()) << err;
    EXPECT_FLOAT_EQ(s.materials[0].anisotropy, 0.6f);
    EXPECT_FLOAT_EQ(s.materials[0].anisotropy_rotation, 0.25f);
    EXPECT_TRUE(s.materials[0].textures[TEXTURE_SLOT_ANISOTROPY].present());
    EXPECT_TRUE(kernel_features(s, RenderOptions{}).has(FEATURE_ANISOTROPY));
    ASSERT_EQ(s.tangents.size(), 1u);
    for (const glm::vec4& t : s.tangents[0])
        EXPECT_LT(glm::length(glm::vec3(t) - glm::vec3(1, 0, 0)), 1e-6f) << t.x << " " << t.y << " " << t.z;
    Scene none = import(tilted_triangle_with([](tinygltf::Material& m) { set_anisotropy(m, 0.0, 1.0); }));
    EXPECT_FALSE(kernel_features(none, RenderOptions{}).has(FEATURE_ANISOTROPY));
    EXPECT_TRUE(none.tangents.empty());
}

TEST(GltfMaterialExtensions, AnisotropyWithoutTangentsOrTexcoordsWarnsAndOutOfRangeIsAnError)
{
    // An anisotropic primitive with neither TANGENT nor texture coordinates gets some
    // direction in the surface and one warning line; a strength outside [0, 1] or a
    // rotation that is not finite is an error naming the field.
    ::testing::internal::CaptureStderr();
    Scene s = import(tilted_triangle_with([](tinygltf::Material& m) { set_anisotropy(m, 0.5); }));
    std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_TRUE(contains(err, "1 primitive with KHR_materials_anisotropy has neither TANGENT nor texture coordinates"))
        << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    ASSERT_EQ(s.tangents.size(), 1u);
    EXPECT_NEAR(glm::length(glm::vec3(s.tangents[0][0])), 1.0f, 1e-6f);
    for (double bad : {1.5, -0.1}) {
        std::string e = error_of([&] { import(tilted_triangle_with([&](tinygltf::Material& m) { set_anisotropy(m, bad); }));
    });
    EXPECT_TRUE(contains(e, "test.gltf: material 0") && contains(e, "anisotropyStrength must lie in [0, 1]")) << e;
}
}

TEST(GltfMaterialExtensions, AnisotropyOnATransmittingSolidSaysItIsApproximate)
{
    // A transmitting solid keeps the isotropic roughness on its interface: one warning
    // line naming the material. A thin-walled transmitter and an opaque plastic are
    // anisotropic as the extension says, without a word.
    auto material = [](double transmission, double thickness) {
        return [=](tinygltf::Material& m) {
            set_anisotropy(m, 0.5);
            tinygltf::Value::Object t, v;
            t["transmissionFactor"] = tinygltf::Value(transmission);
            m.extensions["KHR_materials_transmission"] = tinygltf::Value(t);
            v["thicknessFactor"] = tinygltf::Value(thickness);
            m.extensions["KHR_materials_volume"] = tinygltf::Value(v);
        };
    };
    ::testing::internal::CaptureStderr();
    import(tilted_triangle_with(material(0.8, 0.1)));
    std::string err = ::testing::internal::GetCapturedStderr();
    const std::string said = "test.gltf: material 0 (): KHR_materials_anisotropy on a transmitting solid is "
                             "approximate: its interface keeps the isotropic roughness\n";
    ASSERT_NE(err.find(said), std::string::npos) << err;
    EXPECT_EQ(err.find(said, err.find(said) + 1), std::string::npos) << "said twice: " << err;
    for (auto [transmission, thickness] : {std::pair{0.8, 0.0}, std::pair{0.0, 0.1}}) {
        ::testing::internal::CaptureStderr();
        import(tilted_triangle_with(material(transmission, thickness)));
        err = ::testing::internal::GetCapturedStderr();
        EXPECT_EQ(err.find("isotropic"), std::string::npos) << transmission << " " << thickness << ": " << err;
    }
}

TEST(GltfMaterialExtensions, ClearcoatOutOfRangeIsAnError)
{
    // Factors outside [0, 1], and a clearcoatNormalTexture scale that is not a number, are
    // one-line errors naming the field.
    using Case = std::tuple<double, double, const char*>;
    for (auto [factor, roughness, field] : {Case{1.5, 0.0, "clearcoatFactor"}, Case{-0.1, 0.0, "clearcoatFactor"},
                                            Case{0.5, 2.0, "clearcoatRoughnessFactor"}}) {
        auto edit = [&](tinygltf::Material& m) { set_clearcoat(m, factor, roughness); };
        std::string e = error_of([&] { import(tilted_triangle_with(edit)); });
        EXPECT_TRUE(contains(e, "test.gltf: material 0") && contains(e, std::string(field) + " must lie in [0, 1]"))
            << e;
    }
    GltfBuilder b = tilted_triangle_with([](tinygltf::Material& m) {
        tinygltf::Value::Object o, normal;
        o["clearcoatFactor"] = tinygltf::Value(1.0);
        normal["index"] = tinygltf::Value(0);
        normal["scale"] = tinygltf::Value(std::string("large"));
        o["clearcoatNormalTexture"] = tinygltf::Value(normal);
        m.extensions["KHR_materials_clearcoat"] = tinygltf::Value(o);
    });
    b.add_texture(b.add_png_image(1, 1, {128, 128, 255, 255}));
    std::string e = error_of([&] { import(b); });
    EXPECT_TRUE(contains(e, "test.gltf: material 0") && contains(e, "clearcoatNormalTexture scale must be finite"))
        << e;
}

TEST(GltfMaterialExtensions, ClearcoatNormalTextureIsReadWithItsScale)
{
    // Read into its slot with its scale; it compiles the normal-map code and gives the
    // triangles tangents even without a normalTexture. With a normalTexture of another
    // texture coordinate set, one warning line says the coat's map follows the other set's
    // tangents. Broken variant seen to fail: the scale not read (1).
    for (int base_set : {-1, 0, 1}) {
        SCOPED_TRACE("normalTexture texCoord " + std::to_string(base_set));
        GltfBuilder b = tilted_triangle_with([&](tinygltf::Material& m) {
            tinygltf::Value::Object o, normal;
            o["clearcoatFactor"] = tinygltf::Value(1.0);
            normal["index"] = tinygltf::Value(0);
            normal["scale"] = tinygltf::Value(0.6);
            o["clearcoatNormalTexture"] = tinygltf::Value(normal);
            m.extensions["KHR_materials_clearcoat"] = tinygltf::Value(o);
            if (base_set >= 0) {
                m.normalTexture.index = 0;
                m.normalTexture.texCoord = base_set;
            }
        });
        b.add_texture(b.add_png_image(1, 1, {128, 128, 255, 255}));
        tinygltf::Primitive& prim = b.model.meshes[0].primitives[0];
        for (const char* set : {"TEXCOORD_0", "TEXCOORD_1"})
            prim.attributes[set] = b.add_texcoords({{0, 0}, {1, 0}, {0, 1}});
        ::testing::internal::CaptureStderr();
        Scene s = import(b);
        std::string err = ::testing::internal::GetCapturedStderr();
        const SceneMaterial& m = s.materials[0];
        EXPECT_TRUE(m.textures[TEXTURE_SLOT_CLEARCOAT_NORMAL].present());
        EXPECT_EQ(m.textures[TEXTURE_SLOT_CLEARCOAT_NORMAL].texcoord, 0);
        EXPECT_FLOAT_EQ(m.clearcoat_normal_scale, 0.6f);
        EXPECT_EQ(s.tangents.size(), s.triangles.size());
        EXPECT_TRUE(kernel_features(s, RenderOptions{}).has(FEATURE_NORMAL_MAPS));
        if (base_set == 1) {
            EXPECT_TRUE(contains(err, "test.gltf: material 0") &&
                        contains(err, "clearcoatNormalTexture reads TEXCOORD_0 but the tangents follow normalTexture's "
                                      "TEXCOORD_1"))
                << err;
        }
        EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), base_set == 1 ? 1 : 0) << err;
    }
}

TEST(GltfMaterialExtensions, SpecularGlossinessFactorsBecomeTheIorZeroMaterial)
{
    // diffuse -> base colour and alpha, specular -> KHR_materials_specular colour (weight
    // 1), glossiness -> 1 - roughness, metallic 0, ior 0; the metallic-roughness fallback
    // and a file-level requirement of the extension are accepted. Broken variants seen to
    // fail: the fallback's metallic kept; roughness = glossiness.
    GltfBuilder b = tilted_triangle_with([](tinygltf::Material& m) {
        m.pbrMetallicRoughness.metallicFactor = 1.0;
        m.pbrMetallicRoughness.roughnessFactor = 0.1;
        m.pbrMetallicRoughness.baseColorFactor = {0.1, 0.1, 0.1, 1.0};
        tinygltf::Value::Object sg;
        sg["diffuseFactor"] = json_numbers({0.8, 0.6, 0.4, 0.5});
        sg["specularFactor"] = json_numbers({0.3, 0.2, 0.1});
        sg["glossinessFactor"] = tinygltf::Value(0.75);
        m.extensions["KHR_materials_pbrSpecularGlossiness"] = tinygltf::Value(sg);
    });
    b.model.extensionsUsed = {"KHR_materials_pbrSpecularGlossiness"};
    b.model.extensionsRequired = {"KHR_materials_pbrSpecularGlossiness"};
    ::testing::internal::CaptureStderr();
    Scene s = import(b);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    const SceneMaterial& m = s.materials[0];
    EXPECT_EQ(m.base_color, glm::vec3(0.8f, 0.6f, 0.4f));
    EXPECT_EQ(m.alpha, 0.5f);
    EXPECT_EQ(m.metallic, 0.0f);
    EXPECT_EQ(m.roughness, 0.25f);
    EXPECT_EQ(m.specular, 1.0f);
    EXPECT_EQ(m.specular_color, glm::vec3(0.3f, 0.2f, 0.1f));
    EXPECT_EQ(m.ior, 0.0f);
    EXPECT_FALSE(m.glossiness_texture);

    // An empty extension object: the extension's defaults (white diffuse, white specular,
    // glossiness 1: a smooth white mirror-like layer over white).
    Scene d = import(tilted_triangle_with([](tinygltf::Material& mat) {
        mat.extensions["KHR_materials_pbrSpecularGlossiness"] = tinygltf::Value(tinygltf::Value::Object{});
    }));
    EXPECT_EQ(d.materials[0].base_color, glm::vec3(1.0f));
    EXPECT_EQ(d.materials[0].specular_color, glm::vec3(1.0f));
    EXPECT_EQ(d.materials[0].roughness, 0.0f);
    EXPECT_EQ(d.materials[0].metallic, 0.0f);
}

TEST(GltfMaterialExtensions, SpecularGlossinessValuesOutOfRangeAreOneLineErrors)
{
    // Broken variant seen to fail: glossinessFactor unchecked (roughness -0.5 reaches the
    // kernels).
    struct Case {
        const char* member;
        tinygltf::Value value;
    };
    const Case cases[] = {{"diffuseFactor", json_numbers({1.2, 0.5, 0.5, 1.0})},
                          {"diffuseFactor", json_numbers({0.5, 0.5, 0.5})},
                          {"specularFactor", json_numbers({0.5, -0.1, 0.5})},
                          {"glossinessFactor", tinygltf::Value(1.5)},
                          {"glossinessFactor", tinygltf::Value(std::string("high"))}};
    for (const Case& c : cases) {
        std::string e = error_of([&] {
            import(tilted_triangle_with([&](tinygltf::Material& m) {
                tinygltf::Value::Object sg;
            sg[c.member] = c.value;
            m.extensions["KHR_materials_pbrSpecularGlossiness"] = tinygltf::Value(sg);
            }));
    });
    EXPECT_TRUE(contains(e, "test.gltf: material 0") &&
                contains(e, std::string("KHR_materials_pbrSpecularGlossiness ") + c.member + " must lie in"))
        << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}
}

// Two triangles, each its own primitive with material 0 ("red"); the file has materials
// green (1) and blue (2) and variants "green" and "blue". The first primitive maps
// green -> 1 and blue -> 2; the second has no mappings.
GltfBuilder variant_scene()
{
    GltfBuilder b;
    int red = b.add_material(glm::vec3(1, 0, 0));
    b.add_material(glm::vec3(0, 1, 0));
    b.add_material(glm::vec3(0, 0, 1));
    int mapped = b.add_mesh(b.add_positions(kTilted), -1, red);
    b.add_root(b.add_node(mapped));
    b.add_root(b.add_node(b.add_mesh(b.add_positions(kTilted), -1, red), {}, {0.0, 0.0, 5.0}));
    auto variant = [](const char* name) {
        tinygltf::Value::Object o;
        o["name"] = tinygltf::Value(std::string(name));
        return tinygltf::Value(o);
    };
    tinygltf::Value::Object root;
    root["variants"] = tinygltf::Value(tinygltf::Value::Array{variant("green"), variant("blue")});
    b.model.extensions["KHR_materials_variants"] = tinygltf::Value(root);
    b.model.extensionsUsed = {"KHR_materials_variants"};
    auto mapping = [](int material, std::vector<int> variants) {
        tinygltf::Value::Object o;
        o["material"] = tinygltf::Value(material);
        tinygltf::Value::Array v;
        for (int i : variants)
            v.emplace_back(i);
        o["variants"] = tinygltf::Value(v);
        return tinygltf::Value(o);
    };
    tinygltf::Value::Object ext;
    ext["mappings"] = tinygltf::Value(tinygltf::Value::Array{mapping(1, {0}), mapping(2, {1})});
    b.model.meshes[static_cast<std::size_t>(mapped)].primitives[0].extensions["KHR_materials_variants"] =
        tinygltf::Value(ext);
    return b;
}

// The base colours of the scene's triangles, in order.
std::vector<glm::vec3> colours(const Scene& s)
{
    std::vector<glm::vec3> out;
    for (const SceneTriangle& t : s.triangles)
        out.push_back(s.materials[static_cast<std::size_t>(t.material)].base_color);
    return out;
}

TEST(GltfMaterialExtensions, VariantsPickTheMappedMaterialAndTheDefaultIsThePrimitivesOwn)
{
    // Broken variants seen to fail: the first mapping taken whatever the variant; the
    // variant applied to primitives without mappings.
    const glm::vec3 red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1);
    GltfBuilder b = variant_scene();
    Scene d = import_gltf(b.model, "v.gltf");
    EXPECT_EQ(d.material_variants, (std::vector<std::string>{"green", "blue"}));
    EXPECT_EQ(colours(d), (std::vector<glm::vec3>{red, red}));
    EXPECT_EQ(colours(import_gltf(b.model, "v.gltf", "", {-1, "green"})), (std::vector<glm::vec3>{green, red}));
    Scene blue_scene = import_gltf(b.model, "v.gltf", "", {-1, "blue"});
    EXPECT_EQ(colours(blue_scene), (std::vector<glm::vec3>{blue, red}));
    EXPECT_EQ(blue_scene.variant, "blue");
}

TEST(GltfMaterialExtensions, AVariantTheFileLacksIsAParameterErrorNamingThoseItHas)
{
    try {
        import_gltf(variant_scene().model, "v.gltf", "", {-1, "gold"});
        ADD_FAILURE() << "did not throw";
    } catch (const ParameterError& e) {
        EXPECT_EQ(e.parameter(), "variant");
        EXPECT_TRUE(contains(e.what(), "no material variant \"gold\": v.gltf has \"green\", \"blue\"")) << e.what();
    }
    std::string none = error_of([] { import_gltf(one_triangle(kTilted).model, "t.gltf", "", {-1, "gold"}); });
    EXPECT_TRUE(contains(none, "t.gltf has none")) << none;
}

TEST(GltfMaterialExtensions, MalformedVariantMappingsAreErrorsNamingThePrimitive)
{
    // Checked whatever the variant chosen (here the default).
    auto with_mapping = [](const std::function<void(tinygltf::Value::Object&)>& edit) {
        GltfBuilder b = variant_scene();
        tinygltf::Value::Object m;
        m["material"] = tinygltf::Value(1);
        m["variants"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(0)});
        edit(m);
        tinygltf::Value::Object ext;
        ext["mappings"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(m)});
        b.model.meshes[0].primitives[0].extensions["KHR_materials_variants"] = tinygltf::Value(ext);
        return error_of([&] { import_gltf(b.model, "v.gltf"); });
    };
    std::string e = with_mapping([](tinygltf::Value::Object& m) { m["material"] = tinygltf::Value(3); });
    EXPECT_TRUE(contains(e, "v.gltf: node 0") && contains(e, "mapping 0: material must be the index")) << e;
    e = with_mapping([](tinygltf::Value::Object& m) {
        m["variants"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(2)});
    });
    EXPECT_TRUE(contains(e, "mapping 0: variants lists a variant that does not exist")) << e;
    e = with_mapping([](tinygltf::Value::Object& m) { m.erase("variants"); });
    EXPECT_TRUE(contains(e, "mapping 0: variants must be a non-empty array")) << e;
}

} // namespace
} // namespace pathcl::test_gltf_material_extensions
