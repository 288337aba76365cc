// The light tree (--light-sampler tree): a binary tree over every light's bounds (box,
// power, the cone of directions it emits along), built on the host and descended on the
// device, where each step picks a child in proportion to its importance at the shading
// point (kernels/light/light_tree.cl; Conty Estevez and Kulla 2018). Infinite lights
// (directional, environment) have no bounds: they stay out of the tree and are picked
// beside it, with a probability in proportion to their share of the power.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "common/default_init_allocator.h"
#include "render/render_options.h"
#include "scene/scene.h"
#include "types.h"

namespace pathcl {

// The directions a light emits along: within theta_o of `axis` (cos_o; -1: every
// direction), and spreading theta_e past that cone (cos_e; 0 for a Lambertian surface).
struct LightCone {
    glm::dvec3 axis{0.0, 0.0, 1.0};
    double cos_o = -1.0;
    double cos_e = 0.0;
};

struct LightBounds {
    bool infinite = false; // directional or environment: no bounds, picked beside the tree
    glm::dvec3 lo{0.0}, hi{0.0};
    double phi = 0.0; // power (W of luminance), as the power table weighs lights
    LightCone cone;
    bool two_sided = false;
};

// The smallest cone (up to the method's slack) that holds both.
LightCone cone_union(const LightCone& a, const LightCone& b);

struct LightTree {
    UninitializedVector<LightTreeNode> nodes;   // depth-first, root first; empty when every light is infinite
    std::vector<pcl_ulong> trails;              // per light: bit k = the child taken at depth k (1: the second); all
                                                // ones for an infinite light
    std::vector<LightTreeClusterLight> cluster; // the cluster leaves: each a header and then its lights
    std::vector<pcl_int> infinite;              // the infinite lights
    double infinite_pick = 0.0;                 // the probability of picking one of them
    std::uint32_t depth = 0;                    // the number of levels of eight-wide nodes
};

// Builds the tree by the surface area orientation heuristic (the paper's SAOH: binned
// along the longest axis of the lights' centroids, power x orientation measure x box
// area; ranges of at most eight lights by power x box area alone), one light per leaf of
// the binary tree; in the eight-wide one, a few neighbouring lights of one surface that face
// nearly one way may share a leaf (a cluster). Throws pathcl::Error if a light's bounds
// are not finite, or if there are more lights than a leaf can index (2^28).
LightTree build_light_tree(const std::vector<LightBounds>& lights);

// The same over the light records themselves (what the kernels sample) and each light's
// power (compile_lights): each light's bounds are made from its record as the build reads
// it, on every core, rather than kept for every light first.
LightTree build_light_tree(const std::vector<Light>& lights, const std::vector<double>& power);

// The light sampler a render takes: the one the options ask for, or for Auto the light
// tree where the scene has at least three lights with a position (emissive triangles,
// point, spot and sphere lights) spread over at least a quarter of the scene's diagonal,
// and the power table elsewhere (and always with the wavefront, whose stages have no
// tree). Measured (docs/accuracy.md, "Light samplers"): the tree gains 1.5-5.7x where
// lamps light different rooms and 4.2-5.0x on a glowing sphere of a hundred thousand
// triangles, and loses 17-32 % on one area light.
LightSampler resolve_light_sampler(const Scene& scene, const RenderOptions& options);

} // namespace pathcl
