// Textures for the device (kernels/texture/lookup.cl): the texels of every image packed
// into one buffer of 32-bit words (RGBA8: 4 bytes per texel, RGBA16: 8), one TextureImage
// per image, one TextureView per distinct way a material slot samples an image
// (texture-coordinate set, wrap modes, filter, KHR_texture_transform, sRGB or linear),
// and the texture-coordinate sets those views read, per triangle in BVH leaf order.
#include <limits>

#include "common/error.h"
#include "common/memory_limits.h"
#include "compile/compile_scene.h"
#include "compile/texture_lookup.h"
#include "scene/texture_slots.h"

namespace pathcl {
namespace {

bool same_view(const TextureView& a, const TextureView& b)
{
    auto same4 = [](const pcl_float4& x, const pcl_float4& y) {
        return x.x == y.x && x.y == y.y && x.z == y.z && x.w == y.w;
    };
    return same4(a.transform_u, b.transform_u) && same4(a.transform_v, b.transform_v) && a.image == b.image &&
           a.texcoord_base == b.texcoord_base && a.wrap_s == b.wrap_s && a.wrap_t == b.wrap_t && a.flags == b.flags;
}

void pack_images(const Scene& scene, SceneArrays& a)
{
    // Allocated once: grown image by image, the buffer would be copied at each doubling.
    std::size_t total = 0;
    for (const SceneImage& img : scene.images)
        total += static_cast<std::size_t>(img.width) * img.height * (img.bits == 16 ? 2 : 1);
    check_memory_for(static_cast<double>(total) * sizeof(pcl_uint), "packing the scene's textures");
    a.texels.reserve(a.texels.size() + total);
    for (const SceneImage& img : scene.images) {
        TextureImage ti{};
        ti.offset = static_cast<pcl_uint>(a.texels.size());
        ti.width = img.width;
        ti.height = img.height;
        std::size_t texels = static_cast<std::size_t>(img.width) * img.height;
        std::size_t words = texels * (img.bits == 16 ? 2 : 1);
        if (a.texels.size() + words > std::numeric_limits<pcl_uint>::max())
            throw Error(img.name + ": the scene's textures exceed 16 GiB of texels (the device buffer's limit) at "
                                   "this image");
        if (img.bits == 16) {
            ti.format = TEXTURE_FORMAT_RGBA16;
            for (std::size_t i = 0; i < texels; ++i) {
                const std::uint16_t* c = &img.rgba16[i * 4];
                a.texels.push_back(static_cast<pcl_uint>(c[0]) | static_cast<pcl_uint>(c[1]) << 16);
                a.texels.push_back(static_cast<pcl_uint>(c[2]) | static_cast<pcl_uint>(c[3]) << 16);
            }
        } else {
            ti.format = TEXTURE_FORMAT_RGBA8;
            for (std::size_t i = 0; i < texels; ++i) {
                const std::uint8_t* c = &img.rgba8[i * 4];
                a.texels.push_back(static_cast<pcl_uint>(c[0]) | static_cast<pcl_uint>(c[1]) << 8 |
                                   static_cast<pcl_uint>(c[2]) << 16 | static_cast<pcl_uint>(c[3]) << 24);
            }
        }
        a.texture_images.push_back(ti);
    }
}

} // namespace

void compile_textures(const Scene& scene, const std::vector<std::uint32_t>& leaf_order, SceneArrays& a)
{
    pack_images(scene, a);

    // Texture-coordinate sets the scene carries, each a block of leaf-ordered triangles.
    const std::size_t n = leaf_order.size();
    std::vector<pcl_uint> set_base(scene.texcoords.size(), 0);
    for (std::size_t set = 0; set < scene.texcoords.size(); ++set) {
        if (scene.texcoords[set].empty())
            continue;
        set_base[set] = static_cast<pcl_uint>(a.texcoords.size());
        for (std::size_t i = 0; i < n; ++i) {
            const TriangleUv& uv = scene.texcoords[set][leaf_order[i]];
            a.texcoords.push_back({{uv[0].x, uv[0].y, uv[1].x, uv[1].y}, {uv[2].x, uv[2].y, 0.0f, 0.0f}});
        }
    }

    auto view_of = [&](const SceneTexture& t, bool srgb) -> pcl_int {
        if (!t.present())
            return TEXTURE_NONE;
        TextureView v{};
        v.transform_u = to_float4(t.transform_u);
        v.transform_v = to_float4(t.transform_v);
        v.image = t.image;
        v.texcoord_base = set_base.at(static_cast<std::size_t>(t.texcoord));
        v.wrap_s = texture_wrap_mode(t.wrap_s);
        v.wrap_t = texture_wrap_mode(t.wrap_t);
        v.flags = (srgb ? TEXTURE_SRGB : 0u) | (t.nearest ? TEXTURE_NEAREST : 0u);
        for (std::size_t i = 0; i < a.texture_views.size(); ++i)
            if (same_view(a.texture_views[i], v))
                return static_cast<pcl_int>(i);
        a.texture_views.push_back(v);
        return static_cast<pcl_int>(a.texture_views.size() - 1);
    };
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        for (const TextureSlot& ts : texture_slot_table())
            a.materials[i].textures[ts.slot] =
                view_of(scene.materials[i].textures[static_cast<std::size_t>(ts.slot)], ts.srgb);
    }
}

} // namespace pathcl
