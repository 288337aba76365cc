// The samplers of kernels/sample/sampler.cl seen from the host: their names, how each
// rounds the sample count, and a way to read a sampler's points back from the device (for
// the visualizer and the tests).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cl/cl_runtime.h"
#include "types.h"

namespace pathcl {

// The samplers (FrameParams.sampler: the SAMPLER_* values of kernels/types.h).
enum class SamplerType : std::uint32_t {
    Independent = SAMPLER_INDEPENDENT,
    Jittered = SAMPLER_JITTERED,
    MultiJittered = SAMPLER_MULTI_JITTERED,
    NRooks = SAMPLER_N_ROOKS,
    Sobol = SAMPLER_SOBOL,
    Halton = SAMPLER_HALTON,
    Hammersley = SAMPLER_HAMMERSLEY,
};

// Every sampler by name ("independent", "multi-jittered", ...).
const std::map<std::string, SamplerType>& sampler_names();

// The name of a sampler; throws pathcl::Error for a value that names none.
std::string sampler_name(SamplerType sampler);

// The samples per pixel a render with `sampler` takes when `requested` are asked for:
// jittered and multi-jittered round up to the next square (sqrt(spp) x sqrt(spp) strata,
// one sample each), hammersley to the next power of two (a (0,m,2)-net); the others take
// `requested` as it is.
std::uint32_t sampler_spp(SamplerType sampler, std::uint32_t requested);

// Stratified samplers draw their sets on a grid of cols x rows strata (jittered,
// multi-jittered: the 2D grid; n-rooks: spp x spp rows and columns).
struct StrataGrid {
    std::uint32_t cols = 0, rows = 0; // 0: no strata (independent, halton)
    std::uint32_t fine = 0;           // multi-jittered: spp fine columns and rows as well
};
StrataGrid sampler_strata(SamplerType sampler, std::uint32_t spp);

struct SamplerPointsRequest {
    SamplerType sampler = SamplerType::Independent;
    std::uint32_t spp = 1; // the set size (after sampler_spp)
    std::uint32_t seed = 0;
    std::uint32_t dim0 = 0, dim1 = 1;  // dim1 == dim0 + 1: the 2D decision at dim0; else two 1D
    std::vector<std::uint32_t> pixels; // pixel indices (y * width + x in a render)
    std::uint32_t first_sample = 0;
    std::uint32_t count = 0; // samples per pixel to read (0: spp)
};

// Runs the kernel sampler_points of `program` (any program built from the kernel
// sources); result[p * count + k] is sample first_sample + k of pixels[p].
std::vector<glm::vec2> compute_sampler_points(const ClDevice& dev, const cl::Program& program,
                                              const SamplerPointsRequest& request);

} // namespace pathcl
