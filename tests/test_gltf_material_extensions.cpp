// The material extensions that change how other fields are read (host only, no device):
// KHR_materials_ior's ior 0 (specular-glossiness mode) and
// KHR_materials_pbrSpecularGlossiness, read as the metallic-roughness material in that
// mode. Next to each test: a broken variant seen to fail it.
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/kernel_features.h"
#include "scene/scene.h"
#include "support/expect_error.h"
#include "support/gltf_builder.h"
#include "support/gltf_fixtures.h"

namespace pathcl {
namespace {

using test::contains;
using test::error_of;
using test::GltfBuilder;
using test::import;
using test::kTilted;
using test::one_triangle;

tinygltf::Value numbers(std::vector<double> v)
{
    tinygltf::Value::Array a;
    for (double x : v)
        a.emplace_back(x);
    return tinygltf::Value(a);
}

// One triangle whose material `edit` changes; the scene it loads to.
GltfBuilder triangle_with(const std::function<void(tinygltf::Material&)>& edit)
{
    GltfBuilder b = one_triangle(kTilted);
    edit(b.model.materials[0]);
    return b;
}

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
    Scene s = import(triangle_with([](tinygltf::Material& m) { set_ior(m, 0.0); }));
    EXPECT_EQ(s.materials[0].ior, 0.0f);
    EXPECT_TRUE(kernel_features(s, RenderOptions{}).has(FEATURE_SCHLICK_LAYER));
    EXPECT_FALSE(kernel_features(import(one_triangle(kTilted)), RenderOptions{}).has(FEATURE_SCHLICK_LAYER));
    for (double bad : {0.5, -1.0}) {
        std::string e = error_of([&] { import(triangle_with([&](tinygltf::Material& m) { set_ior(m, bad); }));
    });
    EXPECT_TRUE(contains(e, "test.gltf: material 0") && contains(e, "KHR_materials_ior ior must be")) << e;
}
}

TEST(GltfMaterialExtensions, IorZeroTransmitsNothingAndSaysSo)
{
    // The Fresnel term of ior 0 is 1: transmission is dropped with one warning line.
    // Broken variant seen to fail: transmission kept (refraction at eta 0 is undefined).
    GltfBuilder b = triangle_with([](tinygltf::Material& m) {
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

TEST(GltfMaterialExtensions, SpecularGlossinessFactorsBecomeTheIorZeroMaterial)
{
    // diffuse -> base colour and alpha, specular -> KHR_materials_specular colour (weight
    // 1), glossiness -> 1 - roughness, metallic 0, ior 0; the metallic-roughness fallback
    // and a file-level requirement of the extension are accepted. Broken variants seen to
    // fail: the fallback's metallic kept; roughness = glossiness.
    GltfBuilder b = triangle_with([](tinygltf::Material& m) {
        m.pbrMetallicRoughness.metallicFactor = 1.0;
        m.pbrMetallicRoughness.roughnessFactor = 0.1;
        m.pbrMetallicRoughness.baseColorFactor = {0.1, 0.1, 0.1, 1.0};
        tinygltf::Value::Object sg;
        sg["diffuseFactor"] = numbers({0.8, 0.6, 0.4, 0.5});
        sg["specularFactor"] = numbers({0.3, 0.2, 0.1});
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
    Scene d = import(triangle_with([](tinygltf::Material& mat) {
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
    const Case cases[] = {{"diffuseFactor", numbers({1.2, 0.5, 0.5, 1.0})},
                          {"diffuseFactor", numbers({0.5, 0.5, 0.5})},
                          {"specularFactor", numbers({0.5, -0.1, 0.5})},
                          {"glossinessFactor", tinygltf::Value(1.5)},
                          {"glossinessFactor", tinygltf::Value(std::string("high"))}};
    for (const Case& c : cases) {
        std::string e = error_of([&] {
            import(triangle_with([&](tinygltf::Material& m) {
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

} // namespace
} // namespace pathcl
