// What the sampler tests share: the program over tests/kernels/sampler_test_kernels.cl,
// the points a sampler gives a range of pixels (through the kernel sampler_points the
// visualizer uses), and exact checks of their stratification.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "cl/cl_runtime.h"
#include "sampling/samplers.h"

namespace pathcl::test {

// The real kernel sources plus tests/kernels/sampler_test_kernels.cl, built once.
const cl::Program& sampler_program();

// Pixels first, first + 1, ..., first + n - 1.
std::vector<std::uint32_t> pixel_range(std::uint32_t first, std::uint32_t n);

// Points of `pixels`, spp each, for the 2D decision at dim (or two 1D decisions at dim
// and dim + 2 when one_d).
std::vector<glm::vec2> points(SamplerType sampler, std::uint32_t spp, const std::vector<std::uint32_t>& pixels,
                              std::uint32_t dim, bool one_d = false, std::uint32_t seed = 11);

// Every value in [0, 1), and each of the n strata of coordinate c holds exactly one of
// the set's n points.
::testing::AssertionResult one_per_stratum_1d(const glm::vec2* p, std::uint32_t n, int c);

// Each of the cols x rows cells holds exactly spp / (cols * rows) points (one for a
// full grid).
::testing::AssertionResult one_per_cell(const glm::vec2* p, std::uint32_t n, std::uint32_t cols, std::uint32_t rows);

} // namespace pathcl::test
