#include "scene/gltf_morph_targets.h"

#include <cmath>

#include <tiny_gltf.h>

#include "common/error.h"
#include "scene/gltf_accessor.h"

namespace pathcl {

MorphDeltas morph_deltas(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                         const std::vector<double>& weights, std::size_t vertex_count, bool quantized,
                         const std::string& source, const std::string& what)
{
    MorphDeltas d;
    if (prim.targets.empty())
        return d;
    if (!weights.empty() && weights.size() != prim.targets.size())
        throw Error(source + ": " + what + ": has " + std::to_string(prim.targets.size()) +
                    " morph targets but its weights number " + std::to_string(weights.size()));
    for (std::size_t k = 0; k < prim.targets.size(); ++k) {
        const double w = weights.empty() ? 0.0 : weights[k];
        if (!std::isfinite(w))
            throw Error(source + ": " + what + ": morph target weight " + std::to_string(k) + " is not finite");
        for (const auto& [attribute, accessor] : prim.targets[k]) {
            std::vector<glm::dvec3>* sum = attribute == "POSITION"  ? &d.position
                                           : attribute == "NORMAL"  ? &d.normal
                                           : attribute == "TANGENT" ? &d.tangent
                                                                    : nullptr;
            if (sum == nullptr) {
                ++d.ignored_attributes;
                continue;
            }
            // Read even at weight 0, so a broken target is an error whatever the weights.
            AccessorReader r(model, accessor, what + " morph target " + std::to_string(k) + " " + attribute, source);
            if (r.components() != 3 || r.count() != vertex_count)
                r.fail("a morph target must be VEC3 with one displacement per vertex");
            if (!r.is_float() && !quantized)
                r.fail("must be FLOAT (integer displacements need KHR_mesh_quantization)");
            if (w == 0.0)
                continue;
            sum->resize(vertex_count, glm::dvec3(0.0));
            for (std::size_t i = 0; i < vertex_count; ++i) {
                glm::dvec3 v(r.get(i, 0), r.get(i, 1), r.get(i, 2));
                if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                    r.fail("vertex " + std::to_string(i) + " has a NaN or infinite displacement");
                (*sum)[i] += w * v;
            }
        }
    }
    return d;
}

} // namespace pathcl
