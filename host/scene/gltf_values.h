// Optional fields of the free-form JSON objects of a glTF file (extension objects and
// extras), which tinygltf leaves untyped; shared by the material, light and environment
// importers, which each check the range of what they read.
#pragma once

#include <glm/glm.hpp>

namespace tinygltf {
class Value;
}

namespace pathcl {

// obj[key] as a number; `fallback` when obj is not an object or lacks the key. Anything
// but a number there gives NaN, which the caller's range check rejects: a value of the
// wrong type is an error, not the default.
double number_or(const tinygltf::Value& obj, const char* key, double fallback);

// obj[key] as three numbers; `fallback` when absent. A value that is not an array of
// three numbers gives NaN components, which the caller's range check rejects.
glm::vec3 vec3_or(const tinygltf::Value& obj, const char* key, glm::vec3 fallback);

// obj[key] as four numbers, like vec3_or.
glm::vec4 vec4_or(const tinygltf::Value& obj, const char* key, glm::vec4 fallback);

} // namespace pathcl
