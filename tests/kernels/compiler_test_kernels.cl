/* Test kernels for what the kernels rely on from the device's OpenCL C compiler: float3
 * arguments of a call it keeps out of line. */
#include "types.h"

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
