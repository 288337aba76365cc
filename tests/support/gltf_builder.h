// Builds tinygltf models in memory, so tests can make exactly the geometry they need
// (hierarchies, instancing, index types, strips, broken data) without files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace pathcl::test {

// Accessor component types, for add_indices and add_accessor.
inline constexpr int kU8 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
inline constexpr int kU16 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
inline constexpr int kU32 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

class GltfBuilder {
public:
    GltfBuilder();

    // Appends raw bytes as a new buffer view; returns the view index.
    int add_view(const void* data, std::size_t bytes);
    int add_accessor(int view, int component_type, int type, std::size_t count);

    int add_positions(const std::vector<glm::vec3>& p);
    int add_normals(const std::vector<glm::vec3>& n);
    // component_type: TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE/SHORT/INT
    int add_indices(const std::vector<std::uint32_t>& idx, int component_type);

    // The material an add_*material call returned, to edit further.
    tinygltf::Material& material(int index) { return model.materials[static_cast<std::size_t>(index)]; }
    // An exactly Lambertian material (metallic 0, KHR_materials_specular specularFactor 0).
    int add_material(const glm::vec3& base_color, const glm::vec3& emission = glm::vec3(0.0f),
                     bool double_sided = false, double emissive_strength = 1.0);
    // A glTF metallic-roughness material; transmission > 0 adds KHR_materials_transmission
    // and _ior, thickness > 0 makes it a solid (KHR_materials_volume).
    struct Pbr {
        glm::vec3 base_color{1.0f};
        double metallic = 0.0, roughness = 0.0;
        double transmission = 0.0, ior = 1.5, thickness = 0.0;
        double specular = 1.0;
        bool double_sided = false;
    };
    int add_pbr_material(const Pbr& pbr);
    // A mesh with one primitive. indices < 0: non-indexed. normals < 0: none.
    int add_mesh(int positions, int indices, int material, int mode = 4, int normals = -1);
    // A node; returns its index. Root nodes must also be passed to add_root.
    int add_node(int mesh, const std::vector<double>& matrix = {}, const std::vector<double>& translation = {},
                 const std::vector<double>& rotation = {}, const std::vector<double>& scale = {});
    int add_perspective_camera(double yfov);
    // A KHR_lights_punctual light ("point", "spot", "directional"); returns its index.
    int add_light(const std::string& type, const glm::vec3& color, double intensity, double inner_cone = 0.0,
                  double outer_cone = 0.7853981634, const tinygltf::Value& extras = {});
    // A root node carrying light `light` (or camera `camera`) with a TRS transform.
    int add_light_node(int light, const std::vector<double>& translation, const std::vector<double>& rotation = {});
    int add_camera_node(int camera, const std::vector<double>& translation, const std::vector<double>& rotation = {});
    void add_root(int node);

    // A UV sphere (stacks x slices) of the given radius; normals point inward when
    // `inward` (the front face then faces the centre). smooth_normals: a NORMAL
    // attribute with the sphere's own (radial) normals, for smooth shading.
    int add_sphere_mesh(double radius, int stacks, int slices, int material, bool inward, bool smooth_normals = false);
    // A quad mesh: the triangles (0, 1, 2) and (0, 2, 3) of its four corners (give them
    // counter-clockwise seen from the front).
    int add_quad_mesh(const std::vector<glm::vec3>& corners, int material);
    // A closed box mesh (12 triangles, counter-clockwise seen from outside) with the given
    // half extents, centred at the origin.
    int add_box_mesh(glm::vec3 half, int material);

    // Textures. Images are stored as PNG bytes in a bufferView (as in a .glb), encoded by
    // OpenImageIO with alpha kept unassociated.
    int add_png_image(int width, int height, const std::vector<std::uint8_t>& rgba8);
    int add_png_image16(int width, int height, const std::vector<std::uint16_t>& rgba16);
    // Raw (encoded) image bytes in a bufferView.
    int add_image_bytes(const std::vector<unsigned char>& bytes, const std::string& mime_type);
    // A sampler (-1: leave the glTF default); returns its index.
    int add_sampler(int mag_filter, int wrap_s = 10497, int wrap_t = 10497);
    int add_texture(int image, int sampler = -1);
    // Float VEC2 texture coordinates, VEC4 tangents, VEC3 float colours: accessor indices.
    int add_texcoords(const std::vector<glm::vec2>& uv);
    int add_tangents(const std::vector<glm::vec4>& t);
    // Sets attribute `name` of primitive 0 of `mesh`.
    void set_attribute(int mesh, const std::string& name, int accessor);

    tinygltf::Model model;
};

// JSON values for the extension objects tinygltf leaves untyped: an array of numbers, and
// a textureInfo {"index": index, "texCoord": texcoord}.
tinygltf::Value json_numbers(const std::vector<double>& values);
tinygltf::Value texture_info(int index, int texcoord = 0);
// Gives material `m` KHR_materials_clearcoat with these factors.
void set_clearcoat(tinygltf::Material& m, double factor, double roughness);
// Gives material `m` KHR_materials_sheen with these factors.
void set_sheen(tinygltf::Material& m, const std::vector<double>& color, double roughness);
// KHR_materials_anisotropy with these strength and rotation (radians).
void set_anisotropy(tinygltf::Material& m, double strength, double rotation = 0.0);

} // namespace pathcl::test
