// The glTF importer's driver: load_gltf and import_gltf, the checks of the file as a
// whole (required extensions, default scene) and the depth-first walk of the node
// hierarchy, which hands each mesh, light and camera to its importer and the result to
// render_space.
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <utility>

#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "common/error.h"
#include "common/memory_limits.h"
#include "scene/confined_files.h"
#include "scene/gltf_camera.h"
#include "scene/gltf_container.h"
#include "scene/gltf_draco.h"
#include "scene/gltf_environment.h"
#include "scene/gltf_images.h"
#include "scene/gltf_instancing.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_primitives.h"
#include "scene/gltf_schema.h"
#include "scene/gltf_textures.h"
#include "scene/gltf_variants.h"
#include "scene/pending_geometry.h"
#include "scene/render_space.h"

namespace pathcl {
namespace {

// A .gltf or .glb larger than this is refused (a GLB cannot be larger: its length is 32 bits).
constexpr std::size_t kMaxGltfFileBytes = 0xffffffffu;

// What a triangle costs on the host while a scene is imported and compiled (its pending
// double-precision copy, the scene's, the BVH's, the device arrays): about 316 bytes
// measured, `/usr/bin/time -v pathcl info` peaking at 675 MB resident for the 1,048,604
// flat-shaded triangles of the dense box and at 352 MB for the 38 of the Cornell box (its
// 50 MB file included; normals, texture coordinates and tangents add to it). The limit
// counts 300, so it refuses only scenes that cannot fit.
constexpr std::uint64_t kBytesPerTriangle = 300;
// What an instance of a stored mesh costs: its transform as imported (twice: pending and
// scene), its device record, its top-level BVH share.
constexpr std::uint64_t kBytesPerInstance = 600;
// Instances (drawings of stored meshes) a scene may have.
constexpr std::uint64_t kMaxInstances = std::uint64_t(1) << 22;

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

// The extensions pathcl reads; a file that requires any other is refused.
const std::set<std::string>& supported_extensions()
{
    static const std::set<std::string> supported = {"KHR_materials_emissive_strength",
                                                    "KHR_materials_specular",
                                                    "KHR_materials_clearcoat",
                                                    "KHR_materials_sheen",
                                                    "KHR_materials_anisotropy",
                                                    "KHR_materials_transmission",
                                                    "KHR_materials_ior",
                                                    "KHR_materials_pbrSpecularGlossiness",
                                                    "KHR_materials_variants",
                                                    "KHR_materials_unlit",
                                                    "KHR_materials_volume",
                                                    "KHR_lights_punctual",
                                                    "KHR_texture_transform",
                                                    "KHR_mesh_quantization",
                                                    "KHR_draco_mesh_compression",
                                                    "EXT_mesh_gpu_instancing"};
    return supported;
}

void check_required_extensions(const std::vector<std::string>& required, const std::string& source)
{
    for (const std::string& ext : required)
        if (!supported_extensions().count(ext))
            throw Error(source + ": requires the unsupported extension " + ext);
}

// extensionsRequired read from the parsed JSON, before tinygltf parses the file: an
// extension such as EXT_meshopt_compression makes buffers that tinygltf would refuse with
// a message about byte lengths instead.
void check_required_extensions(const nlohmann::json& doc, const std::string& source)
{
    if (!doc.is_object())
        return; // not JSON (tinygltf says so) or not a document (the schema check has)
    auto required = doc.find("extensionsRequired");
    if (required == doc.end() || !required->is_array())
        return;
    std::vector<std::string> names;
    for (const nlohmann::json& name : *required)
        if (name.is_string())
            names.push_back(name.get<std::string>());
    check_required_extensions(names, source);
}

struct Importer {
    Importer(const tinygltf::Model& m, const std::string& src, const std::string& dir)
        : model(m), source(src), base_dir(dir), textures(m, src, dir), primitives(m, src, scene.materials, geometry)
    {}

    const tinygltf::Model& model;
    const std::string& source;
    std::string base_dir;
    TextureImporter textures;
    Scene scene;
    PendingGeometry geometry; // the triangles, in world space until the render-space origin is known
    PrimitiveImporter primitives;
    SceneChoice choice;

    void run()
    {
        check_required_extensions(model.extensionsRequired, source);
        // One line per extension the file uses and pathcl does not read: the image may
        // differ from what its author meant (an alpha cut-out, a clear coat, a variant).
        for (const std::string& ext : std::set<std::string>(model.extensionsUsed.begin(), model.extensionsUsed.end()))
            if (!supported_extensions().count(ext))
                warn(source + ": ignores the extension " + ext + " (what it adds is not rendered)");

        scene.material_variants = material_variants(model, source);
        scene.variant = choice.variant;
        primitives.choose_variant(variant_index(scene.material_variants, choice.variant, source),
                                  scene.material_variants.size());
        scene.materials = import_materials(model, textures, source);
        plan_attributes(scene.materials, geometry);

        int scene_index = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (model.scenes.empty())
            throw Error(source + ": has no scene");
        if (scene_index >= static_cast<int>(model.scenes.size()))
            throw Error(source + ": default scene " + std::to_string(scene_index) + " does not exist");
        const tinygltf::Scene& gltf_scene = model.scenes[static_cast<std::size_t>(scene_index)];

        scene.environment = import_environment(gltf_scene.extras, base_dir, source);
        bool have_camera = import_nodes(gltf_scene.nodes);
        import_drawings();
        try {
            move_to_render_space(geometry, have_camera, scene);
        } catch (const Error& e) {
            throw Error(source + ": " + e.what());
        }
        scene.images = textures.take_images();
        if (scene.materials.empty())
            scene.materials.push_back(SceneMaterial{});
        if (std::size_t n = primitives.skipped_points_lines(); n > 0)
            warn(source + ": skipped " + std::to_string(n) +
                 (n == 1 ? " point or line primitive" : " point and line primitives") +
                 " (only triangles are rendered)");
        if (std::size_t n = primitives.incomplete_triangle_lists(); n > 0)
            warn(source + ": ignored the last one or two indices of " + std::to_string(n) + " triangle primitive" +
                 (n == 1 ? "" : "s") + " whose index count is not a multiple of 3");
        if (primitives.ignored_morph_attributes())
            warn(source + ": ignores " + std::to_string(primitives.ignored_morph_attributes()) +
                 " morph targets of attributes other than POSITION, NORMAL and TANGENT");
        if (std::size_t n = primitives.arbitrary_tangents(); n > 0)
            warn(source + ": " + std::to_string(n) + " primitive" + (n == 1 ? "" : "s") +
                 " with KHR_materials_anisotropy " + (n == 1 ? "has" : "have") +
                 " neither TANGENT nor texture coordinates: the anisotropy direction is arbitrary");
        if (scene.dropped_degenerate)
            warn(source + ": dropped " + std::to_string(scene.dropped_degenerate) +
                 " degenerate (zero-area) triangles");
        if (scene.repaired_normals)
            warn(source + ": replaced " + std::to_string(scene.repaired_normals) +
                 " zero-length or NaN normals by the geometric normal");
    }

    // A mesh drawn more than once (by several nodes, or EXT_mesh_gpu_instancing
    // instances) at the same morph weights is stored once and drawn by instances (a
    // two-level BVH), unless it emits light (each emissive triangle is a light with its
    // own render-space record) or the choice asks for copies. A mesh drawn once, and an
    // emissive one, is copied into render space per drawing.
    struct Drawing {
        int mesh;
        std::vector<double> weights; // the morph weights it is drawn at (the node's, else the mesh's)
        std::vector<glm::dmat4> transforms;
        std::string what;
    };
    std::vector<Drawing> drawings; // in depth-first node order

    // Copies and drawings are counted before any is made: a few hundred bytes of glTF
    // (a node, an instance's translation) can ask for more triangles than the machine
    // holds, and a scene that would not fit in memory is refused.
    std::uint64_t planned_triangles = 0, planned_instances = 0;

    static std::uint64_t mesh_triangle_count(const tinygltf::Model& model, const tinygltf::Mesh& mesh)
    {
        std::uint64_t count = 0;
        for (const tinygltf::Primitive& prim : mesh.primitives) {
            int counted = prim.indices;
            if (counted < 0) {
                auto pos = prim.attributes.find("POSITION");
                counted = pos == prim.attributes.end() ? -1 : pos->second;
            }
            if (counted < 0 || counted >= static_cast<int>(model.accessors.size()))
                continue; // the import names what is wrong
            const std::uint64_t n = model.accessors[static_cast<std::size_t>(counted)].count;
            const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
            count += mode == TINYGLTF_MODE_TRIANGLES                                              ? n / 3
                     : mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN ? (n > 2 ? n - 2 : 0)
                                                                                                  : 0;
        }
        return count;
    }

    void plan(std::uint64_t triangles, std::uint64_t instances, const std::string& what)
    {
        planned_triangles += triangles;
        planned_instances += instances;
        const std::string needs = source + ": " + what + ": the scene would need " + std::to_string(planned_triangles) +
                                  " triangles and " + std::to_string(planned_instances) + " instances";
        if (planned_instances > kMaxInstances)
            throw Error(needs + ", more than the " + std::to_string(kMaxInstances) +
                        " instances a scene may have (a ray may have to visit every instance whose box it "
                        "crosses: coincident instances cost time without bound)");
        const MemoryLimit memory = memory_limit();
        // In double: the counts may be far beyond what 64-bit byte counts hold.
        const double bytes = static_cast<double>(planned_triangles) * kBytesPerTriangle +
                             static_cast<double>(planned_instances) * kBytesPerInstance;
        if (bytes > memory.bytes)
            throw Error(needs + ", about " + gib(bytes) + " at " + std::to_string(kBytesPerTriangle) + " and " +
                        std::to_string(kBytesPerInstance) + " bytes each, more than " + memory.what);
    }

    // Imports every drawing: copies first, in node order, then each instanced mesh once
    // in its own space with its instances.
    void import_drawings()
    {
        using Key = std::pair<int, std::vector<double>>;
        std::map<Key, std::uint64_t> uses;
        for (const Drawing& d : drawings)
            uses[{d.mesh, d.weights}] += d.transforms.size();
        std::vector<bool> shared(drawings.size(), false);
        std::set<Key> planned;
        for (std::size_t i = 0; i < drawings.size(); ++i) {
            const Drawing& d = drawings[i];
            const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(d.mesh)];
            const std::uint64_t triangles = mesh_triangle_count(model, mesh);
            shared[i] = !choice.copy_instances && uses[{d.mesh, d.weights}] > 1 &&
                        !primitives.mesh_emits(mesh, d.what + " mesh " + std::to_string(d.mesh));
            // (Every drawing was counted as an instance when its transforms were read.)
            if (!shared[i])
                plan(triangles * d.transforms.size(), 0, d.what);
            else if (planned.insert({d.mesh, d.weights}).second)
                plan(triangles, 0, d.what);
        }
        auto import_mesh = [&](const Drawing& d, const glm::dmat4& transform) {
            const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(d.mesh)];
            for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
                primitives.import_primitive(
                    mesh.primitives[p], transform,
                    d.what + " mesh " + std::to_string(d.mesh) + " primitive " + std::to_string(p), d.weights);
        };
        for (std::size_t i = 0; i < drawings.size(); ++i)
            if (!shared[i])
                for (const glm::dmat4& transform : drawings[i].transforms)
                    import_mesh(drawings[i], transform);
        std::map<Key, std::size_t> mesh_index;
        for (std::size_t i = 0; i < drawings.size(); ++i) {
            if (!shared[i])
                continue;
            const Drawing& d = drawings[i];
            auto [it, first] = mesh_index.insert({{d.mesh, d.weights}, geometry.mesh_starts.size()});
            if (first) {
                geometry.mesh_starts.push_back(geometry.triangles.size());
                import_mesh(d, glm::dmat4(1.0));
            }
            for (const glm::dmat4& transform : d.transforms)
                geometry.instances.push_back(PendingInstance{it->second, transform});
        }
    }

    // glTF nodes form disjoint trees: a node has at most one parent and a scene's roots
    // have none. Checked before the walk, which could otherwise loop forever (a cycle) or
    // visit a node exponentially often (a chain of nodes that each list the next twice).
    void check_forest(const std::vector<int>& roots) const
    {
        const int n = static_cast<int>(model.nodes.size());
        auto check_index = [&](int node) {
            if (node < 0 || node >= n)
                throw Error(source + ": node index " + std::to_string(node) + " does not exist");
        };
        std::vector<int> parent(model.nodes.size(), -1);
        for (int i = 0; i < n; ++i)
            for (int child : model.nodes[static_cast<std::size_t>(i)].children) {
                check_index(child);
                int& p = parent[static_cast<std::size_t>(child)];
                if (p >= 0)
                    throw Error(source + ": node " + std::to_string(child) + " is a child of node " +
                                std::to_string(p) + " and of node " + std::to_string(i) +
                                " (a glTF node has at most one parent)");
                p = i;
            }
        std::vector<bool> is_root(model.nodes.size(), false);
        for (int root : roots) {
            check_index(root);
            if (parent[static_cast<std::size_t>(root)] >= 0)
                throw Error(source + ": root node " + std::to_string(root) + " is a child of node " +
                            std::to_string(parent[static_cast<std::size_t>(root)]) +
                            " (the hierarchy has a cycle or a root that is not a root)");
            if (is_root[static_cast<std::size_t>(root)])
                throw Error(source + ": the scene lists root node " + std::to_string(root) + " twice");
            is_root[static_cast<std::size_t>(root)] = true;
        }
    }

    // Walks the hierarchy below `roots` depth first, composing the node transforms in
    // double precision, and imports each node's mesh and light, and the chosen camera
    // (into scene.camera, still in world space). Returns whether it found that camera.
    bool import_nodes(const std::vector<int>& roots)
    {
        bool have_camera = false;
        int camera_nodes = 0; // camera nodes seen so far, in depth-first order
        const int wanted_camera = std::max(choice.camera, 0);
        struct Item {
            int node;
            glm::dmat4 parent;
        };
        check_forest(roots);
        std::vector<Item> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it)
            stack.push_back({*it, glm::dmat4(1.0)});
        while (!stack.empty()) {
            Item item = stack.back();
            stack.pop_back();
            const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(item.node)];
            glm::dmat4 world = item.parent * local_transform(node);
            std::string what = "node " + std::to_string(item.node) + (node.name.empty() ? "" : " " + quote(node.name));
            if (node.mesh >= 0) {
                if (node.mesh >= static_cast<int>(model.meshes.size()))
                    throw Error(source + ": " + what + ": mesh " + std::to_string(node.mesh) + " does not exist");
                const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(node.mesh)];
                // EXT_mesh_gpu_instancing: one drawing of the mesh per instance.
                auto plan_drawings = [&](std::size_t count) { plan(0, count, what); };
                drawings.push_back(Drawing{
                    node.mesh, node.weights.empty() ? mesh.weights : node.weights,
                    instance_transforms(model, node, world, primitives.quantized(), source, what, plan_drawings),
                    what});
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
                stack.push_back({*it, world});
        }
        if (choice.camera >= 0 && !have_camera)
            throw ParameterError("camera", "there is no camera node " + std::to_string(choice.camera) + ": " + source +
                                               " has " + std::to_string(camera_nodes) + " camera node" +
                                               (camera_nodes == 1 ? "" : "s") + " (counted from 0)");
        return have_camera;
    }
};

} // namespace

Scene import_gltf(const tinygltf::Model& model, const std::string& source, const std::string& base_dir,
                  const SceneChoice& choice)
{
    if (has_draco_primitives(model)) { // decoded into a copy: the caller's model stays as it is
        tinygltf::Model decoded = model;
        decode_draco_primitives(decoded, source);
        return import_gltf(decoded, source, base_dir, choice);
    }
    Importer importer(model, source, base_dir);
    importer.choice = choice;
    importer.run();
    return std::move(importer.scene);
}

Scene load_gltf(const std::string& path, const SceneChoice& choice)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(path + (std::filesystem::exists(path, ec) ? ": is not a regular file" : ": no such file"));
    // Read here, not by tinygltf: the container, the JSON nesting and the schema are checked first.
    std::vector<unsigned char> bytes = read_regular_file(path, kMaxGltfFileBytes);
    bool binary = is_glb(bytes.data(), bytes.size());
    std::string_view json(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (binary)
        json = check_glb(bytes.data(), bytes.size(), path);
    else
        check_json_nesting(bytes.data(), bytes.size(), path);
    nlohmann::json doc = parse_gltf_json(json);
    check_gltf_schema(doc, path);
    check_required_extensions(doc, path);
    DracoIndices draco_indices;
    if (std::vector<unsigned char> detached = detach_draco_indices(bytes, binary, json.size(), doc, draco_indices);
        !detached.empty())
        bytes = std::move(detached); // `json` and `doc` are not used below
    std::string base_dir = std::filesystem::path(path).parent_path().string();
    ConfinedFiles files(base_dir);
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(files.callbacks());
    loader.SetImageLoader(keep_encoded_image, nullptr); // decoded later, and only if a texture uses it
    tinygltf::Model model;
    std::string err, warning;
    bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warning, bytes.data(),
                                                   static_cast<unsigned int>(bytes.size()), base_dir)
                     : loader.LoadASCIIFromString(&model, &err, &warning, reinterpret_cast<const char*>(bytes.data()),
                                                  static_cast<unsigned int>(bytes.size()), base_dir);
    if (!ok && !files.refusals().empty())
        throw Error(path + ": " + files.refusals().front());
    if (!ok)
        throw Error(path + ": cannot load glTF: " + one_line(err.empty() ? warning : err));
    decode_draco_primitives(model, path, draco_indices);
    Importer importer(model, path, base_dir);
    importer.choice = choice;
    importer.textures.set_refusals(&files.refusals());
    importer.run();
    importer.scene.input_files = files.files_read();
    importer.scene.input_files.push_back(path);
    return std::move(importer.scene);
}

} // namespace pathcl
