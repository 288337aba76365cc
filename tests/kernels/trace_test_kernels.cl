/* Test kernels over the real traversal code (kernels/bvh.cl): closest hit through the
 * BVH, closest hit by brute force over every triangle, and any-hit. */

__kernel void test_trace_closest(__global const float4* origins, __global const float4* dirs,
                                 __global const BvhNode* nodes,
                                 __global const Triangle* triangles, __global float4* out)
{
    uint i = get_global_id(0);
    Hit h = bvh_trace(nodes, triangles, origins[i].xyz, dirs[i].xyz, INFINITY, false);
    out[i] = (float4)(h.t, h.b1, h.b2, as_float(h.triangle));
}

__kernel void test_trace_brute_force(__global const float4* origins, __global const float4* dirs,
                                     __global const Triangle* triangles, uint count,
                                     __global float4* out)
{
    uint i = get_global_id(0);
    RayTraversal r = ray_traversal_setup(origins[i].xyz, dirs[i].xyz);
    Hit h;
    h.t = INFINITY;
    h.b1 = h.b2 = 0.0f;
    h.triangle = -1;
    for (uint k = 0; k < count; ++k) {
        float t, b1, b2;
        if (ray_triangle(&r, &triangles[k], h.t, &t, &b1, &b2)) {
            h.t = t;
            h.b1 = b1;
            h.b2 = b2;
            h.triangle = (int)k;
        }
    }
    out[i] = (float4)(h.t, h.b1, h.b2, as_float(h.triangle));
}

__kernel void test_any_hit(__global const float4* origins, __global const float4* dirs,
                           __global const BvhNode* nodes, __global const Triangle* triangles,
                           float t_max, __global int* out)
{
    uint i = get_global_id(0);
    out[i] = bvh_trace(nodes, triangles, origins[i].xyz, dirs[i].xyz, t_max, true).triangle >= 0;
}
