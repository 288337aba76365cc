#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "common/error.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_camera.h"
#include "scene/gltf_environment.h"
#include "scene/gltf_images.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_textures.h"
#include "scene/pending_geometry.h"
#include "scene/render_space.h"
#include "scene/tangents.h"

namespace pathcl {
namespace {

constexpr int kModeTriangles = 4, kModeStrip = 5, kModeFan = 6;

std::string one_line(std::string s)
{
    std::replace(s.begin(), s.end(), '\n', ' ');
    while (!s.empty() && (s.back() == ' ' || s.back() == '\r'))
        s.pop_back();
    return s;
}

glm::dmat4 local_transform(const tinygltf::Node& node)
{
    if (node.matrix.size() == 16)
        return glm::make_mat4(node.matrix.data()); // column-major, as glTF stores it
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3)
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4) {
        glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        m = m * glm::mat4_cast(glm::normalize(q));
    }
    if (node.scale.size() == 3)
        m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

struct Importer {
    Importer(const tinygltf::Model& m, const std::string& src, const std::string& dir)
        : model(m), source(src), base_dir(dir), textures(m, src, dir)
    {
    }

    const tinygltf::Model& model;
    const std::string& source;
    std::string base_dir;
    TextureImporter textures;
    Scene scene;
    int default_material = -1;
    std::size_t skipped_points_lines = 0;

    PendingGeometry geometry; // the triangles, in world space until the render-space origin is known
    int camera_choice = -1; // camera node to use (depth-first order); -1: the first, if any

    int material_for(int gltf_material)
    {
        if (gltf_material >= 0) {
            if (gltf_material >= static_cast<int>(model.materials.size()))
                throw Error(source + ": material index " + std::to_string(gltf_material) +
                            " does not exist");
            return gltf_material;
        }
        if (default_material < 0) {
            SceneMaterial def; // the glTF default material
            def.name = "(default)";
            default_material = static_cast<int>(scene.materials.size());
            scene.materials.push_back(def);
        }
        return default_material;
    }

    // Vertex indices of the primitive's triangles, strips and fans converted.
    std::vector<std::uint32_t> triangle_indices(const tinygltf::Primitive& prim,
                                                std::size_t vertex_count, const std::string& what)
    {
        std::vector<std::uint32_t> idx;
        if (prim.indices >= 0) {
            AccessorReader r(model, prim.indices, what + " indices", source);
            if (!r.is_index_type())
                r.fail("indices must be unsigned byte, short or int scalars");
            idx.resize(r.count());
            for (std::size_t i = 0; i < r.count(); ++i) {
                double v = r.get(i, 0);
                if (v >= static_cast<double>(vertex_count))
                    r.fail("index " + std::to_string(static_cast<std::uint64_t>(v)) +
                           " is out of range (" + std::to_string(vertex_count) + " vertices)");
                idx[i] = static_cast<std::uint32_t>(v);
            }
        } else {
            idx.resize(vertex_count);
            for (std::size_t i = 0; i < vertex_count; ++i)
                idx[i] = static_cast<std::uint32_t>(i);
        }
        std::vector<std::uint32_t> tris;
        if (prim.mode == kModeTriangles) {
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

    void import_primitive(const tinygltf::Primitive& prim_in, const glm::dmat4& world,
                          const std::string& what)
    {
        tinygltf::Primitive prim = prim_in;
        if (prim.mode < 0) // unset (tinygltf's -1): glTF's default is triangles
            prim.mode = kModeTriangles;
        if (prim.mode < kModeTriangles) {
            ++skipped_points_lines;
            return;
        }
        if (prim.mode > kModeFan)
            throw Error(source + ": " + what + ": invalid primitive mode " + std::to_string(prim.mode));
        auto pos_it = prim.attributes.find("POSITION");
        if (pos_it == prim.attributes.end())
            throw Error(source + ": " + what + ": has no POSITION attribute");
        AccessorReader pos(model, pos_it->second, what + " POSITION", source);
        if (pos.components() != 3)
            pos.fail("POSITION must be VEC3");
        std::vector<glm::dvec3> p(pos.count());
        for (std::size_t i = 0; i < pos.count(); ++i) {
            glm::dvec4 w = world * glm::dvec4(pos.get(i, 0), pos.get(i, 1), pos.get(i, 2), 1.0);
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
            AccessorReader nr(model, nrm_it->second, what + " NORMAL", source);
            if (nr.components() != 3 || nr.count() != pos.count())
                nr.fail("NORMAL must be VEC3 with one normal per vertex");
            n.resize(nr.count());
            for (std::size_t i = 0; i < nr.count(); ++i)
                n[i] = normal_matrix * glm::dvec3(nr.get(i, 0), nr.get(i, 1), nr.get(i, 2));
        }
        int material = material_for(prim.material);
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
            geometry.triangles.push_back(tri);
            for (std::size_t set = 0; set < geometry.texcoord_used.size(); ++set) {
                if (!geometry.texcoord_used[set])
                    continue;
                TriangleUv uv{};
                if (!attr.texcoords[set].empty())
                    for (int k = 0; k < 3; ++k)
                        uv[static_cast<std::size_t>(k)] = attr.texcoords[set][ids[k]];
                geometry.texcoords[set].push_back(uv);
            }
            if (geometry.tangents_used) {
                std::array<glm::dvec4, 3> tangent{};
                if (!attr.tangents.empty())
                    for (int k = 0; k < 3; ++k) {
                        glm::dvec4 ot = attr.tangents[t + static_cast<std::size_t>(corner[k])];
                        tangent[static_cast<std::size_t>(k)] = glm::dvec4(m3 * glm::dvec3(ot), ot.w * handedness);
                    }
                geometry.tangents.push_back(tangent);
            }
            if (!attr.colors.empty() || !geometry.colors.empty()) {
                geometry.colors.resize(geometry.triangles.size() - 1, kWhiteTriangleColor);
                TriangleColor c = kWhiteTriangleColor;
                if (!attr.colors.empty())
                    for (int k = 0; k < 3; ++k)
                        c[static_cast<std::size_t>(k)] = attr.colors[ids[k]];
                geometry.colors.push_back(c);
            }
        }
    }

    // A primitive's optional vertex attributes, for the vertices of `tris`.
    struct VertexAttributes {
        std::vector<std::vector<glm::vec2>> texcoords; // [set][vertex], for the used sets it has
        std::vector<glm::dvec4> tangents;              // object space, per corner of `tris`
        std::vector<glm::vec3> colors;                 // per vertex
    };

    VertexAttributes read_vertex_attributes(const tinygltf::Primitive& prim, int material, const AccessorReader& pos,
                                            const std::vector<std::uint32_t>& tris, const std::string& what)
    {
        VertexAttributes attr;
        const SceneMaterial& mat = scene.materials[static_cast<std::size_t>(material)];
        // Every set the material's textures read must be there.
        for (const auto& [slot, name] : texture_slots(mat)) {
            if (!slot->present())
                continue;
            std::string attribute = "TEXCOORD_" + std::to_string(slot->texcoord);
            if (!prim.attributes.count(attribute))
                throw Error(source + ": " + what + ": its material's " + name + " reads " + attribute +
                            ", which the primitive does not have");
        }
        attr.texcoords.resize(geometry.texcoord_used.size());
        for (std::size_t set = 0; set < geometry.texcoord_used.size(); ++set) {
            auto it = prim.attributes.find("TEXCOORD_" + std::to_string(set));
            if (!geometry.texcoord_used[set] || it == prim.attributes.end())
                continue;
            AccessorReader r(model, it->second, what + " TEXCOORD_" + std::to_string(set), source);
            if (r.components() != 2 || r.count() != pos.count())
                r.fail("TEXCOORD_n must be VEC2 with one coordinate per vertex");
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
            AccessorReader r(model, it->second, what + " COLOR_0", source);
            if ((r.components() != 3 && r.components() != 4) || r.count() != pos.count())
                r.fail("COLOR_0 must be VEC3 or VEC4 with one colour per vertex");
            r.require_float_or_normalized();
            attr.colors.resize(r.count());
            for (std::size_t i = 0; i < r.count(); ++i) {
                glm::dvec3 c(r.get(i, 0), r.get(i, 1), r.get(i, 2)); // alpha is not used
                for (int k = 0; k < 3; ++k)
                    if (!(c[k] >= 0.0 && c[k] <= 1.0))
                        r.fail("vertex " + std::to_string(i) + " has a colour component outside [0, 1]");
                attr.colors[i] = glm::vec3(c);
            }
        }
        if (mat.normal_texture.present())
            attr.tangents = object_tangents(prim, mat.normal_texture.texcoord, pos, tris, what);
        return attr;
    }

    // Object-space tangents per corner of `tris`: the TANGENT attribute when the primitive
    // has it and NORMAL (glTF: without normals, tangents are ignored), else computed from
    // the normal texture's texture coordinates.
    std::vector<glm::dvec4> object_tangents(const tinygltf::Primitive& prim, int texcoord, const AccessorReader& pos,
                                            const std::vector<std::uint32_t>& tris, const std::string& what)
    {
        auto nrm_it = prim.attributes.find("NORMAL");
        auto tan_it = prim.attributes.find("TANGENT");
        std::vector<glm::dvec4> out(tris.size());
        if (tan_it != prim.attributes.end() && nrm_it != prim.attributes.end()) {
            AccessorReader r(model, tan_it->second, what + " TANGENT", source);
            if (r.components() != 4 || r.count() != pos.count())
                r.fail("TANGENT must be VEC4 with one tangent per vertex");
            std::vector<glm::dvec4> t(r.count());
            for (std::size_t i = 0; i < r.count(); ++i) {
                t[i] = glm::dvec4(r.get(i, 0), r.get(i, 1), r.get(i, 2), r.get(i, 3) < 0.0 ? -1.0 : 1.0);
                if (!std::isfinite(t[i].x) || !std::isfinite(t[i].y) || !std::isfinite(t[i].z))
                    r.fail("vertex " + std::to_string(i) + " has a NaN or infinite tangent");
            }
            for (std::size_t c = 0; c < tris.size(); ++c)
                out[c] = t[tris[c]];
            return out;
        }
        std::vector<glm::dvec3> positions(pos.count()), normals;
        for (std::size_t i = 0; i < pos.count(); ++i)
            positions[i] = glm::dvec3(pos.get(i, 0), pos.get(i, 1), pos.get(i, 2));
        if (nrm_it != prim.attributes.end()) {
            AccessorReader nr(model, nrm_it->second, what + " NORMAL", source);
            normals.resize(nr.count());
            for (std::size_t i = 0; i < nr.count(); ++i)
                normals[i] = glm::dvec3(nr.get(i, 0), nr.get(i, 1), nr.get(i, 2));
        }
        AccessorReader ur(model, prim.attributes.at("TEXCOORD_" + std::to_string(texcoord)),
                          what + " TEXCOORD_" + std::to_string(texcoord), source);
        std::vector<glm::dvec2> uvs(ur.count());
        for (std::size_t i = 0; i < ur.count(); ++i)
            uvs[i] = glm::dvec2(ur.get(i, 0), ur.get(i, 1));
        return compute_tangents(positions, normals, uvs, tris);
    }

    void run()
    {
        static const std::set<std::string> supported = {
            "KHR_materials_emissive_strength", "KHR_materials_specular", "KHR_materials_transmission",
            "KHR_materials_ior", "KHR_materials_volume", "KHR_lights_punctual", "KHR_texture_transform"};
        for (const std::string& ext : model.extensionsRequired)
            if (!supported.count(ext))
                throw Error(source + ": requires the unsupported extension " + ext);

        scene.materials = import_materials(model, textures, source);
        for (const SceneMaterial& material : scene.materials) {
            for (const auto& [slot, name] : texture_slots(material)) {
                if (!slot->present())
                    continue;
                std::size_t set = static_cast<std::size_t>(slot->texcoord);
                if (set >= geometry.texcoord_used.size())
                    geometry.texcoord_used.resize(set + 1, false);
                geometry.texcoord_used[set] = true;
            }
            geometry.tangents_used = geometry.tangents_used || material.normal_texture.present();
        }
        geometry.texcoords.resize(geometry.texcoord_used.size());

        int scene_index = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (model.scenes.empty())
            throw Error(source + ": has no scene");
        if (scene_index >= static_cast<int>(model.scenes.size()))
            throw Error(source + ": default scene " + std::to_string(scene_index) + " does not exist");

        scene.environment = import_environment(model.scenes[static_cast<std::size_t>(scene_index)].extras, base_dir,
                                               source);

        bool have_camera = false;
        int camera_nodes = 0; // camera nodes seen so far, in depth-first order
        const int wanted_camera = std::max(camera_choice, 0);
        struct Item {
            int node;
            glm::dmat4 parent;
            int depth;
        };
        std::vector<Item> stack;
        const auto& roots = model.scenes[static_cast<std::size_t>(scene_index)].nodes;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it)
            stack.push_back({*it, glm::dmat4(1.0), 0});
        const int max_depth = static_cast<int>(model.nodes.size()) + 1; // deeper means a cycle
        while (!stack.empty()) {
            Item item = stack.back();
            stack.pop_back();
            if (item.node < 0 || item.node >= static_cast<int>(model.nodes.size()))
                throw Error(source + ": node index " + std::to_string(item.node) + " does not exist");
            if (item.depth > max_depth)
                throw Error(source + ": the node hierarchy has a cycle");
            const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(item.node)];
            glm::dmat4 world = item.parent * local_transform(node);
            std::string what = "node " + std::to_string(item.node) +
                               (node.name.empty() ? "" : " '" + node.name + "'");
            if (node.mesh >= 0) {
                if (node.mesh >= static_cast<int>(model.meshes.size()))
                    throw Error(source + ": " + what + ": mesh " + std::to_string(node.mesh) + " does not exist");
                const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(node.mesh)];
                for (std::size_t i = 0; i < mesh.primitives.size(); ++i)
                    import_primitive(mesh.primitives[i], world,
                                     what + " mesh " + std::to_string(node.mesh) + " primitive " +
                                         std::to_string(i));
            }
            auto light_ext = node.extensions.find("KHR_lights_punctual");
            if (light_ext != node.extensions.end() && light_ext->second.Has("light"))
                scene.lights.push_back(import_light(model, light_ext->second.Get("light"), world, what, source));
            if (node.camera >= 0) {
                if (node.camera >= static_cast<int>(model.cameras.size()))
                    throw Error(source + ": " + what + ": camera " + std::to_string(node.camera) + " does not exist");
                if (camera_nodes++ == wanted_camera) {
                    scene.camera = import_camera(model.cameras[static_cast<std::size_t>(node.camera)], node.extras,
                                                 world, what, source);
                    have_camera = true;
                }
            }
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
                stack.push_back({*it, world, item.depth + 1});
        }
        if (camera_choice >= 0 && !have_camera)
            throw Error(source + ": --camera " + std::to_string(camera_choice) + ": the scene has " +
                        std::to_string(camera_nodes) + " camera node" + (camera_nodes == 1 ? "" : "s") +
                        " (counted from 0)");
        move_to_render_space(geometry, have_camera, scene);
        scene.images = textures.take_images();
        if (scene.materials.empty())
            scene.materials.push_back(SceneMaterial{});
        if (skipped_points_lines)
            warn(source + ": skipped " + std::to_string(skipped_points_lines) +
                 " point and line primitives (only triangles are rendered)");
        if (scene.dropped_degenerate)
            warn(source + ": dropped " + std::to_string(scene.dropped_degenerate) +
                 " degenerate (zero-area) triangles");
        if (scene.repaired_normals)
            warn(source + ": replaced " + std::to_string(scene.repaired_normals) +
                 " zero-length or NaN normals by the geometric normal");
    }
};

} // namespace

Scene import_gltf(const tinygltf::Model& model, const std::string& source, const std::string& base_dir, int camera)
{
    Importer importer(model, source, base_dir);
    importer.camera_choice = camera;
    importer.run();
    return std::move(importer.scene);
}

Scene load_gltf(const std::string& path, int camera)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(path + ": no such file");
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(load_gltf_image, nullptr); // OpenImageIO decodes, not tinygltf
    tinygltf::Model model;
    std::string err, warning;
    bool binary = std::filesystem::path(path).extension() == ".glb";
    bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warning, path)
                     : loader.LoadASCIIFromFile(&model, &err, &warning, path);
    if (!ok)
        throw Error(path + ": cannot load glTF: " + one_line(err.empty() ? warning : err));
    return import_gltf(model, path, std::filesystem::path(path).parent_path().string(), camera);
}

} // namespace pathcl
