// instance_transforms: the extension's attributes read through AccessorReader (bounds,
// types), every instance checked before any is used.
#include "scene/gltf_instancing.h"

#include <cmath>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

#include "common/error.h"
#include "scene/gltf_accessor.h"

namespace pathcl {

std::vector<glm::dmat4> instance_transforms(const tinygltf::Model& model, const tinygltf::Node& node,
                                            const glm::dmat4& node_world, bool quantized, const std::string& source,
                                            const std::string& what,
                                            const std::function<void(std::size_t)>& check_count)
{
    auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
    if (ext == node.extensions.end()) {
        check_count(1);
        return {node_world};
    }
    const std::string at = what + " EXT_mesh_gpu_instancing";
    const tinygltf::Value& attributes = ext->second.Get("attributes"); // tinygltf: {} is no object
    auto none = [&] { return Error(source + ": " + at + ": has none of TRANSLATION, ROTATION and SCALE"); };
    if (!attributes.IsObject())
        throw none();
    std::optional<std::size_t> count;
    // One attribute's reader, its type checked and its count the same as the others'.
    auto reader = [&](const char* name, int components, bool rotation) -> std::optional<AccessorReader> {
        if (!attributes.Has(name))
            return std::nullopt;
        const tinygltf::Value& index = attributes.Get(name);
        if (!index.IsInt())
            throw Error(source + ": " + at + ": " + name + " is not an accessor index");
        AccessorReader r(model, index.GetNumberAsInt(), at + " " + name, source);
        if (r.components() != components)
            r.fail(std::string("must be ") + (components == 3 ? "VEC3" : "VEC4"));
        if (rotation)
            r.require_float_or_normalized(); // the extension allows normalized bytes and shorts
        else if (!r.is_float() && !quantized)
            r.fail("must be FLOAT (integers need KHR_mesh_quantization)");
        if (count && r.count() != *count)
            r.fail("has " + std::to_string(r.count()) + " elements, another attribute " + std::to_string(*count));
        count = r.count();
        return r;
    };
    std::optional<AccessorReader> translation = reader("TRANSLATION", 3, false);
    std::optional<AccessorReader> rotation = reader("ROTATION", 4, true);
    std::optional<AccessorReader> scale = reader("SCALE", 3, false);
    if (!count)
        throw none();
    check_count(*count);
    std::vector<glm::dmat4> out(*count);
    for (std::size_t i = 0; i < *count; ++i) {
        glm::dmat4 m(1.0);
        if (translation)
            m = glm::translate(m, glm::dvec3(translation->get(i, 0), translation->get(i, 1), translation->get(i, 2)));
        if (rotation) {
            glm::dquat q(rotation->get(i, 3), rotation->get(i, 0), rotation->get(i, 1), rotation->get(i, 2));
            double len = glm::length(q);
            if (!(len > 0.0) || !std::isfinite(len))
                rotation->fail("instance " + std::to_string(i) + " is the zero quaternion or not finite");
            m = m * glm::mat4_cast(q / len);
        }
        if (scale)
            m = glm::scale(m, glm::dvec3(scale->get(i, 0), scale->get(i, 1), scale->get(i, 2)));
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(m[c][r]))
                    throw Error(source + ": " + at + ": instance " + std::to_string(i) +
                                " has a NaN or infinite value");
        out[i] = node_world * m;
    }
    return out;
}

} // namespace pathcl
