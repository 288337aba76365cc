// Small glTF models built in code for the import tests (the tilted triangle, the unit quad,
// one triangle under a TRS node), the loader's render-space result moved back into world
// space, and the double-precision helpers the expectations are written with.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "support/gltf_builder.h"

namespace pathcl::test {

// The loader returns render space (positions relative to render_origin, the camera);
// these tests state their expectations in world space.
inline Scene in_world_space(Scene s)
{
    for (std::size_t i = 0; i < s.render_space_triangles(); ++i) // (instanced meshes are in their own space)
        for (glm::vec3& v : s.triangles[i].v)
            v = glm::vec3(glm::dvec3(v) + s.render_origin);
    for (SceneInstance& i : s.instances)
        i.to_render = glm::translate(glm::dmat4(1.0), s.render_origin) * i.to_render;
    s.camera.position += s.render_origin;
    s.render_origin = glm::dvec3(0.0);
    return s;
}

inline Scene import(const GltfBuilder& b, const std::string& source = "test.gltf", const SceneChoice& choice = {})
{
    return in_world_space(import_gltf(b.model, source, "", choice));
}

// The same with every mesh copied per drawing (SceneChoice::copy_instances).
inline Scene import_copies(const GltfBuilder& b, const std::string& source = "test.gltf")
{
    SceneChoice copies;
    copies.copy_instances = true;
    return import(b, source, copies);
}

inline glm::dvec3 d3(const glm::vec3& v)
{
    return glm::dvec3(v);
}

// |a - b| <= rel * max(1, |b|), componentwise on the vector length.
inline bool near_rel(const glm::dvec3& a, const glm::dvec3& b, double rel)
{
    return glm::length(a - b) <= rel * std::max(1.0, glm::length(b));
}

inline std::string str(const glm::dvec3& v)
{
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

// Axis-angle rotation written out (Rodrigues), independent of glm's quaternion code.
inline glm::dmat3 rodrigues(glm::dvec3 axis, double angle)
{
    axis = glm::normalize(axis);
    glm::dmat3 k(0.0); // cross-product matrix [axis]x, by columns
    k[0] = glm::dvec3(0.0, axis.z, -axis.y);
    k[1] = glm::dvec3(-axis.z, 0.0, axis.x);
    k[2] = glm::dvec3(axis.y, -axis.x, 0.0);
    return glm::dmat3(1.0) + std::sin(angle) * k + (1.0 - std::cos(angle)) * (k * k);
}

// The glTF quaternion [x, y, z, w] of the same rotation.
inline std::vector<double> quaternion(glm::dvec3 axis, double angle)
{
    axis = glm::normalize(axis);
    double s = std::sin(0.5 * angle);
    return {axis.x * s, axis.y * s, axis.z * s, std::cos(0.5 * angle)};
}

// One triangle (1,0,0), (0,2,0), (0,0,3): its counter-clockwise normal is (6,3,2)/7.
inline const std::vector<glm::vec3> kTilted = {{1.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, {0.0f, 0.0f, 3.0f}};
inline const glm::dvec3 kTiltedNormal = glm::dvec3(6.0, 3.0, 2.0) / 7.0;

// A model with the triangle `p` (non-indexed) in one root node with the given TRS.
inline GltfBuilder one_triangle(const std::vector<glm::vec3>& p, const std::vector<double>& translation = {},
                                const std::vector<double>& rotation = {}, const std::vector<double>& scale = {},
                                bool with_normals = false, glm::vec3 normal = glm::vec3(0.0f))
{
    GltfBuilder b;
    int pos = b.add_positions(p);
    int nrm = with_normals ? b.add_normals({normal, normal, normal}) : -1;
    int mat = b.add_material(glm::vec3(0.5f));
    int mesh = b.add_mesh(pos, -1, mat, 4, nrm);
    b.add_root(b.add_node(mesh, {}, translation, rotation, scale));
    return b;
}

// The tilted triangle with its material changed by `edit` (the material tests' model).
inline GltfBuilder tilted_triangle_with(const std::function<void(tinygltf::Material&)>& edit)
{
    GltfBuilder b = one_triangle(kTilted);
    edit(b.model.materials[0]);
    return b;
}

// A unit quad as two triangles, (0,1,2) and (0,2,3), counter-clockwise from +Z.
inline const std::vector<glm::vec3> kQuad = {
    {0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
inline const std::vector<std::uint32_t> kQuadIndices = {0, 1, 2, 0, 2, 3};

} // namespace pathcl::test
