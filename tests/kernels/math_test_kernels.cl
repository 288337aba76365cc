/* Test kernels over the device's own math routines (kernels/util/): the fast atan2. */
#include "util/atan.cl"
#include "util/compat.h"

/* out[i] = atan2_fast(yx[i].x, yx[i].y). */
PATHCL_KERNEL void test_atan2(__global const float2* yx, __global float* out)
{
    uint i = get_global_id(0);
    out[i] = atan2_fast(yx[i].x, yx[i].y);
}
