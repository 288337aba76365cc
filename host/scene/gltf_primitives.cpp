// PrimitiveImporter: positions and normals to world space (a mirroring transform flips
// the winding and the tangents' handedness back), then each attribute checked per vertex
// and gathered per triangle corner.
#include "scene/gltf_primitives.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <tiny_gltf.h>

#include "common/error.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_variants.h"
#include "scene/tangents.h"
#include "scene/texture_slots.h"

namespace pathcl {
namespace {

// glTF primitive modes; the lower ones (points and lines) are skipped.
constexpr int kModeTriangles = 4, kModeStrip = 5, kModeFan = 6;

} // namespace

int tangent_texcoord(const SceneMaterial& material)
{
    for (int slot : {TEXTURE_SLOT_NORMAL, TEXTURE_SLOT_CLEARCOAT_NORMAL, TEXTURE_SLOT_ANISOTROPY})
        if (material.textures[static_cast<std::size_t>(slot)].present())
            return material.textures[static_cast<std::size_t>(slot)].texcoord;
    return material.has_anisotropy() ? 0 : -1;
}

void plan_attributes(const std::vector<SceneMaterial>& materials, PendingGeometry& geometry)
{
    for (const SceneMaterial& material : materials) {
        for (const SceneTexture& texture : material.textures) {
            if (!texture.present())
                continue;
            std::size_t set = static_cast<std::size_t>(texture.texcoord);
            if (set >= geometry.texcoord_used.size())
                geometry.texcoord_used.resize(set + 1, false);
            geometry.texcoord_used[set] = true;
        }
        geometry.tangents_used = geometry.tangents_used || tangent_texcoord(material) >= 0;
    }
    geometry.texcoords.resize(geometry.texcoord_used.size());
}

PrimitiveImporter::PrimitiveImporter(const tinygltf::Model& model, const std::string& source,
                                     std::vector<SceneMaterial>& materials, PendingGeometry& geometry)
    : model_(model), source_(source), materials_(materials), geometry_(geometry),
      quantized_(std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_mesh_quantization") !=
                 model.extensionsUsed.end())
{}

// A primitive's optional vertex attributes, for the vertices of `tris`.
struct PrimitiveImporter::VertexAttributes {
    std::vector<std::vector<glm::vec2>> texcoords; // [set][vertex], for the used sets it has
    std::vector<glm::dvec4> tangents;              // object space, per corner of `tris`
    std::vector<glm::vec4> colors;                 // per vertex, rgba
};

void PrimitiveImporter::import_primitive(const tinygltf::Primitive& prim_in, const glm::dmat4& world,
                                         const std::string& what, const std::vector<double>& morph_weights)
{
    tinygltf::Primitive prim = prim_in;
    if (prim.mode < 0) // unset (tinygltf's -1): glTF's default is triangles
        prim.mode = kModeTriangles;
    if (prim.mode < kModeTriangles) {
        ++skipped_points_lines_;
        return;
    }
    if (prim.mode > kModeFan)
        throw Error(source_ + ": " + what + ": invalid primitive mode " + std::to_string(prim.mode));
    auto pos_it = prim.attributes.find("POSITION");
    if (pos_it == prim.attributes.end())
        throw Error(source_ + ": " + what + ": has no POSITION attribute");
    AccessorReader pos(model_, pos_it->second, what + " POSITION", source_);
    if (pos.components() != 3)
        pos.fail("POSITION must be VEC3");
    if (!pos.is_float() && !quantized_)
        pos.fail("POSITION must be FLOAT (integer positions need KHR_mesh_quantization)");
    morph_ = morph_deltas(model_, prim, morph_weights, pos.count(), quantized_, source_, what);
    ignored_morph_attributes_ += morph_.ignored_attributes;
    std::vector<glm::dvec3> p(pos.count());
    for (std::size_t i = 0; i < pos.count(); ++i) {
        glm::dvec3 o = object_position(pos, i);
        glm::dvec4 w = world * glm::dvec4(o, 1.0);
        p[i] = glm::dvec3(w);
        if (!std::isfinite(p[i].x) || !std::isfinite(p[i].y) || !std::isfinite(p[i].z))
            pos.fail("vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
    }
    glm::dmat3 m3(world);
    glm::dmat3 normal_matrix = glm::transpose(glm::inverse(m3));
    bool mirrored = glm::determinant(m3) < 0.0; // a mirror flips counter-clockwise
    std::vector<glm::dvec3> n;
    auto nrm_it = prim.attributes.find("NORMAL");
    if (nrm_it != prim.attributes.end()) {
        AccessorReader nr(model_, nrm_it->second, what + " NORMAL", source_);
        if (nr.components() != 3 || nr.count() != pos.count())
            nr.fail("NORMAL must be VEC3 with one normal per vertex");
        if (!nr.is_float() && !quantized_)
            nr.fail("NORMAL must be FLOAT (integer normals need KHR_mesh_quantization)");
        n.resize(nr.count());
        for (std::size_t i = 0; i < nr.count(); ++i)
            n[i] = normal_matrix * object_normal(nr, i);
    }
    int material =
        material_for(variant_material(prim, variant_, variant_count_, model_.materials.size(), source_ + ": " + what));
    std::vector<std::uint32_t> tris = triangle_indices(prim, p.size(), what);
    tris.resize(tris.size() / 3 * 3);
    VertexAttributes attr = read_vertex_attributes(prim, material, pos, tris, what);
    const double handedness = mirrored ? -1.0 : 1.0; // a mirror flips the bitangent
    for (std::size_t t = 0; t < tris.size(); t += 3) {
        std::uint32_t ids[3] = {tris[t], tris[t + 1], tris[t + 2]};
        int corner[3] = {0, 1, 2};
        if (mirrored) {
            std::swap(ids[1], ids[2]);
            std::swap(corner[1], corner[2]);
        }
        PendingTriangle tri;
        tri.material = material;
        tri.has_normals = !n.empty();
        for (int k = 0; k < 3; ++k) {
            tri.v[k] = p[ids[k]];
            tri.n[k] = n.empty() ? glm::dvec3(0.0) : n[ids[k]];
        }
        geometry_.triangles.push_back(tri);
        for (std::size_t set = 0; set < geometry_.texcoord_used.size(); ++set) {
            if (!geometry_.texcoord_used[set])
                continue;
            TriangleUv uv{};
            if (!attr.texcoords[set].empty())
                for (int k = 0; k < 3; ++k)
                    uv[static_cast<std::size_t>(k)] = attr.texcoords[set][ids[k]];
            geometry_.texcoords[set].push_back(uv);
        }
        if (geometry_.tangents_used) {
            std::array<glm::dvec4, 3> tangent{};
            if (!attr.tangents.empty())
                for (int k = 0; k < 3; ++k) {
                    glm::dvec4 ot = attr.tangents[t + static_cast<std::size_t>(corner[k])];
                    tangent[static_cast<std::size_t>(k)] = glm::dvec4(m3 * glm::dvec3(ot), ot.w * handedness);
                }
            geometry_.tangents.push_back(tangent);
        }
        if (!attr.colors.empty() || !geometry_.colors.empty()) {
            geometry_.colors.resize(geometry_.triangles.size() - 1, kWhiteTriangleColor);
            TriangleColor c = kWhiteTriangleColor;
            if (!attr.colors.empty())
                for (int k = 0; k < 3; ++k)
                    c[static_cast<std::size_t>(k)] = attr.colors[ids[k]];
            geometry_.colors.push_back(c);
        }
    }
}

glm::dvec3 PrimitiveImporter::object_position(const AccessorReader& pos, std::size_t i) const
{
    glm::dvec3 v(pos.get(i, 0), pos.get(i, 1), pos.get(i, 2));
    return morph_.position.empty() ? v : v + morph_.position[i];
}

glm::dvec3 PrimitiveImporter::object_normal(const AccessorReader& nr, std::size_t i) const
{
    glm::dvec3 v(nr.get(i, 0), nr.get(i, 1), nr.get(i, 2));
    return morph_.normal.empty() ? v : v + morph_.normal[i];
}

bool PrimitiveImporter::mesh_emits(const tinygltf::Mesh& mesh, const std::string& what) const
{
    for (std::size_t i = 0; i < mesh.primitives.size(); ++i) {
        int m = variant_material(mesh.primitives[i], variant_, variant_count_, model_.materials.size(),
                                 source_ + ": " + what + " primitive " + std::to_string(i));
        if (m >= 0 && static_cast<std::size_t>(m) < materials_.size() &&
            materials_[static_cast<std::size_t>(m)].emits())
            return true;
    }
    return false;
}

int PrimitiveImporter::material_for(int gltf_material)
{
    if (gltf_material >= 0) {
        if (gltf_material >= static_cast<int>(model_.materials.size()))
            throw Error(source_ + ": material index " + std::to_string(gltf_material) + " does not exist");
        return gltf_material;
    }
    if (default_material_ < 0) {
        SceneMaterial def; // the glTF default material
        def.name = "(default)";
        default_material_ = static_cast<int>(materials_.size());
        materials_.push_back(def);
    }
    return default_material_;
}

// Vertex indices of the primitive's triangles, strips and fans converted.
std::vector<std::uint32_t> PrimitiveImporter::triangle_indices(const tinygltf::Primitive& prim,
                                                               std::size_t vertex_count, const std::string& what)
{
    std::vector<std::uint32_t> idx;
    if (prim.indices >= 0) {
        AccessorReader r(model_, prim.indices, what + " indices", source_);
        if (!r.is_index_type())
            r.fail("indices must be unsigned byte, short or int scalars");
        idx.resize(r.count());
        for (std::size_t i = 0; i < r.count(); ++i) {
            double v = r.get(i, 0);
            if (v >= static_cast<double>(vertex_count))
                r.fail("index " + std::to_string(static_cast<std::uint64_t>(v)) + " is out of range (" +
                       std::to_string(vertex_count) + " vertices)");
            idx[i] = static_cast<std::uint32_t>(v);
        }
    } else {
        idx.resize(vertex_count);
        for (std::size_t i = 0; i < vertex_count; ++i)
            idx[i] = static_cast<std::uint32_t>(i);
    }
    std::vector<std::uint32_t> tris;
    if (prim.mode == kModeTriangles) {
        incomplete_triangle_lists_ += idx.size() % 3 != 0;
        tris.assign(idx.begin(), idx.begin() + static_cast<std::ptrdiff_t>(idx.size() / 3 * 3));
    } else if (prim.mode == kModeStrip) {
        for (std::size_t i = 2; i < idx.size(); ++i) {
            bool even = (i % 2) == 0; // alternate winding keeps every triangle CCW
            tris.insert(tris.end(), {idx[i - 2], even ? idx[i - 1] : idx[i], even ? idx[i] : idx[i - 1]});
        }
    } else if (prim.mode == kModeFan) {
        for (std::size_t i = 2; i < idx.size(); ++i)
            tris.insert(tris.end(), {idx[0], idx[i - 1], idx[i]});
    }
    return tris;
}

PrimitiveImporter::VertexAttributes PrimitiveImporter::read_vertex_attributes(const tinygltf::Primitive& prim,
                                                                              int material, const AccessorReader& pos,
                                                                              const std::vector<std::uint32_t>& tris,
                                                                              const std::string& what)
{
    VertexAttributes attr;
    const SceneMaterial& mat = materials_[static_cast<std::size_t>(material)];
    // Every set the material's textures read must be there.
    for (const TextureSlot& ts : texture_slot_table()) {
        const SceneTexture& texture = mat.textures[static_cast<std::size_t>(ts.slot)];
        if (!texture.present())
            continue;
        std::string attribute = "TEXCOORD_" + std::to_string(texture.texcoord);
        if (!prim.attributes.count(attribute))
            throw Error(source_ + ": " + what + ": its material's " + ts.name + " reads " + attribute +
                        ", which the primitive does not have");
    }
    attr.texcoords.resize(geometry_.texcoord_used.size());
    for (std::size_t set = 0; set < geometry_.texcoord_used.size(); ++set) {
        auto it = prim.attributes.find("TEXCOORD_" + std::to_string(set));
        if (!geometry_.texcoord_used[set] || it == prim.attributes.end())
            continue;
        AccessorReader r(model_, it->second, what + " TEXCOORD_" + std::to_string(set), source_);
        if (r.components() != 2 || r.count() != pos.count())
            r.fail("TEXCOORD_n must be VEC2 with one coordinate per vertex");
        if (!quantized_) // KHR_mesh_quantization allows unnormalized integers (scaled by a texture transform)
            r.require_float_or_normalized();
        attr.texcoords[set].resize(r.count());
        for (std::size_t i = 0; i < r.count(); ++i) {
            glm::dvec2 uv(r.get(i, 0), r.get(i, 1));
            if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
                r.fail("vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
            attr.texcoords[set][i] = glm::vec2(uv);
        }
    }
    if (auto it = prim.attributes.find("COLOR_0"); it != prim.attributes.end()) {
        AccessorReader r(model_, it->second, what + " COLOR_0", source_);
        if ((r.components() != 3 && r.components() != 4) || r.count() != pos.count())
            r.fail("COLOR_0 must be VEC3 or VEC4 with one colour per vertex");
        r.require_float_or_normalized();
        attr.colors.resize(r.count());
        for (std::size_t i = 0; i < r.count(); ++i) {
            glm::dvec4 c(r.get(i, 0), r.get(i, 1), r.get(i, 2), r.components() == 4 ? r.get(i, 3) : 1.0);
            for (int k = 0; k < 4; ++k)
                if (!(c[k] >= 0.0 && c[k] <= 1.0))
                    r.fail("vertex " + std::to_string(i) + " has a colour component outside [0, 1]");
            attr.colors[i] = glm::vec4(c);
        }
    }
    if (int set = tangent_texcoord(mat); set >= 0)
        attr.tangents = object_tangents(prim, set, pos, tris, what);
    return attr;
}

// Object-space tangents per corner of `tris`: the TANGENT attribute when the primitive
// has it and NORMAL (glTF: without normals, tangents are ignored), else computed from
// the texture coordinates of set `texcoord` (an anisotropic primitive without them gets
// arbitrary tangents in the surface, counted for a warning).
std::vector<glm::dvec4> PrimitiveImporter::object_tangents(const tinygltf::Primitive& prim, int texcoord,
                                                           const AccessorReader& pos,
                                                           const std::vector<std::uint32_t>& tris,
                                                           const std::string& what)
{
    auto nrm_it = prim.attributes.find("NORMAL");
    auto tan_it = prim.attributes.find("TANGENT");
    std::vector<glm::dvec4> out(tris.size());
    if (tan_it != prim.attributes.end() && nrm_it != prim.attributes.end()) {
        AccessorReader r(model_, tan_it->second, what + " TANGENT", source_);
        if (r.components() != 4 || r.count() != pos.count())
            r.fail("TANGENT must be VEC4 with one tangent per vertex");
        if (!r.is_float() && !quantized_)
            r.fail("TANGENT must be FLOAT (integer tangents need KHR_mesh_quantization)");
        std::vector<glm::dvec4> t(r.count());
        for (std::size_t i = 0; i < r.count(); ++i) {
            glm::dvec3 xyz(r.get(i, 0), r.get(i, 1), r.get(i, 2));
            if (!morph_.tangent.empty())
                xyz += morph_.tangent[i];
            t[i] = glm::dvec4(xyz, r.get(i, 3) < 0.0 ? -1.0 : 1.0);
            if (!std::isfinite(t[i].x) || !std::isfinite(t[i].y) || !std::isfinite(t[i].z))
                r.fail("vertex " + std::to_string(i) + " has a NaN or infinite tangent");
        }
        for (std::size_t c = 0; c < tris.size(); ++c)
            out[c] = t[tris[c]];
        return out;
    }
    std::vector<glm::dvec3> positions(pos.count()), normals;
    for (std::size_t i = 0; i < pos.count(); ++i)
        positions[i] = object_position(pos, i);
    if (nrm_it != prim.attributes.end()) {
        AccessorReader nr(model_, nrm_it->second, what + " NORMAL", source_);
        normals.resize(nr.count());
        for (std::size_t i = 0; i < nr.count(); ++i)
            normals[i] = object_normal(nr, i);
    }
    std::vector<glm::dvec2> uvs(pos.count(), glm::dvec2(0.0)); // no UV area: any direction in the surface
    if (auto uv_it = prim.attributes.find("TEXCOORD_" + std::to_string(texcoord)); uv_it != prim.attributes.end()) {
        AccessorReader ur(model_, uv_it->second, what + " TEXCOORD_" + std::to_string(texcoord), source_);
        if (ur.components() != 2 || ur.count() != pos.count())
            ur.fail("TEXCOORD_n must be VEC2 with one coordinate per vertex");
        for (std::size_t i = 0; i < ur.count(); ++i)
            uvs[i] = glm::dvec2(ur.get(i, 0), ur.get(i, 1));
    } else {
        ++arbitrary_tangents_;
    }
    return compute_tangents(positions, normals, uvs, tris);
}

} // namespace pathcl
