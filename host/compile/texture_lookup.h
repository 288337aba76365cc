// Texture lookups on the host, for estimates the compile stage needs before the kernels
// run (a textured emitter's power): nearest-texel reads through the same wrap and sRGB
// formulas the kernels use (kernels/texture/wrap.h, srgb.h), in double.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "types.h"

namespace pathcl {

// sRGB-encoded 8-bit value -> linear, computed in double and rounded to float: the values
// the kernels' table (kernels/texture/lookup.cl) holds.
float srgb8_to_linear(std::uint8_t value);

// The texture value (RGBA, linear) of slot `texture` at texture coordinate uv, by
// nearest-texel lookup after its transform and wrap modes (the kernels filter
// bilinearly where the sampler says so; this is for estimates).
glm::vec4 texture_value_nearest(const SceneImage& image, const SceneTexture& texture, bool srgb, glm::vec2 uv);

// Mean RGB of `texture` over a triangle with vertex coordinates uv: 64 stratified points,
// nearest-texel lookups. Estimates a textured emitter's power.
glm::dvec3 texture_mean_over_triangle(const SceneImage& image, const SceneTexture& texture, bool srgb,
                                      const TriangleUv& uv);

// The TEXTURE_WRAP_* value of a wrap mode.
pcl_uint texture_wrap_mode(TextureWrap w);

} // namespace pathcl
