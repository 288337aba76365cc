// The scene compiled for the device: every array the kernels read (compile/device_arrays.h),
// built by small named steps, one concept per file (LuxCore's compile*.cpp):
//   compile_geometry.cpp   BVH (two levels with instances), triangles in leaf order with their
//                          shading data, tangents, colours
//   compile_materials.cpp  Material records
//   compile_textures.cpp   texel buffer, images, views, texture-coordinate sets
//   compile_lights.cpp     Light records and their powers (light_distribution.h turns the
//                          powers into the pick probabilities and the alias table, and
//                          light_tree.h into the light tree)
//   environment.cpp        the environment map's texels and sampling distribution
//   compile_camera.cpp     the Camera for an image size
// compile_scene runs them in that order; only the steps the feature mask asks for fill
// their arrays.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bvh/bvh_builder.h"
#include "bvh/triangle_blocks.h"
#include "compile/device_arrays.h"
#include "compile/kernel_features.h"
#include "render/render_options.h"
#include "scene/scene.h"

namespace pathcl {

struct CompiledScene {
    SceneArrays arrays; // the camera array is filled per image size (compile_camera)
    KernelFeatures features;
    // The light array's order: sphere lights first (rays test lights[0 .. sphere_count)
    // directly), then emissive triangles (TriangleShading.emitter names them), punctual
    // lights, and the environment last (environment_light; -1 if none).
    std::size_t sphere_count = 0;
    int environment_light = -1;
    // The light tree (FEATURE_LIGHT_TREE; compile/light_tree.h): how often the infinite
    // lights (arrays.light_tree_infinite) are picked, the tree's depth and build time.
    double infinite_pick = 0.0;
    std::uint32_t light_tree_depth = 0;
    double light_tree_build_seconds = 0.0;
    // Depth and leaf figures (its nodes moved into arrays.nodes; with instances, the
    // top-level tree's) and triangle_order: the stored triangle at each leaf position.
    Bvh bvh;
    double bvh_build_seconds = 0.0;
    // By stored triangle: its BVH leaf's node and block (compile_geometry), which
    // compile_lights copies into an emissive triangle's Light.
    std::vector<TriangleLeaf> triangle_leaves;

    std::size_t texel_bytes() const { return arrays.texels.size() * sizeof(pcl_uint); }
};

// light_sampler: the weights of the power table (uniform: all alike); the tree is built
// when the features ask for it.
CompiledScene compile_scene(const Scene& scene, const KernelFeatures& features,
                            LightSampler light_sampler = LightSampler::Power);

inline pcl_float4 to_float4(const glm::vec3& v, float w = 0.0f)
{
    return {v.x, v.y, v.z, w};
}

inline pcl_float4 to_float4(const glm::dvec3& v, float w = 0.0f)
{
    return to_float4(glm::vec3(v), w);
}

// The steps. leaf_order[i] is the scene triangle at BVH leaf position i.
std::vector<std::uint32_t> compile_geometry(const Scene& scene, CompiledScene& out);
void compile_materials(const Scene& scene, const KernelFeatures& features, SceneArrays& arrays);
void compile_textures(const Scene& scene, const std::vector<std::uint32_t>& leaf_order, SceneArrays& arrays);
// Fills lights (in the order CompiledScene describes), the emitter index of every
// emissive triangle's shading record, and returns each light's power (luminance, W),
// the weight it is picked with.
std::vector<double> compile_lights(const Scene& scene, const std::vector<std::uint32_t>& leaf_order,
                                   CompiledScene& out);

// Camera for an image of the given size: yfov (orthographic: ymag) is kept; the
// horizontal extent follows the image's aspect ratio.
Camera compile_camera(const SceneCamera& camera, std::uint32_t width, std::uint32_t height);

} // namespace pathcl
