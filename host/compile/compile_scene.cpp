#include "compile/compile_scene.h"

#include <algorithm>
#include <chrono>

#include "common/elapsed.h"
#include "compile/light_distribution.h"
#include "compile/light_tree.h"

namespace pathcl {

CompiledScene compile_scene(const Scene& scene, const KernelFeatures& features, LightSampler light_sampler)
{
    CompiledScene out;
    out.features = features;
    std::vector<std::uint32_t> leaf_order = compile_geometry(scene, out);
    compile_materials(scene, features, out.arrays);
    if (features.has(FEATURE_TEXTURES))
        compile_textures(scene, leaf_order, out.arrays);
    std::vector<double> power = compile_lights(scene, leaf_order, out);
    if (light_sampler == LightSampler::Uniform)
        std::fill(power.begin(), power.end(), 1.0);
    out.arrays.light_distribution = build_light_distribution(power);
    if (features.has(FEATURE_LIGHT_TREE)) {
        const auto start = std::chrono::steady_clock::now();
        LightTree tree = build_light_tree(out.arrays.lights, power);
        out.light_tree_build_seconds = seconds_since(start);
        out.arrays.light_tree = std::move(tree.nodes);
        out.arrays.light_tree_cluster = std::move(tree.cluster);
        out.arrays.light_tree_trail = std::move(tree.trails);
        out.arrays.light_tree_infinite = std::move(tree.infinite);
        out.infinite_pick = tree.infinite_pick;
        out.light_tree_depth = tree.depth;
    }
    return out;
}

} // namespace pathcl
