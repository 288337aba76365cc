// Geometry for the device: the BVH over the scene's triangles, the triangles in its leaf
// order (positions for intersection, normals and material for shading), and the
// optional per-vertex attributes in the same order.
#include <chrono>

#include "render/compile_scene.h"
#include "scene/alpha_cutouts.h"

namespace pathcl {

std::vector<std::uint32_t> compile_geometry(const Scene& scene, CompiledScene& out)
{
    auto start = std::chrono::steady_clock::now();
    const std::size_t n = scene.triangles.size();
    BvhBuildInput input;
    input.box_min.resize(n);
    input.box_max.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const SceneTriangle& t = scene.triangles[i];
        input.box_min[i] = glm::min(t.v[0], glm::min(t.v[1], t.v[2]));
        input.box_max[i] = glm::max(t.v[0], glm::max(t.v[1], t.v[2]));
    }
    out.bvh = build_bvh(input);
    out.bvh_build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    SceneArrays& a = out.arrays;
    a.nodes = std::move(out.bvh.nodes);
    const std::vector<std::uint32_t>& order = out.bvh.triangle_order;

    a.triangles.resize(n);
    a.shading.resize(n);
    std::vector<bool> alpha_tested;
    if (out.features.has(FEATURE_ALPHA))
        alpha_tested = alpha_tested_triangles(scene);
    for (std::size_t i = 0; i < n; ++i) {
        const SceneTriangle& t = scene.triangles[order[i]];
        float alpha_flag = !alpha_tested.empty() && alpha_tested[order[i]] ? TRIANGLE_ALPHA_TESTED : 0.0f;
        a.triangles[i] = Triangle{to_float4(t.v[0], alpha_flag), to_float4(t.v[1]), to_float4(t.v[2])};
        // The emitter index is set by compile_lights.
        a.shading[i] = TriangleShading{to_float4(t.n[0]), to_float4(t.n[1]), to_float4(t.n[2]), t.material, -1, 0, 0};
    }
    // A program with every feature compiled in (--specialization all) reads these arrays
    // for scenes without them: tangents are read only through a normal texture, so any
    // value does; vertex colours multiply, so white.
    if (out.features.has(FEATURE_NORMAL_MAPS)) {
        a.tangents.resize(n, TriangleTangents{});
        for (std::size_t i = 0; i < n && !scene.tangents.empty(); ++i) {
            const TriangleTangent& t = scene.tangents[order[i]];
            a.tangents[i] = {
                {t[0].x, t[0].y, t[0].z, t[0].w}, {t[1].x, t[1].y, t[1].z, t[1].w}, {t[2].x, t[2].y, t[2].z, t[2].w}};
        }
    }
    if (out.features.has(FEATURE_VERTEX_COLORS)) {
        const pcl_float4 white = {1.0f, 1.0f, 1.0f, 1.0f};
        a.colors.resize(n, TriangleColors{white, white, white});
        for (std::size_t i = 0; i < n && !scene.colors.empty(); ++i) {
            const TriangleColor& c = scene.colors[order[i]];
            a.colors[i] = {
                {c[0].x, c[0].y, c[0].z, c[0].w}, {c[1].x, c[1].y, c[1].z, c[1].w}, {c[2].x, c[2].y, c[2].z, c[2].w}};
        }
    }
    return order;
}

} // namespace pathcl
