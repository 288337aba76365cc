// Textures as the kernels read them (kernels/textures.cl): the texels of every image
// packed into one buffer of 32-bit words (RGBA8: 4 bytes per texel, RGBA16: 8), one
// TextureImage per image, one TextureView per distinct way a material slot samples an
// image (texture-coordinate set, wrap modes, filter, KHR_texture_transform, sRGB or
// linear), and the texture-coordinate sets those views read, per triangle in BVH leaf
// order. Plus the host-side lookups used to estimate the power of textured emitters.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "shared_types.h"

namespace pathcl {

struct DeviceTextures {
    std::vector<pcl_uint> texels;
    std::vector<TextureImage> images;
    std::vector<TextureView> views;
    std::vector<TriangleTexcoords> texcoords; // one block of triangle-count entries per set used

    std::size_t texel_bytes() const { return texels.size() * sizeof(pcl_uint); }
};

// Packs the scene's images and makes the views its materials' texture slots need; sets
// the texture fields of `materials` (the device copies of scene.materials, in the same
// order) to those views. `leaf_order[i]` is the scene triangle at BVH leaf position i.
// Throws pathcl::Error when the texels exceed what 32-bit word offsets can address.
DeviceTextures pack_textures(const Scene& scene, const std::vector<std::uint32_t>& leaf_order,
                             std::vector<Material>& materials);

// sRGB-encoded 8-bit value -> linear (IEC 61966-2-1), computed in double and rounded to
// float: the values the kernels' table holds.
float srgb8_to_linear(std::uint8_t value);

// The texture value (RGBA, linear) of slot `texture` at texture coordinate uv, by
// nearest-texel lookup after its transform and wrap modes (the kernels filter
// bilinearly where the sampler says so; this is for estimates).
glm::vec4 texture_value_nearest(const SceneImage& image, const SceneTexture& texture, bool srgb, glm::vec2 uv);

// Mean RGB of `texture` over a triangle with vertex coordinates uv: 64 stratified points,
// nearest-texel lookups. Estimates a textured emitter's power.
glm::dvec3 texture_mean_over_triangle(const SceneImage& image, const SceneTexture& texture, bool srgb,
                                      const TriangleUv& uv);

} // namespace pathcl
