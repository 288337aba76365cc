#include "render/textures.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"

namespace pathcl {
namespace {

pcl_uint wrap_mode(TextureWrap w)
{
    switch (w) {
    case TextureWrap::ClampToEdge:
        return TEXTURE_WRAP_CLAMP_TO_EDGE;
    case TextureWrap::MirroredRepeat:
        return TEXTURE_WRAP_MIRRORED_REPEAT;
    default:
        return TEXTURE_WRAP_REPEAT;
    }
}

bool same_view(const TextureView& a, const TextureView& b)
{
    auto same4 = [](const pcl_float4& x, const pcl_float4& y) {
        return x.x == y.x && x.y == y.y && x.z == y.z && x.w == y.w;
    };
    return same4(a.transform_u, b.transform_u) && same4(a.transform_v, b.transform_v) && a.image == b.image &&
           a.texcoord_base == b.texcoord_base && a.wrap_s == b.wrap_s && a.wrap_t == b.wrap_t && a.flags == b.flags;
}

// Texel index i wrapped into [0, n), as kernels/textures.cl wraps it.
std::int64_t wrap_index(std::int64_t i, std::int64_t n, TextureWrap mode)
{
    if (mode == TextureWrap::Repeat)
        return ((i % n) + n) % n;
    if (mode == TextureWrap::MirroredRepeat) {
        std::int64_t r = ((i % (2 * n)) + 2 * n) % (2 * n);
        return r < n ? r : 2 * n - 1 - r;
    }
    return std::clamp<std::int64_t>(i, 0, n - 1);
}

double srgb_to_linear(double c)
{
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

} // namespace

float srgb8_to_linear(std::uint8_t value)
{
    return static_cast<float>(srgb_to_linear(value / 255.0));
}

glm::vec4 texture_value_nearest(const SceneImage& image, const SceneTexture& texture, bool srgb, glm::vec2 uv)
{
    glm::dvec3 p(uv.x, uv.y, 1.0);
    double u = glm::dot(glm::dvec3(texture.transform_u), p), v = glm::dot(glm::dvec3(texture.transform_v), p);
    auto index = [](double c, std::uint32_t n) {
        double x = std::isfinite(c) ? std::clamp(std::floor(c * n), -1e15, 1e15) : 0.0;
        return static_cast<std::int64_t>(x);
    };
    std::size_t x = static_cast<std::size_t>(wrap_index(index(u, image.width), image.width, texture.wrap_s));
    std::size_t y = static_cast<std::size_t>(wrap_index(index(v, image.height), image.height, texture.wrap_t));
    std::size_t base = (y * image.width + x) * 4;
    glm::vec4 out;
    for (int c = 0; c < 4; ++c) {
        bool decode = srgb && c < 3;
        if (image.bits == 16) {
            double value = image.rgba16[base + static_cast<std::size_t>(c)] / 65535.0;
            out[c] = static_cast<float>(decode ? srgb_to_linear(value) : value);
        } else {
            std::uint8_t value = image.rgba8[base + static_cast<std::size_t>(c)];
            out[c] = decode ? srgb8_to_linear(value) : static_cast<float>(value / 255.0);
        }
    }
    return out;
}

glm::dvec3 texture_mean_over_triangle(const SceneImage& image, const SceneTexture& texture, bool srgb,
                                      const TriangleUv& uv)
{
    const int n = 8;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            // Cell centres of an n x n grid, warped to the triangle uniformly by area.
            double su = std::sqrt((i + 0.5) / n), b1 = 1.0 - su, b2 = (j + 0.5) / n * su, b0 = 1.0 - b1 - b2;
            glm::dvec2 p = b0 * glm::dvec2(uv[0]) + b1 * glm::dvec2(uv[1]) + b2 * glm::dvec2(uv[2]);
            sum += glm::dvec3(glm::vec3(texture_value_nearest(image, texture, srgb, glm::vec2(p))));
        }
    return sum / double(n * n);
}

DeviceTextures pack_textures(const Scene& scene, const std::vector<std::uint32_t>& leaf_order,
                             std::vector<Material>& materials)
{
    DeviceTextures dt;
    for (const SceneImage& img : scene.images) {
        TextureImage ti{};
        ti.offset = static_cast<pcl_uint>(dt.texels.size());
        ti.width = img.width;
        ti.height = img.height;
        std::size_t texels = static_cast<std::size_t>(img.width) * img.height;
        std::size_t words = texels * (img.bits == 16 ? 2 : 1);
        if (dt.texels.size() + words > std::numeric_limits<pcl_uint>::max())
            throw Error(img.name + ": the scene's textures exceed 16 GiB of texels (the device buffer's limit) at "
                                   "this image");
        if (img.bits == 16) {
            ti.format = TEXTURE_FORMAT_RGBA16;
            for (std::size_t i = 0; i < texels; ++i) {
                const std::uint16_t* c = &img.rgba16[i * 4];
                dt.texels.push_back(static_cast<pcl_uint>(c[0]) | static_cast<pcl_uint>(c[1]) << 16);
                dt.texels.push_back(static_cast<pcl_uint>(c[2]) | static_cast<pcl_uint>(c[3]) << 16);
            }
        } else {
            ti.format = TEXTURE_FORMAT_RGBA8;
            for (std::size_t i = 0; i < texels; ++i) {
                const std::uint8_t* c = &img.rgba8[i * 4];
                dt.texels.push_back(static_cast<pcl_uint>(c[0]) | static_cast<pcl_uint>(c[1]) << 8 |
                                    static_cast<pcl_uint>(c[2]) << 16 | static_cast<pcl_uint>(c[3]) << 24);
            }
        }
        dt.images.push_back(ti);
    }

    // Texture-coordinate sets the scene carries, each a block of leaf-ordered triangles.
    const std::size_t n = leaf_order.size();
    std::vector<pcl_uint> set_base(scene.texcoords.size(), 0);
    for (std::size_t set = 0; set < scene.texcoords.size(); ++set) {
        if (scene.texcoords[set].empty())
            continue;
        set_base[set] = static_cast<pcl_uint>(dt.texcoords.size());
        for (std::size_t i = 0; i < n; ++i) {
            const TriangleUv& uv = scene.texcoords[set][leaf_order[i]];
            dt.texcoords.push_back({{uv[0].x, uv[0].y, uv[1].x, uv[1].y}, {uv[2].x, uv[2].y, 0.0f, 0.0f}});
        }
    }

    auto view_of = [&](const SceneTexture& t, bool srgb) -> pcl_int {
        if (!t.present())
            return TEXTURE_NONE;
        TextureView v{};
        v.transform_u = {t.transform_u.x, t.transform_u.y, t.transform_u.z, 0.0f};
        v.transform_v = {t.transform_v.x, t.transform_v.y, t.transform_v.z, 0.0f};
        v.image = t.image;
        v.texcoord_base = set_base.at(static_cast<std::size_t>(t.texcoord));
        v.wrap_s = wrap_mode(t.wrap_s);
        v.wrap_t = wrap_mode(t.wrap_t);
        v.flags = (srgb ? TEXTURE_SRGB : 0u) | (t.nearest ? TEXTURE_NEAREST : 0u);
        for (std::size_t i = 0; i < dt.views.size(); ++i)
            if (same_view(dt.views[i], v))
                return static_cast<pcl_int>(i);
        dt.views.push_back(v);
        return static_cast<pcl_int>(dt.views.size() - 1);
    };
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const SceneMaterial& sm = scene.materials[i];
        Material& m = materials[i];
        m.base_color_texture = view_of(sm.base_color_texture, true);
        m.metallic_roughness_texture = view_of(sm.metallic_roughness_texture, false);
        m.emissive_texture = view_of(sm.emissive_texture, true);
        m.normal_texture = view_of(sm.normal_texture, false);
        m.specular_texture = view_of(sm.specular_texture, false);
        m.specular_color_texture = view_of(sm.specular_color_texture, true);
        m.transmission_texture = view_of(sm.transmission_texture, false);
    }
    return dt;
}

} // namespace pathcl
