// check_gltf_schema: one pass over the document, object by object, in the order of the
// glTF 2.0 schema. Each check names the member by its JSON path.
#include "scene/gltf_schema.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include <nlohmann/json.hpp>

#include "common/error.h"

namespace pathcl {
namespace {

using Json = nlohmann::json;

class SchemaCheck {
public:
    SchemaCheck(const Json& root, const std::string& what) : root_(root), what_(what) {}

    void run()
    {
        if (!root_.is_object())
            fail("the document", "is not a JSON object");
        asset_version();
        extension_objects(root_, "");
        lights_ = count_extension_array("KHR_lights_punctual", "lights");
        variants_ = count_extension_array("KHR_materials_variants", "variants");
        index(root_, "scene", "scene", "scenes");
        each(root_, "scenes", "scenes",
             [&](const Json& s, const std::string& at) { index_array(s, "nodes", at + ".nodes", "nodes"); });
        each(root_, "nodes", "nodes", [&](const Json& n, const std::string& at) { node(n, at); });
        each(root_, "meshes", "meshes", [&](const Json& m, const std::string& at) { mesh(m, at); });
        each(root_, "accessors", "accessors", [&](const Json& a, const std::string& at) { accessor(a, at); });
        each(root_, "bufferViews", "bufferViews", [&](const Json& v, const std::string& at) {
            index(v, "buffer", at + ".buffer", "buffers");
            integer(v, "byteOffset", at);
            integer(v, "byteLength", at);
            integer(v, "byteStride", at);
        });
        each(root_, "buffers", "buffers", [&](const Json& b, const std::string& at) { integer(b, "byteLength", at); });
        each(root_, "materials", "materials", [&](const Json& m, const std::string& at) { material(m, at); });
        each(root_, "textures", "textures", [&](const Json& t, const std::string& at) {
            index(t, "sampler", at + ".sampler", "samplers");
            index(t, "source", at + ".source", "images");
        });
        each(root_, "images", "images", [&](const Json& im, const std::string& at) {
            index(im, "bufferView", at + ".bufferView", "bufferViews");
        });
        each(root_, "samplers", "samplers", [&](const Json& s, const std::string& at) {
            for (const char* key : {"magFilter", "minFilter", "wrapS", "wrapT"})
                integer(s, key, at);
        });
        each(root_, "cameras", "cameras", [&](const Json& c, const std::string& at) { camera(c, at); });
        each(root_, "skins", "skins", [&](const Json& s, const std::string& at) {
            index(s, "inverseBindMatrices", at + ".inverseBindMatrices", "accessors");
            index(s, "skeleton", at + ".skeleton", "nodes");
            index_array(s, "joints", at + ".joints", "nodes");
        });
        each(root_, "animations", "animations", [&](const Json& a, const std::string& at) { animation(a, at); });
    }

private:
    // A major version other than 2 (glTF 1.0 has another schema) is refused before any of
    // its members is misread. (A missing asset or version is tinygltf's error.)
    void asset_version() const
    {
        auto asset = root_.find("asset");
        if (asset == root_.end() || !asset->is_object())
            return;
        auto version = asset->find("version");
        if (version == asset->end())
            return;
        if (!version->is_string()) // glTF 1.0 files have been written with "version": 1
            fail("asset.version", "is " + version->dump() + ", not a string \"2.x\": only glTF 2.0 files are read");
        const std::string& v = version->get_ref<const std::string&>();
        if (v.rfind("2.", 0) != 0)
            fail("asset.version", "is " + quote(v) + ": only glTF 2.0 files are read");
    }

    [[noreturn]] void fail(const std::string& at, const std::string& problem) const
    {
        throw Error(what_ + ": " + at + " " + problem);
    }

    // The length of root[array], 0 when absent; anything but an array is an error.
    std::size_t count(const char* array) const
    {
        if (!root_.contains(array))
            return 0;
        if (!root_[array].is_array())
            fail(array, "is not an array");
        return root_[array].size();
    }

    // Every "extensions" member anywhere in the document (outside extras, which are free
    // form) is an object whose members are objects: tinygltf skips an extension given as
    // a string or a number as if it were absent (a KHR_texture_transform that silently
    // does nothing).
    void extension_objects(const Json& v, const std::string& at) const
    {
        if (v.is_array()) {
            for (std::size_t i = 0; i < v.size(); ++i)
                extension_objects(v[i], at + "[" + std::to_string(i) + "]");
            return;
        }
        if (!v.is_object())
            return;
        for (const auto& [key, member] : v.items()) {
            const std::string member_at = at.empty() ? key : at + "." + key;
            if (key == "extras")
                continue;
            if (key == "extensions") {
                if (!member.is_object())
                    fail(member_at, "is not an object");
                for (const auto& [name, extension] : member.items())
                    if (!extension.is_object())
                        fail(member_at + "." + name, "is not an object");
            }
            extension_objects(member, member_at);
        }
    }

    std::size_t count_extension_array(const char* extension, const char* array) const
    {
        const Json* ext = member_object(root_, "extensions", "extensions");
        if (ext == nullptr || !ext->contains(extension))
            return 0;
        std::string at = std::string("extensions.") + extension;
        const Json& e = (*ext)[extension];
        if (!e.is_object())
            fail(at, "is not an object");
        if (!e.contains(array))
            return 0;
        if (!e[array].is_array())
            fail(at + "." + array, "is not an array");
        return e[array].size();
    }

    // obj[key] if present, checked to be an object; nullptr when absent.
    const Json* member_object(const Json& obj, const char* key, const std::string& at) const
    {
        if (!obj.contains(key))
            return nullptr;
        if (!obj[key].is_object())
            fail(at, "is not an object");
        return &obj[key];
    }

    // Calls f(element, "KEY[i]") for each element of obj[key], which must be an array of
    // objects when present.
    template <class F>
    void each(const Json& obj, const char* key, const std::string& at, F f) const
    {
        if (!obj.contains(key))
            return;
        const Json& array = obj[key];
        if (!array.is_array())
            fail(at, "is not an array");
        for (std::size_t i = 0; i < array.size(); ++i) {
            std::string element = at + "[" + std::to_string(i) + "]";
            if (!array[i].is_object())
                fail(element, "is not an object");
            f(array[i], element);
        }
    }

    // v must be a JSON integer naming one of `bound` elements of `target`.
    void index_value(const Json& v, const std::string& at, std::size_t bound, const char* target) const
    {
        if (!v.is_number_integer())
            fail(at, "is " + v.dump() + ", not an index (a JSON integer)");
        // nlohmann keeps every non-negative integer literal as unsigned.
        if (!v.is_number_unsigned() || v.get<std::uint64_t>() >= bound)
            fail(at, "is " + v.dump() + ", which names none of the " + std::to_string(bound) + " " + target);
    }

    void index(const Json& obj, const char* key, const std::string& at, const char* target) const
    {
        if (obj.contains(key))
            index_value(obj[key], at, count(target), target);
    }

    void index_array(const Json& obj, const char* key, const std::string& at, const char* target) const
    {
        if (!obj.contains(key))
            return;
        const Json& array = obj[key];
        if (!array.is_array())
            fail(at, "is not an array");
        std::size_t bound = count(target);
        for (std::size_t i = 0; i < array.size(); ++i)
            index_value(array[i], at + "[" + std::to_string(i) + "]", bound, target);
    }

    // Every member of `map` (an object: attributes, a morph target) is an index into `target`.
    void index_members(const Json& map, const std::string& at, const char* target) const
    {
        std::size_t bound = count(target);
        for (const auto& [name, v] : map.items())
            index_value(v, at + "." + name, bound, target);
    }

    // A non-negative JSON integer of at most `max` when present (counts, offsets, enums;
    // the glTF library reads some of them into an int).
    void integer(const Json& obj, const char* key, const std::string& at,
                 std::uint64_t max = std::numeric_limits<std::uint64_t>::max()) const
    {
        if (!obj.contains(key))
            return;
        const Json& v = obj[key];
        if (!v.is_number_unsigned())
            fail(at + "." + key, "is " + v.dump() + ", not a non-negative integer");
        if (v.get<std::uint64_t>() > max)
            fail(at + "." + key, "is " + v.dump() + ", more than " + std::to_string(max));
    }

    // A finite number when present.
    void number(const Json& obj, const char* key, const std::string& at) const
    {
        if (obj.contains(key) && !(obj[key].is_number() && std::isfinite(obj[key].get<double>())))
            fail(at + "." + key, "is " + obj[key].dump() + ", not a finite number");
    }

    // A string when present.
    void string(const Json& obj, const char* key, const std::string& at) const
    {
        if (obj.contains(key) && !obj[key].is_string())
            fail(at + "." + key, "is " + obj[key].dump() + ", not a string");
    }

    // An array of finite numbers when present; of exactly `length` of them unless length is 0.
    void numbers(const Json& obj, const char* key, const std::string& at, std::size_t length) const
    {
        if (!obj.contains(key))
            return;
        const Json& v = obj[key];
        std::string where = at + "." + key;
        if (!v.is_array() || (length != 0 && v.size() != length))
            fail(where,
                 "must be an array of " + (length != 0 ? std::to_string(length) + " " : std::string()) + "numbers");
        for (const Json& x : v)
            if (!(x.is_number() && std::isfinite(x.get<double>())))
                fail(where, "holds " + x.dump() + ", not a finite number");
    }

    void node(const Json& n, const std::string& at) const
    {
        index(n, "camera", at + ".camera", "cameras");
        index(n, "mesh", at + ".mesh", "meshes");
        index(n, "skin", at + ".skin", "skins");
        index_array(n, "children", at + ".children", "nodes");
        numbers(n, "translation", at, 3);
        numbers(n, "rotation", at, 4);
        numbers(n, "scale", at, 3);
        numbers(n, "matrix", at, 16);
        numbers(n, "weights", at, 0);
        if (n.contains("rotation")) {
            // Normalized when read; the zero quaternion has no direction to normalize to.
            const Json& q = n["rotation"];
            double x = q[0].get<double>(), y = q[1].get<double>(), z = q[2].get<double>(), w = q[3].get<double>();
            if (!(x * x + y * y + z * z + w * w > 1e-12))
                fail(at + ".rotation", "is " + q.dump() + ", not a unit quaternion");
        }
        const Json* ext = member_object(n, "extensions", at + ".extensions");
        if (ext != nullptr && ext->contains("KHR_lights_punctual")) {
            std::string light_at = at + ".extensions.KHR_lights_punctual";
            const Json* light = member_object(*ext, "KHR_lights_punctual", light_at);
            if (!light->contains("light"))
                fail(light_at, "has no \"light\"");
            index_value((*light)["light"], light_at + ".light", lights_, "KHR_lights_punctual lights");
        }
        if (ext != nullptr && ext->contains("EXT_mesh_gpu_instancing")) {
            const std::string at_ext = at + ".extensions.EXT_mesh_gpu_instancing";
            const Json* instancing = member_object(*ext, "EXT_mesh_gpu_instancing", at_ext);
            if (const Json* attributes = member_object(*instancing, "attributes", at_ext + ".attributes"))
                index_members(*attributes, at_ext + ".attributes", "accessors");
        }
    }

    // KHR_materials_variants mappings: each names a material and variants of the file's.
    void primitive_variants(const Json& p, const std::string& at) const
    {
        const Json* ext = member_object(p, "extensions", at + ".extensions");
        if (ext == nullptr || !ext->contains("KHR_materials_variants"))
            return;
        const std::string v_at = at + ".extensions.KHR_materials_variants";
        each(*member_object(*ext, "KHR_materials_variants", v_at), "mappings", v_at + ".mappings",
             [&](const Json& m, const std::string& m_at) {
                 index(m, "material", m_at + ".material", "materials");
                 if (!m.contains("variants"))
                     return;
                 const Json& list = m["variants"];
                 if (!list.is_array())
                     fail(m_at + ".variants", "is not an array");
                 for (std::size_t i = 0; i < list.size(); ++i)
                     index_value(list[i], m_at + ".variants[" + std::to_string(i) + "]", variants_,
                                 "KHR_materials_variants variants");
             });
    }

    void mesh(const Json& m, const std::string& at) const
    {
        if (!m.contains("primitives"))
            fail(at, "has no \"primitives\"");
        each(m, "primitives", at + ".primitives", [&](const Json& p, const std::string& p_at) {
            if (!p.contains("attributes"))
                fail(p_at, "has no \"attributes\"");
            index_members(*member_object(p, "attributes", p_at + ".attributes"), p_at + ".attributes", "accessors");
            index(p, "indices", p_at + ".indices", "accessors");
            index(p, "material", p_at + ".material", "materials");
            integer(p, "mode", p_at);
            primitive_variants(p, p_at);
            each(p, "targets", p_at + ".targets",
                 [&](const Json& t, const std::string& t_at) { index_members(t, t_at, "accessors"); });
        });
        numbers(m, "weights", at, 0);
    }

    void accessor(const Json& a, const std::string& at) const
    {
        index(a, "bufferView", at + ".bufferView", "bufferViews");
        integer(a, "byteOffset", at);
        integer(a, "componentType", at);
        integer(a, "count", at);
        numbers(a, "min", at, 0);
        numbers(a, "max", at, 0);
        const Json* sparse = member_object(a, "sparse", at + ".sparse");
        if (sparse == nullptr)
            return;
        // The glTF library reads these as int: 2^32 + 1 would become 1.
        constexpr std::uint64_t kIntMax = std::numeric_limits<std::int32_t>::max();
        integer(*sparse, "count", at + ".sparse", kIntMax);
        for (const char* part : {"indices", "values"}) {
            std::string part_at = at + ".sparse." + part;
            const Json* p = member_object(*sparse, part, part_at);
            if (p == nullptr)
                fail(at + ".sparse", std::string("has no \"") + part + "\"");
            index(*p, "bufferView", part_at + ".bufferView", "bufferViews");
            integer(*p, "byteOffset", part_at, kIntMax);
            integer(*p, "componentType", part_at, kIntMax);
        }
    }

    // A textureInfo (or normal/occlusion textureInfo) object when present.
    void texture_info(const Json& obj, const char* key, const std::string& at) const
    {
        const Json* info = member_object(obj, key, at + "." + key);
        if (info == nullptr)
            return;
        std::string info_at = at + "." + key;
        if (!info->contains("index"))
            fail(info_at, "has no \"index\"");
        index(*info, "index", info_at + ".index", "textures");
        integer(*info, "texCoord", info_at);
        number(*info, "scale", info_at);
        number(*info, "strength", info_at);
    }

    void material(const Json& m, const std::string& at) const
    {
        if (const Json* pbr = member_object(m, "pbrMetallicRoughness", at + ".pbrMetallicRoughness")) {
            std::string pbr_at = at + ".pbrMetallicRoughness";
            numbers(*pbr, "baseColorFactor", pbr_at, 4);
            number(*pbr, "metallicFactor", pbr_at);
            number(*pbr, "roughnessFactor", pbr_at);
            texture_info(*pbr, "baseColorTexture", pbr_at);
            texture_info(*pbr, "metallicRoughnessTexture", pbr_at);
        }
        texture_info(m, "normalTexture", at);
        texture_info(m, "occlusionTexture", at);
        texture_info(m, "emissiveTexture", at);
        numbers(m, "emissiveFactor", at, 3);
        number(m, "alphaCutoff", at);
        string(m, "alphaMode", at);
        // The material extensions name their textures "...Texture"; each is a textureInfo.
        // (extension_objects has made every extension an object.)
        if (const Json* ext = member_object(m, "extensions", at + ".extensions")) {
            for (const auto& [name, e] : ext->items()) {
                for (const auto& [member, v] : e.items()) {
                    (void)v;
                    if (member.size() > 7 && member.compare(member.size() - 7, 7, "Texture") == 0)
                        texture_info(e, member.c_str(), at + ".extensions." + name);
                }
            }
        }
    }

    void camera(const Json& c, const std::string& at) const
    {
        for (const char* projection : {"perspective", "orthographic"}) {
            const Json* p = member_object(c, projection, at + "." + projection);
            if (p == nullptr)
                continue;
            for (const char* key : {"yfov", "aspectRatio", "xmag", "ymag", "znear", "zfar"})
                number(*p, key, at + "." + projection);
        }
    }

    void animation(const Json& a, const std::string& at) const
    {
        std::size_t samplers = 0;
        if (a.contains("samplers")) {
            if (!a["samplers"].is_array())
                fail(at + ".samplers", "is not an array");
            samplers = a["samplers"].size();
        }
        each(a, "channels", at + ".channels", [&](const Json& ch, const std::string& ch_at) {
            if (ch.contains("sampler"))
                index_value(ch["sampler"], ch_at + ".sampler", samplers, "samplers of the animation");
            if (const Json* target = member_object(ch, "target", ch_at + ".target"))
                index(*target, "node", ch_at + ".target.node", "nodes");
        });
        each(a, "samplers", at + ".samplers", [&](const Json& s, const std::string& s_at) {
            index(s, "input", s_at + ".input", "accessors");
            index(s, "output", s_at + ".output", "accessors");
        });
    }

    const Json& root_;
    const std::string& what_;
    std::size_t lights_ = 0, variants_ = 0;
};

} // namespace

Json parse_gltf_json(std::string_view json)
{
    return Json::parse(json.begin(), json.end(), nullptr, /*allow_exceptions=*/false);
}

void check_gltf_schema(const Json& doc, const std::string& what)
{
    if (doc.is_discarded())
        return; // the glTF library's parser reports what is wrong with the text
    SchemaCheck(doc, what).run();
}

} // namespace pathcl
