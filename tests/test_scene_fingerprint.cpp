// The scene fingerprint that keys cached results (converge's reference, checkpoints,
// partial renders): equal for equal scenes, different when anything a render reads
// changes, and no field of a Scene left out of it unnoticed.
#include <iterator>
#include <span>

#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "scene/scene_fingerprint.h"
#include "support/field_count.h"
#include "support/gltf_builder.h"

namespace pathcl::test_scene_fingerprint {
namespace {

Scene sphere_scene()
{
    test::GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f), glm::vec3(0.5f));
    b.add_root(b.add_node(b.add_sphere_mesh(1.0, 6, 12, mat, /*inward=*/true)));
    return import_gltf(b.model, "sphere");
}

TEST(SceneFingerprint, EqualScenesAgreeAndEveryChangeShows)
{
    const Scene base = sphere_scene();
    const std::uint64_t f = scene_fingerprint(base);
    EXPECT_EQ(scene_fingerprint(sphere_scene()), f);
    EXPECT_EQ(scene_fingerprint_hex(base).size(), 16u);

    Scene s = base;
    s.materials[0].roughness += 0.25f;
    EXPECT_NE(scene_fingerprint(s), f) << "material";
    s = base;
    s.triangles[3].v[1].x = std::nextafter(s.triangles[3].v[1].x, 2.0f);
    EXPECT_NE(scene_fingerprint(s), f) << "one ulp of one vertex";
    s = base;
    s.environment.present = true;
    s.environment.constant = glm::vec3(1.0f);
    EXPECT_NE(scene_fingerprint(s), f) << "environment";
    s = base;
    s.camera.yfov *= 1.01;
    EXPECT_NE(scene_fingerprint(s), f) << "camera";
    s = base;
    s.materials[0].clearcoat = 0.5f;
    const std::uint64_t coated = scene_fingerprint(s);
    EXPECT_NE(coated, f) << "clear coat";
    s.materials[0].clearcoat_roughness = 0.25f;
    EXPECT_NE(scene_fingerprint(s), coated) << "clear coat roughness";
    s.materials[0].textures[TEXTURE_SLOT_CLEARCOAT_NORMAL].image = 0;
    const std::uint64_t coat_mapped = scene_fingerprint(s);
    EXPECT_NE(coat_mapped, coated) << "clear coat normal texture";
    s.materials[0].clearcoat_normal_scale = 0.5f;
    EXPECT_NE(scene_fingerprint(s), coat_mapped) << "clear coat normal scale";
    s = base;
    s.materials[0].sheen_roughness = 0.5f; // no sheen colour: no sheen, nothing changes
    EXPECT_EQ(scene_fingerprint(s), f) << "roughness of no sheen";
    s.materials[0].sheen_color = glm::vec3(0.0f, 0.5f, 0.0f);
    const std::uint64_t sheen = scene_fingerprint(s);
    EXPECT_NE(sheen, f) << "sheen colour";
    s.materials[0].sheen_roughness = 0.25f;
    const std::uint64_t rougher = scene_fingerprint(s);
    EXPECT_NE(rougher, sheen) << "sheen roughness";
    s.materials[0].textures[TEXTURE_SLOT_SHEEN_ROUGHNESS].image = 0;
    EXPECT_NE(scene_fingerprint(s), rougher) << "sheen roughness texture";
    s = base;
    s.materials[0].anisotropy_rotation = 1.0f; // no strength: isotropic, nothing changes
    EXPECT_EQ(scene_fingerprint(s), f) << "rotation of no anisotropy";
    s.materials[0].anisotropy = 0.5f;
    const std::uint64_t brushed = scene_fingerprint(s);
    EXPECT_NE(brushed, f) << "anisotropy strength";
    s.materials[0].anisotropy_rotation = 1.5f;
    const std::uint64_t turned = scene_fingerprint(s);
    EXPECT_NE(turned, brushed) << "anisotropy rotation";
    s.materials[0].textures[TEXTURE_SLOT_ANISOTROPY].image = 0;
    EXPECT_NE(scene_fingerprint(s), turned) << "anisotropy texture";
    s = base;
    s.materials[0].name = "renamed"; // names do not change a render
    EXPECT_EQ(scene_fingerprint(s), f);
}

// Every field of Scene and of the structs it holds, each changed on its own in a scene
// where every feature is on (so that fields the fingerprint reads only when they matter,
// such as a coat's roughness, count): a field a render reads must change the fingerprint,
// a field no render reads (names, load diagnostics, the files read) must not. Each list
// has one entry per field, checked against the struct's field count at compile time: a
// field added to the struct without an entry here does not compile, and one added here but
// not to scene_fingerprint() fails below.

enum class Read { ByRender, NotByRender };

struct FieldChange {
    const char* field;
    void (*change)(Scene&);
    Read read;
};

// Two materials (the first with every lobe, texture slot and option on), three triangles
// (the third an instanced mesh's), two images (8 and 16 bits), every per-vertex attribute,
// a spot light, an environment image and a thin-lens camera.
Scene scene_with_every_feature()
{
    Scene s;
    SceneTriangle t;
    t.v[0] = {0.0f, 0.0f, 0.0f};
    t.v[1] = {1.0f, 0.0f, 0.0f};
    t.v[2] = {0.0f, 1.0f, 0.0f};
    for (glm::vec3& n : t.n)
        n = {0.0f, 0.0f, 1.0f};
    s.triangles = {t, t, t};
    s.triangles[1].material = 1;
    s.meshes = {SceneMesh{2, 1}};
    s.instances = {SceneInstance{0, glm::dmat4(1.0)}};
    s.instances[0].to_render[3] = glm::dvec4(1.0, 2.0, 3.0, 1.0);
    SceneMaterial m;
    m.name = "everything";
    m.base_color = glm::vec3(0.5f);
    m.alpha = 0.75f;
    m.alpha_mode = AlphaMode::Mask;
    m.metallic = 0.5f;
    m.roughness = 0.5f;
    m.emission = glm::vec3(1.0f);
    m.transmission = 0.5f;
    m.thin_walled = false;
    m.absorption = glm::vec3(0.25f);
    m.clearcoat = 0.5f;
    m.clearcoat_roughness = 0.25f;
    m.clearcoat_normal_scale = 0.5f;
    m.sheen_color = glm::vec3(0.5f);
    m.sheen_roughness = 0.5f;
    m.anisotropy = 0.5f;
    m.anisotropy_rotation = 0.5f;
    for (SceneTexture& texture : m.textures)
        texture.image = 0;
    m.glossiness_texture = true;
    m.glossiness = 0.5f;
    s.materials = {m, SceneMaterial{}};
    SceneImage eight{"eight.png", 2, 2, 8, std::vector<std::uint8_t>(16, 128), {}};
    SceneImage sixteen{"sixteen.png", 2, 2, 16, {}, std::vector<std::uint16_t>(16, 4096)};
    s.images = {eight, sixteen};
    s.texcoords = {std::vector<TriangleUv>(3, TriangleUv{})};
    s.tangents = std::vector<TriangleTangent>(3, TriangleTangent{});
    s.colors = std::vector<TriangleColor>(3, TriangleColor{});
    SceneLight spot;
    spot.type = SceneLight::Type::Spot;
    spot.cos_inner = 0.9;
    spot.cos_outer = 0.8;
    spot.name = "spot";
    s.lights = {spot};
    SceneEnvironment& e = s.environment;
    e.present = true;
    e.path = "sky.hdr";
    e.width = 2;
    e.height = 1;
    e.rgb = {1.0f, 1.0f, 1.0f, 0.5f, 0.5f, 0.5f};
    e.strength = 2.0f;
    s.camera.aperture = 0.1;
    s.camera.focus_distance = 3.0;
    s.camera.from_file = true;
    s.render_origin = glm::dvec3(1.0, 2.0, 3.0);
    s.material_variants = {"red", "blue"};
    s.variant = "red";
    s.input_files = {"scene.gltf"};
    return s;
}

constexpr FieldChange kSceneChanges[] = {
    {"triangles", [](Scene& s) { s.triangles.push_back(s.triangles[0]); }, Read::ByRender},
    {"meshes", [](Scene& s) { s.meshes.push_back(s.meshes[0]); }, Read::ByRender},
    {"instances", [](Scene& s) { s.instances.push_back(s.instances[0]); }, Read::ByRender},
    {"materials", [](Scene& s) { s.materials.push_back(SceneMaterial{}); }, Read::ByRender},
    {"images", [](Scene& s) { s.images.push_back(s.images[0]); }, Read::ByRender},
    {"texcoords", [](Scene& s) { s.texcoords.push_back(s.texcoords[0]); }, Read::ByRender},
    {"tangents", [](Scene& s) { s.tangents[1][2].w = -1.0f; }, Read::ByRender},
    {"colors", [](Scene& s) { s.colors[2][0].x = 0.5f; }, Read::ByRender},
    {"lights", [](Scene& s) { s.lights.push_back(SceneLight{}); }, Read::ByRender},
    {"environment", [](Scene& s) { s.environment = SceneEnvironment{}; }, Read::ByRender},
    {"camera", [](Scene& s) { s.camera = SceneCamera{}; }, Read::ByRender},
    {"dropped_degenerate", [](Scene& s) { s.dropped_degenerate = 3; }, Read::NotByRender},
    {"repaired_normals", [](Scene& s) { s.repaired_normals = 3; }, Read::NotByRender},
    {"render_origin", [](Scene& s) { s.render_origin.z += 1.0; }, Read::ByRender},
    // The chosen variant's materials are in `materials` and the triangles' indices.
    {"material_variants", [](Scene& s) { s.material_variants.push_back("green"); }, Read::NotByRender},
    {"variant", [](Scene& s) { s.variant = "blue"; }, Read::NotByRender},
    {"input_files", [](Scene& s) { s.input_files.push_back("scene.bin"); }, Read::NotByRender},
};
// v and n take three initializers each (brace elision): one entry per vertex.
constexpr FieldChange kTriangleChanges[] = {
    {"v[0]", [](Scene& s) { s.triangles[0].v[0].x = 0.5f; }, Read::ByRender},
    {"v[1]", [](Scene& s) { s.triangles[0].v[1].y = 0.5f; }, Read::ByRender},
    {"v[2]", [](Scene& s) { s.triangles[0].v[2].z = 0.5f; }, Read::ByRender},
    {"n[0]", [](Scene& s) { s.triangles[0].n[0] = glm::vec3(1.0f, 0.0f, 0.0f); }, Read::ByRender},
    {"n[1]", [](Scene& s) { s.triangles[0].n[1] = glm::vec3(1.0f, 0.0f, 0.0f); }, Read::ByRender},
    {"n[2]", [](Scene& s) { s.triangles[0].n[2] = glm::vec3(1.0f, 0.0f, 0.0f); }, Read::ByRender},
    {"material", [](Scene& s) { s.triangles[0].material = 1; }, Read::ByRender},
};
constexpr FieldChange kMeshChanges[] = {
    {"first", [](Scene& s) { s.meshes[0].first = 1; }, Read::ByRender},
    {"count", [](Scene& s) { s.meshes[0].count = 2; }, Read::ByRender},
};
constexpr FieldChange kInstanceChanges[] = {
    {"mesh", [](Scene& s) { s.instances[0].mesh = 1; }, Read::ByRender},
    {"to_render", [](Scene& s) { s.instances[0].to_render[1][1] = 2.0; }, Read::ByRender},
};
constexpr FieldChange kMaterialChanges[] = {
    {"name", [](Scene& s) { s.materials[0].name = "renamed"; }, Read::NotByRender},
    {"base_color", [](Scene& s) { s.materials[0].base_color.y = 0.25f; }, Read::ByRender},
    {"alpha", [](Scene& s) { s.materials[0].alpha = 0.5f; }, Read::ByRender},
    {"alpha_mode", [](Scene& s) { s.materials[0].alpha_mode = AlphaMode::Blend; }, Read::ByRender},
    {"alpha_cutoff", [](Scene& s) { s.materials[0].alpha_cutoff = 0.25f; }, Read::ByRender},
    {"metallic", [](Scene& s) { s.materials[0].metallic = 0.25f; }, Read::ByRender},
    {"roughness", [](Scene& s) { s.materials[0].roughness = 0.25f; }, Read::ByRender},
    {"emission", [](Scene& s) { s.materials[0].emission.z = 2.0f; }, Read::ByRender},
    {"double_sided", [](Scene& s) { s.materials[0].double_sided = true; }, Read::ByRender},
    {"specular", [](Scene& s) { s.materials[0].specular = 0.5f; }, Read::ByRender},
    {"specular_color", [](Scene& s) { s.materials[0].specular_color.x = 0.5f; }, Read::ByRender},
    {"transmission", [](Scene& s) { s.materials[0].transmission = 0.25f; }, Read::ByRender},
    {"ior", [](Scene& s) { s.materials[0].ior = 1.33f; }, Read::ByRender},
    {"thin_walled", [](Scene& s) { s.materials[0].thin_walled = true; }, Read::ByRender},
    {"absorption", [](Scene& s) { s.materials[0].absorption.y = 0.5f; }, Read::ByRender},
    {"clearcoat", [](Scene& s) { s.materials[0].clearcoat = 0.25f; }, Read::ByRender},
    {"clearcoat_roughness", [](Scene& s) { s.materials[0].clearcoat_roughness = 0.5f; }, Read::ByRender},
    {"clearcoat_normal_scale", [](Scene& s) { s.materials[0].clearcoat_normal_scale = 0.25f; }, Read::ByRender},
    {"sheen_color", [](Scene& s) { s.materials[0].sheen_color.x = 0.25f; }, Read::ByRender},
    {"sheen_roughness", [](Scene& s) { s.materials[0].sheen_roughness = 0.25f; }, Read::ByRender},
    {"anisotropy", [](Scene& s) { s.materials[0].anisotropy = 0.25f; }, Read::ByRender},
    {"anisotropy_rotation", [](Scene& s) { s.materials[0].anisotropy_rotation = 0.25f; }, Read::ByRender},
    {"textures", [](Scene& s) { s.materials[0].textures[TEXTURE_SLOT_NORMAL] = SceneTexture{}; }, Read::ByRender},
    {"normal_scale", [](Scene& s) { s.materials[0].normal_scale = 0.5f; }, Read::ByRender},
    {"glossiness_texture", [](Scene& s) { s.materials[0].glossiness_texture = false; }, Read::ByRender},
    {"glossiness", [](Scene& s) { s.materials[0].glossiness = 0.25f; }, Read::ByRender},
    {"unlit", [](Scene& s) { s.materials[0].unlit = true; }, Read::ByRender},
};
constexpr FieldChange kTextureChanges[] = {
    {"image", [](Scene& s) { s.materials[0].textures[TEXTURE_SLOT_BASE_COLOR].image = 1; }, Read::ByRender},
    {"texcoord", [](Scene& s) { s.materials[0].textures[TEXTURE_SLOT_BASE_COLOR].texcoord = 1; }, Read::ByRender},
    {"wrap_s", [](Scene& s) { s.materials[0].textures[TEXTURE_SLOT_BASE_COLOR].wrap_s = TextureWrap::ClampToEdge; },
     Read::ByRender},
    {"wrap_t", [](Scene& s) { s.materials[0].textures[TEXTURE_SLOT_BASE_COLOR].wrap_t = TextureWrap::MirroredRepeat; },
     Read::ByRender},
    {"nearest", [](Scene& s) { s.materials[0].textures[TEXTURE_SLOT_BASE_COLOR].nearest = true; }, Read::ByRender},
    {"transform_u", [](Scene& s) { s.materials[0].textures[TEXTURE_SLOT_BASE_COLOR].transform_u.z = 0.5f; },
     Read::ByRender},
    {"transform_v", [](Scene& s) { s.materials[0].textures[TEXTURE_SLOT_BASE_COLOR].transform_v.x = 0.5f; },
     Read::ByRender},
};
constexpr FieldChange kImageChanges[] = {
    {"name", [](Scene& s) { s.images[0].name = "renamed.png"; }, Read::NotByRender},
    {"width", [](Scene& s) { s.images[0].width = 4; }, Read::ByRender},
    {"height", [](Scene& s) { s.images[0].height = 1; }, Read::ByRender},
    {"bits", [](Scene& s) { s.images[0].bits = 16; }, Read::ByRender},
    {"rgba8", [](Scene& s) { s.images[0].rgba8[5] = 7; }, Read::ByRender},
    {"rgba16", [](Scene& s) { s.images[1].rgba16[5] = 7; }, Read::ByRender},
};
constexpr FieldChange kLightChanges[] = {
    {"type", [](Scene& s) { s.lights[0].type = SceneLight::Type::Point; }, Read::ByRender},
    {"position", [](Scene& s) { s.lights[0].position.x = 1.0; }, Read::ByRender},
    {"direction", [](Scene& s) { s.lights[0].direction = glm::dvec3(0.0, -1.0, 0.0); }, Read::ByRender},
    {"right", [](Scene& s) { s.lights[0].right = glm::dvec3(0.0, 0.0, 1.0); }, Read::ByRender},
    {"intensity", [](Scene& s) { s.lights[0].intensity.y = 2.0f; }, Read::ByRender},
    {"cos_inner", [](Scene& s) { s.lights[0].cos_inner = 0.95; }, Read::ByRender},
    {"cos_outer", [](Scene& s) { s.lights[0].cos_outer = 0.7; }, Read::ByRender},
    {"tan_half_h", [](Scene& s) { s.lights[0].tan_half_h = 0.5; }, Read::ByRender},
    {"tan_half_v", [](Scene& s) { s.lights[0].tan_half_v = 0.5; }, Read::ByRender},
    {"radius", [](Scene& s) { s.lights[0].radius = 0.1; }, Read::ByRender},
    {"name", [](Scene& s) { s.lights[0].name = "renamed"; }, Read::NotByRender},
};
constexpr FieldChange kEnvironmentChanges[] = {
    {"present", [](Scene& s) { s.environment.present = false; }, Read::ByRender},
    // The texels read from it are in rgb.
    {"path", [](Scene& s) { s.environment.path = "renamed.hdr"; }, Read::NotByRender},
    {"width", [](Scene& s) { s.environment.width = 1; }, Read::ByRender},
    {"height", [](Scene& s) { s.environment.height = 2; }, Read::ByRender},
    {"rgb", [](Scene& s) { s.environment.rgb[4] = 0.25f; }, Read::ByRender},
    {"constant", [](Scene& s) { s.environment.constant.x = 1.0f; }, Read::ByRender},
    {"strength", [](Scene& s) { s.environment.strength = 3.0f; }, Read::ByRender},
    {"rotation_degrees", [](Scene& s) { s.environment.rotation_degrees = 90.0; }, Read::ByRender},
};
constexpr FieldChange kCameraChanges[] = {
    {"position", [](Scene& s) { s.camera.position.y = 1.0; }, Read::ByRender},
    {"forward", [](Scene& s) { s.camera.forward = glm::dvec3(1.0, 0.0, 0.0); }, Read::ByRender},
    {"up", [](Scene& s) { s.camera.up = glm::dvec3(0.0, 0.0, 1.0); }, Read::ByRender},
    {"right", [](Scene& s) { s.camera.right = glm::dvec3(0.0, 1.0, 0.0); }, Read::ByRender},
    {"yfov", [](Scene& s) { s.camera.yfov = 0.5; }, Read::ByRender},
    {"orthographic", [](Scene& s) { s.camera.orthographic = true; }, Read::ByRender},
    {"ymag", [](Scene& s) { s.camera.ymag = 2.0; }, Read::ByRender},
    {"aperture", [](Scene& s) { s.camera.aperture = 0.2; }, Read::ByRender},
    {"focus_distance", [](Scene& s) { s.camera.focus_distance = 4.0; }, Read::ByRender},
    // Whether the file named the camera (pathcl info says so): the view is in the fields above.
    {"from_file", [](Scene& s) { s.camera.from_file = false; }, Read::NotByRender},
};

template <class Struct, std::size_t N>
constexpr bool lists_every_field(const FieldChange (&)[N])
{
    return N == test::initializer_count<Struct>();
}
static_assert(lists_every_field<Scene>(kSceneChanges), "a Scene field is missing from kSceneChanges");
static_assert(lists_every_field<SceneTriangle>(kTriangleChanges), "a SceneTriangle field is missing from its list");
static_assert(lists_every_field<SceneMesh>(kMeshChanges), "a SceneMesh field is missing from kMeshChanges");
static_assert(lists_every_field<SceneInstance>(kInstanceChanges), "a SceneInstance field is missing from its list");
static_assert(lists_every_field<SceneMaterial>(kMaterialChanges), "a SceneMaterial field is missing from its list");
static_assert(lists_every_field<SceneTexture>(kTextureChanges), "a SceneTexture field is missing from its list");
static_assert(lists_every_field<SceneImage>(kImageChanges), "a SceneImage field is missing from kImageChanges");
static_assert(lists_every_field<SceneLight>(kLightChanges), "a SceneLight field is missing from kLightChanges");
static_assert(lists_every_field<SceneEnvironment>(kEnvironmentChanges),
              "a SceneEnvironment field is missing from its list");
static_assert(lists_every_field<SceneCamera>(kCameraChanges), "a SceneCamera field is missing from kCameraChanges");

void expect_each_change_read_as_listed(const char* type, std::span<const FieldChange> changes)
{
    const Scene base = scene_with_every_feature();
    const std::uint64_t f = scene_fingerprint(base);
    for (const FieldChange& c : changes) {
        Scene s = base;
        c.change(s);
        if (c.read == Read::ByRender)
            EXPECT_NE(scene_fingerprint(s), f) << type << "::" << c.field << " is not part of the fingerprint";
        else
            EXPECT_EQ(scene_fingerprint(s), f) << type << "::" << c.field << " changes no render, but the fingerprint";
    }
}

TEST(SceneFingerprint, EveryFieldThatARenderReadsIsPartOfIt)
{
    expect_each_change_read_as_listed("Scene", kSceneChanges);
    expect_each_change_read_as_listed("SceneTriangle", kTriangleChanges);
    expect_each_change_read_as_listed("SceneMesh", kMeshChanges);
    expect_each_change_read_as_listed("SceneInstance", kInstanceChanges);
    expect_each_change_read_as_listed("SceneMaterial", kMaterialChanges);
    expect_each_change_read_as_listed("SceneTexture", kTextureChanges);
    expect_each_change_read_as_listed("SceneImage", kImageChanges);
    expect_each_change_read_as_listed("SceneLight", kLightChanges);
    expect_each_change_read_as_listed("SceneEnvironment", kEnvironmentChanges);
    expect_each_change_read_as_listed("SceneCamera", kCameraChanges);
}

} // namespace
} // namespace pathcl::test_scene_fingerprint
