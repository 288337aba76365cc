// number_or and vec3_or. A malformed value is not quietly replaced by its default: NaN
// makes the caller's range check name the field instead.
#include "scene/gltf_values.h"

#include <limits>

#include <tiny_gltf.h>

namespace pathcl {

double number_or(const tinygltf::Value& obj, const char* key, double fallback)
{
    if (!obj.IsObject() || !obj.Has(key))
        return fallback;
    const tinygltf::Value& v = obj.Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : std::numeric_limits<double>::quiet_NaN();
}

glm::vec3 vec3_or(const tinygltf::Value& obj, const char* key, glm::vec3 fallback)
{
    if (!obj.IsObject() || !obj.Has(key))
        return fallback;
    const tinygltf::Value& v = obj.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 3)
        return glm::vec3(std::numeric_limits<float>::quiet_NaN()); // rejected by the range check
    glm::vec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = v.Get(i).IsNumber() ? static_cast<float>(v.Get(i).GetNumberAsDouble())
                                     : std::numeric_limits<float>::quiet_NaN();
    return out;
}

} // namespace pathcl
