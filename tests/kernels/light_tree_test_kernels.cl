/* The light tree through its real code (kernels/light/light_tree.cl): picks at one shading
 * point, each with the probability the pick reports and the one light_tree_pmf computes
 * for the light picked, and light_tree_pmf for every light. Built with
 * FEATURE_LIGHT_TREE. */
#include "kernel_data.cl"
#include "light/light_tree.cl"
#include "util/hash.cl"

/* Pick i with the uniform number hash(seed, i): the light (-1: none) and both pmfs. */
PATHCL_KERNEL void test_light_tree_pick(PATHCL_KERNEL_PARAMS FrameParams frame, float4 ref, float4 n, uint seed,
                                        __global int* light, __global float* pick_pmf, __global float* pmf)
{
    PATHCL_KERNEL_DATA;
    uint i = get_global_id(0);
    uint key = hash_combine(hash_u32(seed), i);
    float u = u32_to_unit_float(hash_u32(key));
    float p;
    int l = light_tree_pick(&kd, &frame, ref.xyz, n.xyz, u, key, &p);
    light[i] = l;
    pick_pmf[i] = p;
    pmf[i] = l >= 0 ? light_tree_pmf(&kd, &frame, ref.xyz, n.xyz, l) : 0.0f;
}

/* light_tree_pmf of light i. */
PATHCL_KERNEL void test_light_tree_pmf(PATHCL_KERNEL_PARAMS FrameParams frame, float4 ref, float4 n,
                                       __global float* pmf)
{
    PATHCL_KERNEL_DATA;
    uint i = get_global_id(0);
    pmf[i] = light_tree_pmf(&kd, &frame, ref.xyz, n.xyz, (int)i);
}

/* The importance of the root's lane 0 at point i (points[i].xyz) with normal normals[i].xyz. */
PATHCL_KERNEL void test_light_tree_importance(PATHCL_KERNEL_PARAMS __global const float4* points,
                                              __global const float4* normals, __global float* importance)
{
    PATHCL_KERNEL_DATA;
    uint i = get_global_id(0);
    importance[i] = light_tree_importance(&kd.light_tree[0], points[i].xyz, normals[i].xyz).s0;
}

/* The importance of each of the root's eight lanes at point i (points[i].xyz) with normal
 * normals[i].xyz: importance[8 i + k] for lane k. */
PATHCL_KERNEL void test_light_tree_importance8(PATHCL_KERNEL_PARAMS __global const float4* points,
                                               __global const float4* normals, __global float* importance)
{
    PATHCL_KERNEL_DATA;
    uint i = get_global_id(0);
    vstore8(light_tree_importance(&kd.light_tree[0], points[i].xyz, normals[i].xyz), i, importance);
}
