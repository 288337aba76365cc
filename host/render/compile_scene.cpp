#include "render/compile_scene.h"

#include "render/light_distribution.h"

namespace pathcl {

CompiledScene compile_scene(const Scene& scene, const KernelFeatures& features)
{
    CompiledScene out;
    out.features = features;
    std::vector<std::uint32_t> leaf_order = compile_geometry(scene, out);
    compile_materials(scene, features, out.arrays);
    if (features.has(FEATURE_TEXTURES))
        compile_textures(scene, leaf_order, out.arrays);
    std::vector<double> power = compile_lights(scene, leaf_order, out);
    out.arrays.light_distribution = build_light_distribution(power);
    return out;
}

} // namespace pathcl
