// number_or, vec3_or and vec4_or. A malformed value is not quietly replaced by its default: NaN
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

namespace {

// obj[key] as N numbers (see vec3_or).
template <int N>
glm::vec<N, float> numbers_or(const tinygltf::Value& obj, const char* key, glm::vec<N, float> fallback)
{
    if (!obj.IsObject() || !obj.Has(key))
        return fallback;
    const tinygltf::Value& v = obj.Get(key);
    if (!v.IsArray() || v.ArrayLen() != N)
        return glm::vec<N, float>(std::numeric_limits<float>::quiet_NaN()); // rejected by the range check
    glm::vec<N, float> out;
    for (int i = 0; i < N; ++i)
        out[i] = v.Get(i).IsNumber() ? static_cast<float>(v.Get(i).GetNumberAsDouble())
                                     : std::numeric_limits<float>::quiet_NaN();
    return out;
}

} // namespace

glm::vec3 vec3_or(const tinygltf::Value& obj, const char* key, glm::vec3 fallback)
{
    return numbers_or<3>(obj, key, fallback);
}

glm::vec4 vec4_or(const tinygltf::Value& obj, const char* key, glm::vec4 fallback)
{
    return numbers_or<4>(obj, key, fallback);
}

} // namespace pathcl
