// The host half of the shared-struct contract: sizes and offsets the kernels rely on
// (kernels/types.h). A mismatch is a compile error, not a corrupted render.
#include <cstddef>

#include "types.h"

namespace pathcl {

static_assert(sizeof(pcl_float4) == 16 && alignof(pcl_float4) == 16);
static_assert(sizeof(Ray) == 32);
static_assert(sizeof(BvhNode) == 256 && offsetof(BvhNode, index) == 192 && offsetof(BvhNode, count) == 224);
static_assert(sizeof(Triangle) == 48);
static_assert(sizeof(TriangleBlock) == 320 && offsetof(TriangleBlock, triangle) == 288);
static_assert(sizeof(Instance) == 112 && offsetof(Instance, to_render) == 48 && offsetof(Instance, root) == 96);
static_assert(sizeof(TriangleShading) == 64 && offsetof(TriangleShading, material) == 48);
static_assert(sizeof(TriangleTexcoords) == 32 && offsetof(TriangleTexcoords, uv2) == 16);
static_assert(sizeof(TriangleTangents) == 48);
static_assert(sizeof(TriangleColors) == 48);
static_assert(sizeof(TextureImage) == 16 && offsetof(TextureImage, format) == 12);
static_assert(sizeof(TextureView) == 64 && offsetof(TextureView, image) == 32 && offsetof(TextureView, flags) == 48);
static_assert(sizeof(Material) == 192 && offsetof(Material, absorption) == 48 && offsetof(Material, metallic) == 64 &&
              offsetof(Material, textures) == 88 && offsetof(Material, smooth_layer_average) == 140 &&
              offsetof(Material, alpha_cutoff) == 144 && offsetof(Material, clearcoat) == 148 &&
              offsetof(Material, clearcoat_roughness) == 152 && offsetof(Material, clearcoat_normal_scale) == 156 &&
              offsetof(Material, sheen) == 160 && offsetof(Material, anisotropy) == 176);
static_assert(sizeof(TriangleLight) == 64 && offsetof(TriangleLight, area) == 48 &&
              offsetof(TriangleLight, texture) == 56);
static_assert(sizeof(PointLight) == 16 && sizeof(DirectionalLight) == 16 && sizeof(EnvironmentLight) == 16);
static_assert(sizeof(SpotLight) == 48 && offsetof(SpotLight, cos_outer) == 32);
static_assert(sizeof(RectSpotLight) == 64 && offsetof(RectSpotLight, tan_half_h) == 48);
static_assert(sizeof(SphereLight) == 32 && offsetof(SphereLight, radius) == 16);
static_assert(sizeof(Light) == 96 && offsetof(Light, radiance) == 64 && offsetof(Light, type) == 80 &&
              offsetof(Light, leaf_node) == 84 && offsetof(Light, leaf_block) == 88);
static_assert(sizeof(LightAliasEntry) == 16 && offsetof(LightAliasEntry, alias) == 8);
static_assert(sizeof(LightTreeNode) == 512 && offsetof(LightTreeNode, phi) == 128 &&
              offsetof(LightTreeNode, cos_e) == 320 && offsetof(LightTreeNode, mean_axis_across) == 384 &&
              offsetof(LightTreeNode, child) == 416 && offsetof(LightTreeNode, two_sided) == 448 &&
              offsetof(LightTreeNode, code) == 480);
static_assert(sizeof(LightTreeClusterLight) == 16 && offsetof(LightTreeClusterLight, keep) == 8 &&
              offsetof(LightTreeClusterLight, alias) == 12);
static_assert(sizeof(Camera) == 80 && offsetof(Camera, type) == 64 && offsetof(Camera, lens_radius) == 68 &&
              offsetof(Camera, focus_distance) == 72);
static_assert(sizeof(FrameParams) == 64 && offsetof(FrameParams, sampler) == 36 && offsetof(FrameParams, spp) == 40 &&
              offsetof(FrameParams, adaptive) == 48 && offsetof(FrameParams, first_row) == 52 &&
              offsetof(FrameParams, infinite_pick) == 56 && offsetof(FrameParams, infinite_count) == 60);
static_assert(sizeof(FilmPixel) == 64);

} // namespace pathcl
