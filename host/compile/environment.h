// Environment maps: the equirectangular texels (radiance x strength) and the 2D
// piecewise-constant distribution that importance-samples them in proportion to
// luminance x sin(theta), as docs/gltf.md defines the mapping. Layout for the
// device (kernels/light/environment.cl): texels row-major from the top row; the marginal CDF
// over rows (height + 1 floats); one conditional CDF per row (height x (width + 1)).
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "types.h"

namespace pathcl {

struct EnvironmentMap {
    std::uint32_t width = 0, height = 0;
    std::vector<pcl_float4> texels;
    std::vector<float> marginal_cdf, conditional_cdf;
    double average_radiance = 0.0; // luminance, solid-angle weighted
};

// The map of the scene's environment (its image, or a constant 1x1 map) times its
// strength, with its sampling distribution; throws pathcl::Error naming the file for a
// negative, NaN or infinite texel.
EnvironmentMap build_environment_map(const SceneEnvironment& env);

// Builds the sampling distribution of an already filled map.
void build_environment_distribution(EnvironmentMap& map);

} // namespace pathcl
