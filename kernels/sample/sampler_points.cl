/* The sample visualizer's kernel (pathcl samples) and the sampler tests' window onto the
 * samplers: the points a render's decisions get, read back to the host. */
#include "sample/sampler.cl"

/* The sample visualizer's and the sampler tests' view of the samplers: out[p * count + k]
 * holds sample first_sample + k of pixel pixels[p], as the decision at dim0 sees it: the
 * 2D pair when dim1 == dim0 + 1, else the two 1D values of decisions at dim0 and dim1.
 * Global size (count, number of pixels). */
PATHCL_KERNEL void sampler_points(uint type, uint spp, uint seed, uint dim0, uint dim1, __global const uint* pixels,
                                  uint first_sample, uint count, __global float2* out)
{
    uint k = get_global_id(0), p = get_global_id(1);
    if (k >= count)
        return;
    SamplerState s = sampler_start_typed(type, spp, pixels[p], first_sample + k, seed, dim0);
    float2 v;
    if (dim1 == dim0 + 1u) {
        v = sampler_get_2d(&s);
    } else {
        v.x = sampler_get_1d(&s);
        s.dimension = dim1;
        v.y = sampler_get_1d(&s);
    }
    out[p * count + k] = v;
}
