/* Test kernels for what the kernels rely on from the device's OpenCL C compiler: float3
 * arguments of a call it keeps out of line, the slab test's min and max on infinities and
 * NaN, and FP_CONTRACT OFF. */
#include "bvh/traversal.cl"

/* Out of line by force, as a compiler may leave any call (a function several kernels
 * call, a large one): x + 2y + 4z, exact in float for the values below. */
PATHCL_NOINLINE static float weigh_float3(float3 v)
{
    return v.x + 2.0f * v.y + 4.0f * v.z;
}

/* out[i] = weigh_float3((i, i + 1, i + 2)) = 7i + 10. */
PATHCL_KERNEL void test_float3_argument(__global float* out)
{
    uint i = get_global_id(0);
    float f = (float)i;
    out[i] = weigh_float3((float3)(f, f + 1.0f, f + 2.0f));
}

/* slab_min and slab_max of every pair of a and b, as float8 lanes: out[2k] the min, out[2k
 * + 1] the max of pair k (k = i * n + j for a[i], b[j]; n a multiple of 8). */
PATHCL_KERNEL void test_slab_min_max(__global const float* a, __global const float* b, uint n, __global float* out)
{
    uint i = get_global_id(0);
    for (uint j = 0; j < n; j += 8u) {
        float8 x = (float8)(a[i]), y = vload8(0, b + j);
        float8 lo = slab_min(x, y), hi = slab_max(x, y);
        float l[8], h[8];
        vstore8(lo, 0, l);
        vstore8(hi, 0, h);
        for (uint k = 0; k < 8u; ++k) {
            out[2u * (i * n + j + k)] = l[k];
            out[2u * (i * n + j + k) + 1u] = h[k];
        }
    }
}

#pragma OPENCL FP_CONTRACT OFF
/* out[i] = x[i] * y[i] - z[i], the product rounded before the subtraction (no fma). */
PATHCL_KERNEL void test_contract_off(__global const float* x, __global const float* y, __global const float* z,
                                     __global float* out)
{
    uint i = get_global_id(0);
    out[i] = x[i] * y[i] - z[i];
}
#pragma OPENCL FP_CONTRACT ON
