/* The strata grid of the jittered and multi-jittered samplers, written once for the
 * kernels (sample/sampler.cl) and the host (the visualizer's grid lines, the sampler
 * tests): cols = floor(sqrt(n)) columns and rows = ceil(n / cols) rows for a set of n
 * points, so a square n (which the host rounds jittered spp to) gives sqrt(n) x sqrt(n). */
#ifndef PATHCL_SAMPLE_STRATA_H
#define PATHCL_SAMPLE_STRATA_H

#include "util/compat.h"

PATHCL_BEGIN

/* floor(sqrt(n)) exactly. */
PATHCL_FN pcl_uint sqrt_floor_u32(pcl_uint n)
{
    pcl_uint r = (pcl_uint)sqrt((float)n);
    while ((pcl_ulong)r * r > n)
        --r;
    while ((pcl_ulong)(r + 1u) * (r + 1u) <= n)
        ++r;
    return r;
}

PATHCL_FN pcl_uint strata_cols(pcl_uint n)
{
    pcl_uint c = sqrt_floor_u32(n);
    return c > 1u ? c : 1u;
}

PATHCL_FN pcl_uint strata_rows(pcl_uint n, pcl_uint cols)
{
    return (n + cols - 1u) / cols;
}

PATHCL_END

#endif
