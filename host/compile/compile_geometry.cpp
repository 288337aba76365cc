// Geometry for the device: the BVH over the scene's triangles, the triangles in its leaf
// order (positions, normals and material for shading; each leaf's copied into a block
// of eight lanes for intersection), and the optional per-vertex attributes in the same
// order.
//
// With instanced meshes (FEATURE_INSTANCES) the BVH has two levels, in one node array: the
// top-level tree first (node 0 its root), over the instances' render-space boxes, its
// leaves naming Instance records; then one tree per mesh over its triangles in its own
// space, the triangles drawn once making one more tree, drawn by an identity instance.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "bvh/triangle_blocks.h"
#include "common/elapsed.h"
#include "common/error.h"
#include "compile/compile_scene.h"
#include "scene/alpha_cutouts.h"

namespace pathcl {
namespace {

BvhBuildInput triangle_boxes(const Scene& scene, std::size_t first, std::size_t count)
{
    BvhBuildInput input;
    input.box_min.resize(count);
    input.box_max.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const SceneTriangle& t = scene.triangles[first + i];
        input.box_min[i] = glm::min(t.v[0], glm::min(t.v[1], t.v[2]));
        input.box_max[i] = glm::max(t.v[0], glm::max(t.v[1], t.v[2]));
    }
    return input;
}

// Rows of an affine map for the device (types.h Instance).
void affine_rows(const glm::dmat4& m, pcl_float4 rows[3])
{
    for (int r = 0; r < 3; ++r)
        rows[r] = {static_cast<float>(m[0][r]), static_cast<float>(m[1][r]), static_cast<float>(m[2][r]),
                   static_cast<float>(m[3][r])};
}

// The two-level BVH; returns the stored triangles in leaf order (each tree's in turn) and
// sets top_nodes to the number of the top-level tree's nodes, which come first.
std::vector<std::uint32_t> build_two_levels(const Scene& scene, CompiledScene& out, std::size_t& top_nodes)
{
    // The trees: triangles drawn once (if any, or if nothing else), then each mesh.
    struct Tree {
        std::size_t first, count;
        Bvh bvh;
        glm::dvec3 lo, hi; // box of its triangles
        int root = 0;      // in the node array
        std::size_t leaf_base = 0;
    };
    std::vector<Tree> trees;
    const std::size_t drawn_once = scene.render_space_triangles();
    const bool world_tree = drawn_once > 0 || scene.meshes.empty();
    if (world_tree)
        trees.push_back(Tree{0, drawn_once, {}, {}, {}});
    for (const SceneMesh& m : scene.meshes) {
        trees.push_back(Tree{m.first, m.count, {}, {}, {}});
        // Every emissive triangle is a light with a render-space record (compile_lights):
        // the importer copies emissive meshes instead of instancing them.
        for (std::size_t i = m.first; i < m.first + m.count; ++i)
            if (scene.materials[static_cast<std::size_t>(scene.triangles[i].material)].emits())
                throw std::logic_error("compile_geometry: an instanced mesh emits light");
    }
    for (Tree& t : trees) {
        t.bvh = build_bvh(triangle_boxes(scene, t.first, t.count));
        t.lo = glm::dvec3(INFINITY);
        t.hi = glm::dvec3(-INFINITY);
        for (std::size_t i = t.first; i < t.first + t.count; ++i)
            for (const glm::vec3& v : scene.triangles[i].v) {
                t.lo = glm::min(t.lo, glm::dvec3(v));
                t.hi = glm::max(t.hi, glm::dvec3(v));
            }
    }
    // The drawings: (tree, map to render space); the identity first.
    struct Drawing {
        std::size_t tree;
        glm::dmat4 to_render;
    };
    std::vector<Drawing> drawings;
    if (world_tree)
        drawings.push_back(Drawing{0, glm::dmat4(1.0)});
    for (const SceneInstance& i : scene.instances)
        drawings.push_back(Drawing{i.mesh + (world_tree ? 1u : 0u), i.to_render});
    // Their render-space boxes, widened so that a ray mapped into a mesh's space with
    // float rounding cannot hit a triangle outside its instance's box: by 2^-18 of the
    // scene's extent from the render-space origin, some ten times that rounding.
    BvhBuildInput top;
    top.box_min.resize(drawings.size());
    top.box_max.resize(drawings.size());
    double extent = 0.0;
    for (std::size_t d = 0; d < drawings.size(); ++d) {
        const Tree& t = trees[drawings[d].tree];
        glm::dvec3 lo(INFINITY), hi(-INFINITY);
        add_mapped_box(drawings[d].to_render, t.lo, t.hi, lo, hi);
        if (t.count == 0)
            lo = hi = glm::dvec3(0.0);
        extent = std::max(
            {extent, std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y), std::abs(hi.z)});
        top.box_min[d] = glm::vec3(lo);
        top.box_max[d] = glm::vec3(hi);
    }
    const float pad = static_cast<float>(std::ldexp(extent, -18));
    for (std::size_t d = 0; d < drawings.size(); ++d)
        if (drawings[d].to_render != glm::dmat4(1.0)) {
            top.box_min[d] -= glm::vec3(pad);
            top.box_max[d] += glm::vec3(pad);
        }
    Bvh top_bvh = build_bvh(top);

    // One node array: the top level, then each tree, indices moved by where it lands.
    SceneArrays& a = out.arrays;
    a.nodes = top_bvh.nodes;
    top_nodes = a.nodes.size();
    std::vector<std::uint32_t> order;
    int deepest = 0;
    for (Tree& t : trees) {
        t.root = static_cast<int>(a.nodes.size());
        t.leaf_base = order.size();
        for (BvhNode node : t.bvh.nodes) {
            for (int k = 0; k < kBvhWidth; ++k)
                if (node.index.s[k] >= 0)
                    node.index.s[k] += node.count.s[k] == 0 ? t.root : static_cast<std::int32_t>(t.leaf_base);
            a.nodes.push_back(node);
        }
        for (std::uint32_t i : t.bvh.triangle_order)
            order.push_back(static_cast<std::uint32_t>(t.first + i));
        deepest = std::max(deepest, t.bvh.stack_needed);
    }
    // The traversal's stack holds the top level's entries, a leaf's instances, the return
    // mark and one tree's entries (+ 1: a node's children are all pushed before one pops).
    const int needed = top_bvh.stack_needed + kBvhMaxLeafSize + 1 + deepest + 1;
    if (needed > BVH_INSTANCED_STACK_SIZE)
        throw Error("the scene's two-level BVH needs a traversal stack of " + std::to_string(needed) +
                    " entries, more than the kernels' " + std::to_string(BVH_INSTANCED_STACK_SIZE));
    a.instances.resize(drawings.size());
    for (std::size_t leaf = 0; leaf < drawings.size(); ++leaf) {
        const Drawing& d = drawings[top_bvh.triangle_order[leaf]];
        Instance& inst = a.instances[leaf];
        inst = Instance{};
        affine_rows(glm::inverse(d.to_render), inst.to_object);
        affine_rows(d.to_render, inst.to_render);
        inst.root = trees[d.tree].root;
        inst.flags = (d.to_render == glm::dmat4(1.0) ? INSTANCE_IDENTITY : 0) |
                     (glm::determinant(glm::dmat3(d.to_render)) < 0.0 ? INSTANCE_MIRRORED : 0);
    }
    out.bvh = std::move(top_bvh);
    out.bvh.nodes.clear();
    return order;
}

} // namespace

std::vector<std::uint32_t> compile_geometry(const Scene& scene, CompiledScene& out)
{
    auto start = std::chrono::steady_clock::now();
    const std::size_t n = scene.triangles.size();
    SceneArrays& a = out.arrays;
    std::size_t top_nodes = 0; // nodes whose leaves name instances, not triangles
    if (out.features.has(FEATURE_INSTANCES)) {
        out.bvh.triangle_order = build_two_levels(scene, out, top_nodes);
    } else {
        if (!scene.instances.empty())
            throw std::logic_error("compile_geometry: a scene with instances needs FEATURE_INSTANCES");
        out.bvh = build_bvh(triangle_boxes(scene, 0, n));
        a.nodes = std::move(out.bvh.nodes);
    }
    out.bvh_build_seconds = seconds_since(start);
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
    make_triangle_blocks(a.nodes, top_nodes, a.triangles, a.triangle_blocks);
    out.triangle_leaves = triangle_leaves(a.nodes, top_nodes, a.triangle_blocks, n);
    // A program with every feature compiled in (--specialization all) reads these arrays
    // for scenes without them: tangents are read only through a normal texture or an
    // anisotropic material, so any value does; vertex colours multiply, so white.
    if (out.features.has(FEATURE_NORMAL_MAPS) || out.features.has(FEATURE_ANISOTROPY)) {
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
