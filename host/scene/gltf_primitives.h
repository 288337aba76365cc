// glTF mesh primitives to PendingGeometry: triangles (strips and fans converted) in
// double-precision world space with their shading normals and the attributes the
// materials need: the TEXCOORD_n sets their textures read, tangents for normal maps
// (TANGENT, else computed) and COLOR_0.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/gltf_morph_targets.h"
#include "scene/pending_geometry.h"
#include "scene/scene.h"

namespace tinygltf {
struct Mesh;
class Model;
struct Primitive;
} // namespace tinygltf

namespace pathcl {

class AccessorReader;

// The texture coordinate set a material's tangents follow: its normal texture's, else its
// clear coat's normal texture's, else its anisotropy texture's (one tangent frame per
// triangle serves them all); TEXCOORD_0 for an anisotropic material without these (its
// direction is relative to the tangent); -1 when it needs no tangents.
int tangent_texcoord(const SceneMaterial& material);

// Decides which attributes the pending triangles carry: each TEXCOORD_n set that a
// texture of `materials` reads, and tangents when one of them needs them (a normal
// texture or anisotropy).
// Called once, with all of the file's materials, before the first primitive.
void plan_attributes(const std::vector<SceneMaterial>& materials, PendingGeometry& geometry);

class PrimitiveImporter {
public:
    // Appends triangles to `geometry`, and the glTF default material to `materials` when
    // a primitive without a material first needs it. `source` names the file in errors.
    PrimitiveImporter(const tinygltf::Model& model, const std::string& source, std::vector<SceneMaterial>& materials,
                      PendingGeometry& geometry);

    // The triangles of `prim` on a node with world transform `world`; `what` names the
    // primitive in errors ("node 2 'floor' mesh 0 primitive 1"). Points and lines are
    // skipped and counted. `morph_weights`: the node's weights, else the mesh's (morph
    // targets are applied at them).
    void import_primitive(const tinygltf::Primitive& prim, const glm::dmat4& world, const std::string& what,
                          const std::vector<double>& morph_weights = {});

    // Whether a primitive of `mesh` takes an emissive material in the chosen variant;
    // `what` names the mesh in the error for a bad variant mapping.
    bool mesh_emits(const tinygltf::Mesh& mesh, const std::string& what) const;

    std::size_t skipped_points_lines() const { return skipped_points_lines_; }
    // Whether the file uses KHR_mesh_quantization (integer positions, normals, ...).
    bool quantized() const { return quantized_; }
    // Triangle-list primitives whose index (or vertex) count is not a multiple of 3.
    std::size_t incomplete_triangle_lists() const { return incomplete_triangle_lists_; }
    // Morph targets of attributes other than POSITION, NORMAL and TANGENT, not applied.
    std::size_t ignored_morph_attributes() const { return ignored_morph_attributes_; }
    // Anisotropic primitives with neither TANGENT nor the texture coordinates to compute
    // tangents from: their anisotropy direction is some direction in the surface.
    std::size_t arbitrary_tangents() const { return arbitrary_tangents_; }

    // Primitives take their material in KHR_materials_variants variant `variant` (-1: the
    // default) of the file's `count`.
    void choose_variant(int variant, std::size_t count)
    {
        variant_ = variant;
        variant_count_ = count;
    }

private:
    struct VertexAttributes;

    int material_for(int gltf_material);
    // Vertex i's object-space position and normal, morphed.
    glm::dvec3 object_position(const AccessorReader& pos, std::size_t i) const;
    glm::dvec3 object_normal(const AccessorReader& nr, std::size_t i) const;
    std::vector<std::uint32_t> triangle_indices(const tinygltf::Primitive& prim, std::size_t vertex_count,
                                                const std::string& what);
    VertexAttributes read_vertex_attributes(const tinygltf::Primitive& prim, int material, const AccessorReader& pos,
                                            const std::vector<std::uint32_t>& tris, const std::string& what);
    std::vector<glm::dvec4> object_tangents(const tinygltf::Primitive& prim, int texcoord, const AccessorReader& pos,
                                            const std::vector<std::uint32_t>& tris, const std::string& what);

    const tinygltf::Model& model_;
    std::string source_;
    std::vector<SceneMaterial>& materials_;
    PendingGeometry& geometry_;
    // KHR_mesh_quantization is used: positions, normals, tangents and texture coordinates
    // may be integers (texture coordinates unnormalized too).
    bool quantized_ = false;
    int default_material_ = -1;
    int variant_ = -1;
    std::size_t variant_count_ = 0;
    std::size_t skipped_points_lines_ = 0;
    std::size_t incomplete_triangle_lists_ = 0;
    std::size_t ignored_morph_attributes_ = 0;
    std::size_t arbitrary_tangents_ = 0;
    MorphDeltas morph_; // the primitive being imported's
};

} // namespace pathcl
