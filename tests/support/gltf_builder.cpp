#include "support/gltf_builder.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>

#include <png.h>

namespace pathcl::test {

GltfBuilder::GltfBuilder()
{
    model.buffers.emplace_back();
    model.scenes.emplace_back();
    model.defaultScene = 0;
}

int GltfBuilder::add_view(const void* data, std::size_t bytes)
{
    std::vector<unsigned char>& buf = model.buffers[0].data;
    while (buf.size() % 4)
        buf.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buf.size();
    view.byteLength = bytes;
    buf.insert(buf.end(), static_cast<const unsigned char*>(data), static_cast<const unsigned char*>(data) + bytes);
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size()) - 1;
}

int GltfBuilder::add_accessor(int view, int component_type, int type, std::size_t count)
{
    tinygltf::Accessor acc;
    acc.bufferView = view;
    acc.componentType = component_type;
    acc.type = type;
    acc.count = count;
    model.accessors.push_back(acc);
    return static_cast<int>(model.accessors.size()) - 1;
}

int GltfBuilder::add_positions(const std::vector<glm::vec3>& p)
{
    int view = add_view(p.data(), p.size() * sizeof(glm::vec3));
    return add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, p.size());
}

int GltfBuilder::add_normals(const std::vector<glm::vec3>& n)
{
    return add_positions(n);
}

int GltfBuilder::add_indices(const std::vector<std::uint32_t>& idx, int component_type)
{
    std::vector<unsigned char> bytes;
    std::size_t size = component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                       : component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                                                                                  : 4;
    for (std::uint32_t i : idx)
        for (std::size_t b = 0; b < size; ++b)
            bytes.push_back(static_cast<unsigned char>(i >> (8 * b)));
    int view = add_view(bytes.data(), bytes.size());
    return add_accessor(view, component_type, TINYGLTF_TYPE_SCALAR, idx.size());
}

int GltfBuilder::add_material(const glm::vec3& base_color, const glm::vec3& emission, bool double_sided,
                              double emissive_strength)
{
    tinygltf::Material m;
    m.pbrMetallicRoughness.baseColorFactor = {base_color.x, base_color.y, base_color.z, 1.0};
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.emissiveFactor = {emission.x, emission.y, emission.z};
    m.doubleSided = double_sided;
    tinygltf::Value::Object spec;
    spec["specularFactor"] = tinygltf::Value(0.0);
    m.extensions["KHR_materials_specular"] = tinygltf::Value(spec);
    if (emissive_strength != 1.0) {
        tinygltf::Value::Object ext;
        ext["emissiveStrength"] = tinygltf::Value(emissive_strength);
        m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(ext);
    }
    model.materials.push_back(m);
    return static_cast<int>(model.materials.size()) - 1;
}

int GltfBuilder::add_pbr_material(const Pbr& pbr)
{
    tinygltf::Material m;
    m.pbrMetallicRoughness.baseColorFactor = {pbr.base_color.x, pbr.base_color.y, pbr.base_color.z, 1.0};
    m.pbrMetallicRoughness.metallicFactor = pbr.metallic;
    m.pbrMetallicRoughness.roughnessFactor = pbr.roughness;
    m.doubleSided = pbr.double_sided;
    auto ext = [&](const char* name, const char* key, double value) {
        tinygltf::Value::Object o;
        o[key] = tinygltf::Value(value);
        m.extensions[name] = tinygltf::Value(o);
    };
    if (pbr.specular != 1.0)
        ext("KHR_materials_specular", "specularFactor", pbr.specular);
    if (pbr.transmission > 0.0) {
        ext("KHR_materials_transmission", "transmissionFactor", pbr.transmission);
        ext("KHR_materials_ior", "ior", pbr.ior);
        if (pbr.thickness > 0.0)
            ext("KHR_materials_volume", "thicknessFactor", pbr.thickness);
    }
    model.materials.push_back(m);
    return static_cast<int>(model.materials.size()) - 1;
}

int GltfBuilder::add_mesh(int positions, int indices, int material, int mode, int normals)
{
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = positions;
    if (normals >= 0)
        prim.attributes["NORMAL"] = normals;
    prim.indices = indices;
    prim.material = material;
    prim.mode = mode;
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(prim);
    model.meshes.push_back(mesh);
    return static_cast<int>(model.meshes.size()) - 1;
}

int GltfBuilder::add_node(int mesh, const std::vector<double>& matrix, const std::vector<double>& translation,
                          const std::vector<double>& rotation, const std::vector<double>& scale)
{
    tinygltf::Node node;
    node.mesh = mesh;
    node.matrix = matrix;
    node.translation = translation;
    node.rotation = rotation;
    node.scale = scale;
    model.nodes.push_back(node);
    return static_cast<int>(model.nodes.size()) - 1;
}

int GltfBuilder::add_perspective_camera(double yfov)
{
    tinygltf::Camera cam;
    cam.type = "perspective";
    cam.perspective.yfov = yfov;
    cam.perspective.aspectRatio = 1.0;
    cam.perspective.znear = 0.01;
    model.cameras.push_back(cam);
    return static_cast<int>(model.cameras.size()) - 1;
}

int GltfBuilder::add_light(const std::string& type, const glm::vec3& color, double intensity, double inner_cone,
                           double outer_cone, const tinygltf::Value& extras)
{
    tinygltf::Light l;
    l.type = type;
    l.color = {color.x, color.y, color.z};
    l.intensity = intensity;
    l.spot.innerConeAngle = inner_cone;
    l.spot.outerConeAngle = outer_cone;
    l.extras = extras;
    model.lights.push_back(l);
    if (std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_lights_punctual") ==
        model.extensionsUsed.end())
        model.extensionsUsed.push_back("KHR_lights_punctual");
    return static_cast<int>(model.lights.size()) - 1;
}

int GltfBuilder::add_light_node(int light, const std::vector<double>& translation, const std::vector<double>& rotation)
{
    int node = add_node(-1, {}, translation, rotation);
    tinygltf::Value::Object ext;
    ext["light"] = tinygltf::Value(light);
    model.nodes[static_cast<std::size_t>(node)].extensions["KHR_lights_punctual"] = tinygltf::Value(ext);
    add_root(node);
    return node;
}

int GltfBuilder::add_camera_node(int camera, const std::vector<double>& translation,
                                 const std::vector<double>& rotation)
{
    int node = add_node(-1, {}, translation, rotation);
    model.nodes[static_cast<std::size_t>(node)].camera = camera;
    add_root(node);
    return node;
}

void GltfBuilder::add_root(int node)
{
    model.scenes[0].nodes.push_back(node);
}

tinygltf::Value json_numbers(const std::vector<double>& values)
{
    tinygltf::Value::Array a;
    for (double v : values)
        a.emplace_back(v);
    return tinygltf::Value(a);
}

tinygltf::Value texture_info(int index, int texcoord)
{
    tinygltf::Value::Object o;
    o["index"] = tinygltf::Value(index);
    o["texCoord"] = tinygltf::Value(texcoord);
    return tinygltf::Value(o);
}

int GltfBuilder::add_quad_mesh(const std::vector<glm::vec3>& corners, int material)
{
    return add_mesh(add_positions(corners), add_indices({0, 1, 2, 0, 2, 3}, kU16), material);
}

int GltfBuilder::add_box_mesh(glm::vec3 h, int material)
{
    std::vector<glm::vec3> p;
    for (int i = 0; i < 8; ++i)
        p.emplace_back((i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z);
    std::vector<std::uint32_t> idx = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                      2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    return add_mesh(add_positions(p), add_indices(idx, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT), material);
}

int GltfBuilder::add_sphere_mesh(double radius, int stacks, int slices, int material, bool inward, bool smooth_normals)
{
    std::vector<glm::vec3> p;
    for (int i = 0; i <= stacks; ++i) {
        double theta = std::numbers::pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            double phi = 2.0 * std::numbers::pi * j / slices;
            p.emplace_back(
                glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)) * radius);
        }
    }
    std::vector<std::uint32_t> idx;
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * slices + (j % slices)); };
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            // Outward-facing (counter-clockwise seen from outside) unless inward.
            std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            std::uint32_t tri[6] = {a, c, b, a, d, c};
            if (inward)
                std::swap(tri[1], tri[2]), std::swap(tri[4], tri[5]);
            // The pole rows collapse to a point: skip their zero-area triangles.
            if (i != stacks - 1)
                idx.insert(idx.end(), tri, tri + 3);
            if (i != 0)
                idx.insert(idx.end(), tri + 3, tri + 6);
        }
    int pos = add_positions(p);
    int ind = add_indices(idx, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    if (!smooth_normals)
        return add_mesh(pos, ind, material);
    std::vector<glm::vec3> n;
    for (const glm::vec3& v : p)
        n.push_back(glm::normalize(v) * (inward ? -1.0f : 1.0f));
    return add_mesh(pos, ind, material, 4, add_normals(n));
}

namespace {

void append_png_bytes(png_structp png, png_bytep data, png_size_t size)
{
    auto* bytes = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
    bytes->insert(bytes->end(), data, data + size);
}

// An RGBA PNG of 8 or 16 bits a channel, as stored (alpha unassociated), by libpng: a
// writer independent of the image module that decodes it.
template <typename T>
std::vector<unsigned char> encode_png(int width, int height, const std::vector<T>& rgba)
{
    constexpr int bits = 8 * sizeof(T);
    if (rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)
        throw std::runtime_error("a test PNG's pixels do not match its size");
    std::vector<unsigned char> bytes;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw std::runtime_error("cannot encode a test PNG");
    }
    png_set_write_fn(png, &bytes, append_png_bytes, nullptr);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), bits,
                 PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    if (bits == 16 && std::endian::native == std::endian::little)
        png_set_swap(png); // PNG stores 16-bit values big-endian
    for (int y = 0; y < height; ++y)
        png_write_row(png, reinterpret_cast<png_const_bytep>(rgba.data() + static_cast<std::size_t>(y) * width * 4));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return bytes;
}

} // namespace

int GltfBuilder::add_image_bytes(const std::vector<unsigned char>& bytes, const std::string& mime_type)
{
    tinygltf::Image img;
    img.bufferView = add_view(bytes.data(), bytes.size());
    img.mimeType = mime_type;
    model.images.push_back(img);
    return static_cast<int>(model.images.size()) - 1;
}

int GltfBuilder::add_png_image(int width, int height, const std::vector<std::uint8_t>& rgba8)
{
    return add_image_bytes(encode_png(width, height, rgba8), "image/png");
}

int GltfBuilder::add_png_image16(int width, int height, const std::vector<std::uint16_t>& rgba16)
{
    return add_image_bytes(encode_png(width, height, rgba16), "image/png");
}

int GltfBuilder::add_sampler(int mag_filter, int wrap_s, int wrap_t)
{
    tinygltf::Sampler s;
    s.magFilter = mag_filter;
    s.wrapS = wrap_s;
    s.wrapT = wrap_t;
    model.samplers.push_back(s);
    return static_cast<int>(model.samplers.size()) - 1;
}

int GltfBuilder::add_texture(int image, int sampler)
{
    tinygltf::Texture t;
    t.source = image;
    t.sampler = sampler;
    model.textures.push_back(t);
    return static_cast<int>(model.textures.size()) - 1;
}

int GltfBuilder::add_texcoords(const std::vector<glm::vec2>& uv)
{
    int view = add_view(uv.data(), uv.size() * sizeof(glm::vec2));
    return add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, uv.size());
}

int GltfBuilder::add_tangents(const std::vector<glm::vec4>& t)
{
    int view = add_view(t.data(), t.size() * sizeof(glm::vec4));
    return add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, t.size());
}

void GltfBuilder::set_attribute(int mesh, const std::string& name, int accessor)
{
    model.meshes[static_cast<std::size_t>(mesh)].primitives[0].attributes[name] = accessor;
}

void set_clearcoat(tinygltf::Material& m, double factor, double roughness)
{
    tinygltf::Value::Object o;
    o["clearcoatFactor"] = tinygltf::Value(factor);
    o["clearcoatRoughnessFactor"] = tinygltf::Value(roughness);
    m.extensions["KHR_materials_clearcoat"] = tinygltf::Value(o);
}

void set_sheen(tinygltf::Material& m, const std::vector<double>& color, double roughness)
{
    tinygltf::Value::Object o;
    o["sheenColorFactor"] = json_numbers(color);
    o["sheenRoughnessFactor"] = tinygltf::Value(roughness);
    m.extensions["KHR_materials_sheen"] = tinygltf::Value(o);
}

void set_anisotropy(tinygltf::Material& m, double strength, double rotation)
{
    tinygltf::Value::Object o;
    o["anisotropyStrength"] = tinygltf::Value(strength);
    o["anisotropyRotation"] = tinygltf::Value(rotation);
    m.extensions["KHR_materials_anisotropy"] = tinygltf::Value(o);
}

} // namespace pathcl::test
