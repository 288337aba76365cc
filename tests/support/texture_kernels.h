// What the device texture tests share: the program over tests/kernels/texture_test_kernels.cl
// with every texture feature, the float4 read-back its kernels need, and the value the
// kernels give an 8-bit texel (to compare lookups and light samples with).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "cl/cl_runtime.h"
#include "features.h"
#include "types.h"

namespace pathcl::test {

inline constexpr std::uint32_t kTextureFeatures = FEATURE_TEXTURES | FEATURE_NORMAL_MAPS | FEATURE_VERTEX_COLORS |
                                                  FEATURE_CLEARCOAT | FEATURE_SHEEN | FEATURE_ANISOTROPY;

// Built once, with kTextureFeatures.
const cl::Program& texture_program();

// The first n float4 results in `b` (device_fixture.h's read_back<pcl_float4>).
std::vector<pcl_float4> read_back(const cl::Buffer& b, std::size_t n);

// The value kernels/texture/lookup.cl gives an 8-bit channel: linear byte * (1 / 255), or the sRGB table.
glm::vec4 texel8(const std::uint8_t* c, bool srgb);

} // namespace pathcl::test
