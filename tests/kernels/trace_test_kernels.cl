/* Test kernels over the real traversal code (kernels/bvh/): closest hit through the BVH,
 * closest hit by brute force over every triangle, and any-hit; spawned rays; and light
 * samples through the real light_sample. */
#include "bvh/traversal.cl"
#include "geom/ray_offset.cl"
#include "kernel_data.cl"
#include "light/light_sample.cl"
#include "sample/sampler.cl"

/* The traversal reads the scene through KernelData; these kernels bind only the BVH, the
 * triangles and their blocks (programs without PATHCL_HAS_ALPHA read nothing else). */
static inline KernelData geometry_only(__global const BvhNode* nodes, __global const Triangle* triangles,
                                       __global const TriangleBlock* blocks)
{
    KernelData kd;
    kd.nodes = nodes;
    kd.triangles = triangles;
    kd.triangle_blocks = blocks;
    return kd;
}

PATHCL_KERNEL void test_trace_closest(__global const float4* origins, __global const float4* dirs,
                                      __global const BvhNode* nodes, __global const Triangle* triangles,
                                      __global const TriangleBlock* blocks, __global float4* out)
{
    uint i = get_global_id(0);
    KernelData kd = geometry_only(nodes, triangles, blocks);
    Hit h = bvh_closest_hit(&kd, origins[i].xyz, dirs[i].xyz, INFINITY);
    out[i] = (float4)(h.t, h.b1, h.b2, as_float(h.triangle));
}

/* Every triangle tested on its own: `singles` holds one block per triangle, its triangle
 * in lane 0 (the traversal's own test, without the tree and without a leaf's lanes). */
PATHCL_KERNEL void test_trace_brute_force(__global const float4* origins, __global const float4* dirs,
                                          __global const Triangle* triangles, __global const TriangleBlock* singles,
                                          uint count, __global float4* out)
{
    uint i = get_global_id(0);
    RayTraversal r = ray_traversal_setup(origins[i].xyz, dirs[i].xyz);
    Hit h;
    h.t = INFINITY;
    h.b1 = h.b2 = 0.0f;
    h.triangle = -1;
    for (uint k = 0; k < count; ++k) {
        float8 t, b1, b2, ts, det_abs;
        if (ray_triangle_block(&r, &singles[k], h.t, &t, &b1, &b2, &ts, &det_abs) & 1u) {
            h.t = t.s0;
            h.b1 = b1.s0;
            h.b2 = b2.s0;
            h.triangle = singles[k].triangle.s0;
        }
    }
    out[i] = (float4)(h.t, h.b1, h.b2, as_float(h.triangle));
}

PATHCL_KERNEL void test_any_hit(__global const float4* origins, __global const float4* dirs,
                                __global const BvhNode* nodes, __global const Triangle* triangles,
                                __global const TriangleBlock* blocks, float t_max, __global int* out)
{
    uint i = get_global_id(0);
    KernelData kd = geometry_only(nodes, triangles, blocks);
    out[i] = bvh_visibility(&kd, origins[i].xyz, dirs[i].xyz, t_max) == 0.0f;
}

/* Spawns one ray per work-item from a random point on a random triangle (through the
 * kernels' own barycentric_point and offset_ray_origin), in a random direction on either
 * side, and returns the triangle it hits first (-1: none). */
PATHCL_KERNEL void test_spawned_ray_hits(__global const BvhNode* nodes, __global const Triangle* triangles,
                                         __global const TriangleBlock* blocks, uint count, uint seed,
                                         __global int* hit_triangle, __global int* source_triangle)
{
    uint i = get_global_id(0);
    SamplerState s = sampler_start(i, 0u, seed, 0u);
    uint t = min((uint)(sampler_get_1d(&s) * (float)count), count - 1u);
    float2 u = sampler_get_2d(&s);
    float su = sqrt(u.x);
    Triangle tri = triangles[t];
    float3 err;
    float3 p = barycentric_point(tri.v0.xyz, tri.v1.xyz, tri.v2.xyz, 1.0f - su, u.y * su, &err);
    float3 n = normalize(cross(tri.v1.xyz - tri.v0.xyz, tri.v2.xyz - tri.v0.xyz));
    float2 w = sampler_get_2d(&s);
    float z = 1.0f - 2.0f * w.x;
    float r = sqrt(fmax(0.0f, 1.0f - z * z));
    float3 d = (float3)(r * cos(2.0f * PI_F * w.y), r * sin(2.0f * PI_F * w.y), z);
    float3 o = offset_ray_origin(p, err, n, d);
    KernelData kd = geometry_only(nodes, triangles, blocks);
    hit_triangle[i] = bvh_closest_hit(&kd, o, d, INFINITY).triangle;
    source_triangle[i] = (int)t;
}

/* Light sampling through the real light_sample (kernels/light/): one sample per work-item
 * from `ref` over the scene arrays' lights; writes the direction and pdf, or a zero vector
 * when there is no sample (the chi-square harness counts those as failures of the
 * sampler), and the radiance the sample carries (so weight = radiance / pdf can be
 * checked). Environment and emissive-texture lookups read the same arrays. */
PATHCL_KERNEL void test_light_sample(PATHCL_KERNEL_PARAMS uint count, float4 ref, uint seed, __global float4* out,
                                     __global float4* radiance_out)
{
    PATHCL_KERNEL_DATA;
    uint i = get_global_id(0);
    SamplerState s = sampler_start(i, 0u, seed, 0u);
    FrameParams frame = {0};
    frame.light_count = count;
    LightSample ls = light_sample(&kd, &frame, ref.xyz, (float3)(0.0f), &s);
    out[i] = (ls.pdf > 0.0f) ? (float4)(ls.wi, ls.pdf) : (float4)(0.0f);
    radiance_out[i] = (ls.pdf > 0.0f) ? (float4)(ls.radiance, 0.0f) : (float4)(0.0f);
}

/* light_pick for each u[i] with the alias coin u_alias and the step jitter jitter: the
 * light and u[i] rescaled within its slot. */
PATHCL_KERNEL void test_light_pick(__global const LightAliasEntry* distribution, uint count, __global const float* u,
                                   float u_alias, float jitter, __global int* picked, __global float* u_out)
{
    uint i = get_global_id(0);
    float v = u[i];
    picked[i] = light_pick(distribution, count, &v, u_alias, jitter);
    u_out[i] = v;
}

/* A naive ray/triangle test for the robustness test to show that its checks catch one:
 * Moller-Trumbore without a determinant check, its range checks written as "reject if
 * outside", which lets NaN through. Never used for rendering. */
PATHCL_KERNEL void test_trace_brute_force_naive(__global const float4* origins, __global const float4* dirs,
                                                __global const Triangle* triangles,
                                                __global const TriangleBlock* singles, uint count, __global float4* out)
{
    uint i = get_global_id(0);
    float3 o = origins[i].xyz, d = dirs[i].xyz;
    float best = INFINITY, best_b1 = 0.0f, best_b2 = 0.0f;
    int best_tri = -1;
    for (uint k = 0; k < count; ++k) {
        float3 v0 = triangles[k].v0.xyz, e1 = triangles[k].v1.xyz - v0, e2 = triangles[k].v2.xyz - v0;
        float3 pv = cross(d, e2);
        float inv_det = 1.0f / dot(e1, pv);
        float3 tv = o - v0;
        float u = dot(tv, pv) * inv_det;
        if (u < 0.0f || u > 1.0f)
            continue;
        float3 qv = cross(tv, e1);
        float v = dot(d, qv) * inv_det;
        if (v < 0.0f || u + v > 1.0f)
            continue;
        float t = dot(e2, qv) * inv_det;
        if (t < 0.0f || t > best)
            continue;
        best = t;
        best_b1 = u;
        best_b2 = v;
        best_tri = (int)k;
    }
    out[i] = (float4)(best, best_b1, best_b2, as_float(best_tri));
}
