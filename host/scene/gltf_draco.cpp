// Draco decoding of KHR_draco_mesh_compression primitives into plain accessors. The
// extension object and its buffer view come from the file and are checked here; the
// Draco bitstream is checked by the Draco decoder; the decoded mesh is checked against
// the accessors the primitive lists (their counts and component counts), which tell the
// type each decoded value is stored as (glTF: "the accessor's type and componentType").
#include "scene/gltf_draco.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <utility>
#include <vector>

#include <draco/compression/decode.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "common/error.h"

namespace pathcl {
namespace {

constexpr const char* kDraco = "KHR_draco_mesh_compression";

// Decoded sections start at multiples of four bytes, as glTF wants of vertex attributes.
constexpr std::size_t kAlign = 4;

class PrimitiveDecoder {
public:
    PrimitiveDecoder(tinygltf::Model& model, tinygltf::Primitive& prim, int indices, std::string what)
        : model_(model), prim_(prim), indices_(indices), what_(std::move(what))
    {}

    void run(const tinygltf::Value& ext)
    {
        if (!ext.IsObject())
            fail("is not a JSON object");
        if (prim_.mode >= 0 && prim_.mode != TINYGLTF_MODE_TRIANGLES)
            fail("compresses a primitive of mode " + std::to_string(prim_.mode) + " (only triangles are read)");
        const tinygltf::Value& attributes = ext.Get("attributes");
        if (!attributes.IsObject())
            fail("has no \"attributes\" object");
        std::unique_ptr<draco::Mesh> mesh = decode(ext);
        buffer_ = static_cast<int>(model_.buffers.size());
        model_.buffers.emplace_back();
        write_indices(*mesh);
        for (const std::string& name : attributes.Keys()) {
            const tinygltf::Value& id = attributes.Get(name);
            if (!id.IsInt() || id.GetNumberAsInt() < 0)
                fail("attribute " + name + " has no valid Draco attribute id");
            const draco::PointAttribute* att =
                mesh->GetAttributeByUniqueId(static_cast<std::uint32_t>(id.GetNumberAsInt()));
            if (att == nullptr)
                fail("attribute " + name + ": the Draco data has no attribute " + std::to_string(id.GetNumberAsInt()));
            write_attribute(name, *att, *mesh);
        }
        prim_.extensions.erase(kDraco);
    }

private:
    [[noreturn]] void fail(const std::string& msg) const { throw Error(what_ + ": " + kDraco + ": " + msg); }

    std::unique_ptr<draco::Mesh> decode(const tinygltf::Value& ext)
    {
        const tinygltf::Value& view_value = ext.Get("bufferView");
        if (!view_value.IsInt())
            fail("has no integer \"bufferView\"");
        const int view_index = view_value.GetNumberAsInt();
        if (view_index < 0 || view_index >= static_cast<int>(model_.bufferViews.size()))
            fail("bufferView " + std::to_string(view_index) + " does not exist");
        const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(view_index)];
        if (view.buffer < 0 || view.buffer >= static_cast<int>(model_.buffers.size()))
            fail("bufferView " + std::to_string(view_index) + " has no valid buffer");
        const std::vector<unsigned char>& data = model_.buffers[static_cast<std::size_t>(view.buffer)].data;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
            fail("bufferView " + std::to_string(view_index) + " lies outside its buffer (" +
                 std::to_string(data.size()) + " bytes)");
        draco::DecoderBuffer in;
        in.Init(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
        draco::StatusOr<draco::EncodedGeometryType> type = draco::Decoder::GetEncodedGeometryType(&in);
        if (!type.ok())
            fail("cannot decode: " + type.status().error_msg_string());
        if (type.value() != draco::TRIANGULAR_MESH)
            fail("the Draco data is not a triangle mesh");
        draco::Decoder decoder;
        draco::StatusOr<std::unique_ptr<draco::Mesh>> mesh = decoder.DecodeMeshFromBuffer(&in);
        if (!mesh.ok())
            fail("cannot decode: " + mesh.status().error_msg_string());
        return std::move(mesh).value();
    }

    // The accessor the primitive names for `use` ("indices", an attribute), checked.
    const tinygltf::Accessor& accessor(int index, const std::string& use) const
    {
        if (index < 0 || index >= static_cast<int>(model_.accessors.size()))
            fail(use + ": accessor " + std::to_string(index) + " does not exist");
        return model_.accessors[static_cast<std::size_t>(index)];
    }

    // Appends `bytes` to the new buffer as a new view and returns the view's index.
    int add_view(const std::vector<unsigned char>& bytes)
    {
        std::vector<unsigned char>& data = model_.buffers[static_cast<std::size_t>(buffer_)].data;
        data.resize((data.size() + kAlign - 1) / kAlign * kAlign, 0);
        tinygltf::BufferView view;
        view.buffer = buffer_;
        view.byteOffset = data.size();
        view.byteLength = bytes.size();
        data.insert(data.end(), bytes.begin(), bytes.end());
        model_.bufferViews.push_back(view);
        return static_cast<int>(model_.bufferViews.size()) - 1;
    }

    // A copy of `like` over `bytes`: dense, at the start of a new view.
    int add_accessor(tinygltf::Accessor like, const std::vector<unsigned char>& bytes)
    {
        like.bufferView = add_view(bytes);
        like.byteOffset = 0;
        like.sparse.isSparse = false;
        model_.accessors.push_back(like);
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    // The faces' point indices as unsigned ints. A primitive without indices gets them:
    // Draco reorders the points, so the faces are the only order there is.
    void write_indices(const draco::Mesh& mesh)
    {
        const std::size_t count = std::size_t(mesh.num_faces()) * 3;
        tinygltf::Accessor acc;
        if (indices_ >= 0) {
            acc = accessor(indices_, "indices");
            if (acc.count != count)
                fail("indices: the accessor counts " + std::to_string(acc.count) + " indices, the Draco mesh has " +
                     std::to_string(count));
        }
        acc.type = TINYGLTF_TYPE_SCALAR;
        acc.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        acc.normalized = false;
        acc.count = count;
        std::vector<unsigned char> bytes(count * sizeof(std::uint32_t));
        for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
            for (int k = 0; k < 3; ++k) {
                std::uint32_t v = mesh.face(f)[k].value();
                std::memcpy(&bytes[(f.value() * 3 + static_cast<std::size_t>(k)) * sizeof v], &v, sizeof v);
            }
        prim_.indices = add_accessor(acc, bytes);
    }

    void write_attribute(const std::string& name, const draco::PointAttribute& att, const draco::Mesh& mesh)
    {
        auto it = prim_.attributes.find(name);
        if (it == prim_.attributes.end())
            fail("compresses attribute " + name + ", which the primitive does not list");
        const tinygltf::Accessor& acc = accessor(it->second, name);
        const std::size_t points = mesh.num_points();
        if (acc.count != points)
            fail(name + ": the accessor counts " + std::to_string(acc.count) + " elements, the Draco mesh has " +
                 std::to_string(points) + " points");
        const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(acc.type));
        const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(acc.componentType));
        if (components <= 0 || size <= 0)
            fail(name + ": the accessor has an invalid type or component type");
        if (components > att.num_components())
            fail(name + ": the accessor has " + std::to_string(components) + " components, the Draco attribute " +
                 std::to_string(att.num_components()));
        std::vector<unsigned char> bytes(points * static_cast<std::size_t>(components * size));
        for (draco::PointIndex p(0); p < mesh.num_points(); ++p)
            if (!convert(att, att.mapped_index(p), acc.componentType, components,
                         &bytes[p.value() * static_cast<std::size_t>(components * size)]))
                fail(name + ": point " + std::to_string(p.value()) + "'s value does not fit the accessor's type");
        it->second = add_accessor(acc, bytes);
    }

    // Stores one value of `att` as `components` components of glTF type `component_type`.
    static bool convert(const draco::PointAttribute& att, draco::AttributeValueIndex v, int component_type,
                        int components, unsigned char* out)
    {
        auto as = [&](auto zero) {
            using T = decltype(zero);
            T value[4] = {};
            if (!att.ConvertValue<T>(v, static_cast<std::int8_t>(components), value))
                return false;
            std::memcpy(out, value, sizeof(T) * static_cast<std::size_t>(components));
            return true;
        };
        switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return as(float{});
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return as(std::int8_t{});
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return as(std::uint8_t{});
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return as(std::int16_t{});
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return as(std::uint16_t{});
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return as(std::uint32_t{});
        default:
            return false;
        }
    }

    tinygltf::Model& model_;
    tinygltf::Primitive& prim_;
    int indices_; // the primitive's indices accessor, -1 if it has none
    std::string what_;
    int buffer_ = -1;
};

void put_le32(std::vector<unsigned char>& out, std::size_t v)
{
    for (int k = 0; k < 4; ++k)
        out.push_back(static_cast<unsigned char>((v >> (8 * k)) & 0xffu));
}

} // namespace

std::vector<unsigned char> detach_draco_indices(const std::vector<unsigned char>& file, bool binary,
                                                std::size_t json_size, nlohmann::json& doc, DracoIndices& indices)
{
    if (!doc.is_object())
        return {}; // not JSON (tinygltf says so) or not a document (the schema check has)
    auto meshes = doc.find("meshes");
    if (meshes == doc.end() || !meshes->is_array())
        return {};
    for (std::size_t m = 0; m < meshes->size(); ++m) {
        nlohmann::json& mesh = (*meshes)[m];
        auto prims = mesh.is_object() ? mesh.find("primitives") : mesh.end();
        if (prims == mesh.end() || !prims->is_array())
            continue;
        for (std::size_t p = 0; p < prims->size(); ++p) {
            nlohmann::json& prim = (*prims)[p];
            if (!prim.is_object() || !prim.contains("indices") || !prim["indices"].is_number_integer())
                continue;
            auto ext = prim.find("extensions");
            if (ext == prim.end() || !ext->is_object() || !ext->contains(kDraco))
                continue;
            indices[{m, p}] = prim["indices"].get<int>();
            prim.erase("indices");
        }
    }
    if (indices.empty())
        return {};
    std::string text = doc.dump();
    if (!binary)
        return {text.begin(), text.end()};
    text.resize((text.size() + 3) / 4 * 4, ' '); // a GLB chunk is padded to four bytes
    // The chunks after the JSON chunk, as they are (check_glb has checked the container).
    const std::size_t rest = 20 + json_size;
    std::vector<unsigned char> out(file.begin(), file.begin() + 8); // magic and version
    put_le32(out, 20 + text.size() + (file.size() - rest));
    put_le32(out, text.size());
    out.insert(out.end(), file.begin() + 16, file.begin() + 20); // the chunk type, JSON
    out.insert(out.end(), text.begin(), text.end());
    out.insert(out.end(), file.begin() + static_cast<std::ptrdiff_t>(rest), file.end());
    return out;
}

bool has_draco_primitives(const tinygltf::Model& model)
{
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& prim : mesh.primitives)
            if (prim.extensions.count(kDraco))
                return true;
    return false;
}

void decode_draco_primitives(tinygltf::Model& model, const std::string& source, const DracoIndices& detached)
{
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& prim = model.meshes[m].primitives[p];
            auto ext = prim.extensions.find(kDraco);
            if (ext == prim.extensions.end())
                continue;
            const tinygltf::Value value = ext->second; // run() erases the extension
            auto it = detached.find({m, p});
            const int indices = it != detached.end() ? it->second : prim.indices;
            PrimitiveDecoder(model, prim, indices,
                             source + ": mesh " + std::to_string(m) + " primitive " + std::to_string(p))
                .run(value);
        }
}

} // namespace pathcl
