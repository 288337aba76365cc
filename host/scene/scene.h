// The flat scene every later stage works on: triangles, materials and one camera,
// independent of glTF and of the device layout. Positions are in render space: world
// space translated by -render_origin (the camera position, else the centre of the
// geometry), so float precision is spent where the camera looks, not on the distance
// from the world origin.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "texture/texture_slots.h"

namespace pathcl {

// A decoded image: RGBA, row-major from the top row, 8 or 16 bits per channel (grey and
// RGB images expanded: grey to RGB, missing alpha to opaque). Values are the file's,
// still sRGB-encoded where the image holds colour; which slot reads it decides.
struct SceneImage {
    std::string name; // for messages: the glTF image's name or uri
    std::uint32_t width = 0, height = 0;
    int bits = 8;                      // 8 or 16
    std::vector<std::uint8_t> rgba8;   // bits 8: width * height * 4 values
    std::vector<std::uint16_t> rgba16; // bits 16: width * height * 4 values
};

enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// One texture slot of a material: which image, which TEXCOORD_n set, the sampler, and
// the KHR_texture_transform. (u', v') = (dot(transform_u, (u, v, 1)), dot(transform_v, (u, v, 1))).
struct SceneTexture {
    int image = -1;   // index into Scene::images; -1: the slot has no texture
    int texcoord = 0; // TEXCOORD_n set (KHR_texture_transform's texCoord already applied)
    TextureWrap wrap_s = TextureWrap::Repeat, wrap_t = TextureWrap::Repeat;
    bool nearest = false; // sampler magFilter NEAREST; otherwise bilinear
    glm::vec3 transform_u{1.0f, 0.0f, 0.0f};
    glm::vec3 transform_v{0.0f, 1.0f, 0.0f};

    bool present() const { return image >= 0; }
    bool operator==(const SceneTexture&) const = default;
};

// glTF alphaMode: OPAQUE ignores alpha; MASK cuts where alpha < alpha_cutoff; BLEND
// makes alpha the surface's coverage (kernels/texture/alpha.cl).
enum class AlphaMode { Opaque, Mask, Blend };

struct SceneMaterial {
    std::string name;
    glm::vec3 base_color{1.0f};
    float alpha = 1.0f; // baseColorFactor's alpha
    AlphaMode alpha_mode = AlphaMode::Opaque;
    float alpha_cutoff = 0.5f;
    float metallic = 1.0f; // glTF defaults
    float roughness = 1.0f;
    glm::vec3 emission{0.0f}; // radiance, W m^-2 sr^-1
    bool double_sided = false;
    float specular = 1.0f;          // KHR_materials_specular specularFactor
    glm::vec3 specular_color{1.0f}; // KHR_materials_specular specularColorFactor
    float transmission = 0.0f;      // KHR_materials_transmission transmissionFactor
    float ior = 1.5f;               // KHR_materials_ior; 0: specular-glossiness mode (Schlick's curve)
    bool thin_walled = true;        // no KHR_materials_volume with thicknessFactor > 0
    // Inside a solid (not thin-walled): Beer-Lambert absorption per unit length,
    // -ln(attenuationColor) / attenuationDistance (0: clear; at most FLT_MAX).
    glm::vec3 absorption{0.0f};
    float clearcoat = 0.0f;              // KHR_materials_clearcoat clearcoatFactor (0: no coat)
    float clearcoat_roughness = 0.0f;    // clearcoatRoughnessFactor
    float clearcoat_normal_scale = 1.0f; // clearcoatNormalTexture.scale
    glm::vec3 sheen_color{0.0f};         // KHR_materials_sheen sheenColorFactor (0: no sheen)
    float sheen_roughness = 0.0f;        // sheenRoughnessFactor
    float anisotropy = 0.0f;             // KHR_materials_anisotropy anisotropyStrength (0: isotropic)
    float anisotropy_rotation = 0.0f;    // anisotropyRotation, radians from the tangent towards the bitangent

    // Textures, one per slot (TEXTURE_SLOT_*, the table in scene/texture_slots.h); each
    // value multiplies its factor.
    std::array<SceneTexture, TEXTURE_SLOT_COUNT> textures;
    float normal_scale = 1.0f;
    // KHR_materials_pbrSpecularGlossiness with a specularGlossinessTexture: the
    // metallic-roughness slot holds it, and roughness = 1 - glossiness x its alpha
    // (roughness above is 1 - glossiness, its value where the alpha is 1).
    bool glossiness_texture = false;
    float glossiness = 1.0f;
    // KHR_materials_unlit: the base colour is seen as radiance (directly and through delta
    // bounces); the material lights and scatters nothing (kernels/integrator/shade_surface.cl).
    bool unlit = false;

    bool emits() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
    bool has_sheen() const { return sheen_color.x > 0.0f || sheen_color.y > 0.0f || sheen_color.z > 0.0f; }
    bool has_anisotropy() const { return anisotropy > 0.0f; }
    // Whether light can travel inside it (a solid that transmits) and be absorbed there.
    bool absorbs() const
    {
        return transmission > 0.0f && !thin_walled &&
               (absorption.x > 0.0f || absorption.y > 0.0f || absorption.z > 0.0f);
    }
    bool has_textures() const
    {
        for (const SceneTexture& t : textures)
            if (t.present())
                return true;
        return false;
    }
};

struct SceneTriangle {
    glm::vec3 v[3]; // render-space positions; counter-clockwise = front
    glm::vec3 n[3]; // shading normals (the geometric normal when the file has none)
    std::int32_t material = 0;
};

// A KHR_lights_punctual light (see docs/gltf.md for units).
struct SceneLight {
    enum class Type { Point, Spot, RectSpot, Directional, Sphere };
    Type type = Type::Point;
    glm::dvec3 position{0.0};                  // render space (not used by Directional)
    glm::dvec3 direction{0.0, 0.0, -1.0};      // unit, the way light travels (node -Z)
    glm::dvec3 right{1.0, 0.0, 0.0};           // unit, node +X, orthogonal to direction
    glm::vec3 intensity{1.0f};                 // color x intensity: W/sr, or W/m^2 (Directional)
    double cos_inner = 1.0, cos_outer = 0.0;   // Spot
    double tan_half_h = 1.0, tan_half_v = 1.0; // RectSpot
    double radius = 0.0;                       // Sphere
    std::string name;
};

// The environment seen by escaping rays: an equirectangular image or a constant colour;
// radiance = texel x strength; rotated about +Y by rotation_degrees. The image is read
// when the scene is loaded (scene/environment_image.h), so a Scene is complete.
struct SceneEnvironment {
    bool present = false;
    std::string path; // the image file; empty: constant
    std::uint32_t width = 0, height = 0;
    std::vector<float> rgb; // the image's texels as read, rows from the top
    glm::vec3 constant{0.0f};
    float strength = 1.0f;
    double rotation_degrees = 0.0;
};

struct SceneCamera {
    // Render-space position and world-space frame (unit vectors): looks along forward.
    glm::dvec3 position{0.0};
    glm::dvec3 forward{0.0, 0.0, -1.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    glm::dvec3 right{1.0, 0.0, 0.0};
    double yfov = 0.8; // perspective: full vertical field of view, radians
    bool orthographic = false;
    double ymag = 1.0; // orthographic: half the view's height (glTF ymag), world units
    // Thin lens: radius of the lens disk (0: pinhole) and distance of the plane of focus
    // along forward, world units (docs/gltf.md; node extras aperture, focusDistance).
    double aperture = 0.0;
    double focus_distance = 0.0;
    bool from_file = false;
};

// Per-vertex attributes of one triangle (vertex k as in SceneTriangle::v[k]).
using TriangleUv = std::array<glm::vec2, 3>;
using TriangleTangent = std::array<glm::vec4, 3>; // xyz unit world tangent, w handedness (+-1)
using TriangleColor = std::array<glm::vec4, 3>;   // COLOR_0 rgba (alpha 1 for VEC3)

// A mesh drawn more than once, stored once (a two-level BVH): triangles [first, first +
// count) of Scene::triangles, in the mesh's own space.
struct SceneMesh {
    std::size_t first = 0, count = 0;
};

// One drawing of a SceneMesh: x_render = to_render * x_mesh.
struct SceneInstance {
    std::uint32_t mesh = 0;
    glm::dmat4 to_render{1.0};
};

struct Scene {
    // First the triangles drawn once, in render space (render_space_triangles() of them),
    // then those of each instanced mesh, in its own space.
    std::vector<SceneTriangle> triangles;
    std::vector<SceneMesh> meshes;
    std::vector<SceneInstance> instances;
    std::vector<SceneMaterial> materials; // never empty: index 0 may be the default
    std::vector<SceneImage> images;       // those some material's texture reads
    // Optional per-vertex attributes, parallel to `triangles`; each empty unless used:
    // texcoords[n] holds TEXCOORD_n when some texture reads set n (zero for triangles whose
    // primitive lacks it); tangents when some material has a normal texture (zero for the
    // other triangles); colors when some primitive has COLOR_0 (white for the others).
    std::vector<std::vector<TriangleUv>> texcoords;
    std::vector<TriangleTangent> tangents;
    std::vector<TriangleColor> colors;
    std::vector<SceneLight> lights; // punctual lights; emissive triangles are area lights
    SceneEnvironment environment;
    SceneCamera camera;
    std::size_t dropped_degenerate = 0; // zero-area triangles dropped at load
    std::size_t repaired_normals = 0;   // zero-length or NaN vertex normals replaced by the geometric one
    glm::dvec3 render_origin{0.0};      // world position of the render-space origin
    // KHR_materials_variants: the file's variant names, and the one its triangles took
    // their materials from ("" the default).
    std::vector<std::string> material_variants;
    std::string variant;
    // The files it was read from (the glTF file, its buffers and images; the environment
    // map is environment.path): no output may replace one of them.
    std::vector<std::string> input_files;

    std::size_t render_space_triangles() const { return meshes.empty() ? triangles.size() : meshes.front().first; }
    // Triangles drawn: those in render space and each instance's mesh.
    std::size_t drawn_triangles() const;
};

// Axis-aligned bounds of all triangles drawn, instances included (min > max when the
// scene is empty).
void scene_bounds(const Scene& scene, glm::vec3& lo, glm::vec3& hi);

// Widens [lo, hi] by the box [box_lo, box_hi] mapped by m: the box of its eight mapped
// corners (a little larger than the mapped contents' under a rotation). An empty box
// (box_lo.x > box_hi.x) adds nothing.
void add_mapped_box(const glm::dmat4& m, const glm::dvec3& box_lo, const glm::dvec3& box_hi, glm::dvec3& lo,
                    glm::dvec3& hi);

// Every triangle drawn, in render space: those drawn once, then each instance's mesh
// mapped by it (normals through the inverse transpose, re-wound where the map mirrors so
// that counter-clockwise stays the front): the copies --copy-instances would make.
std::vector<SceneTriangle> drawn_triangle_list(const Scene& scene);

// A camera that sees the whole scene: looking along -Z at the bounds' centre, far enough
// back that the bounding sphere fits the vertical field of view.
SceneCamera framing_camera(const Scene& scene, double yfov);

} // namespace pathcl
