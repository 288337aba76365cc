/* How a light is picked, written once for the kernel that picks (light/light_pick.cl)
 * and the host that gives every light the exact probability of being picked
 * (host/compile/light_distribution.cpp). The slot and the alias coin are each an integer
 * on a grid of LIGHT_PICK_GRID = 2^24 steps, so every sampler's numbers fall on it the
 * same way: step k of the slot grid picks slot (k n) >> 24 of n slots. */
#ifndef PATHCL_LIGHT_LIGHT_PICK_H
#define PATHCL_LIGHT_LIGHT_PICK_H

#include "util/compat.h"

#define LIGHT_PICK_GRID 16777216u

PATHCL_BEGIN

/* The slot step k in [0, LIGHT_PICK_GRID) picks among n slots. */
PATHCL_FN pcl_uint light_pick_slot(pcl_uint k, pcl_uint n)
{
    return (pcl_uint)(((pcl_ulong)k * n) >> 24);
}

/* The first step that picks slot j or a later one (j <= n): ceil(j 2^24 / n), so slot j
 * comes up for the steps [light_pick_first_step(j), light_pick_first_step(j + 1)). */
PATHCL_FN pcl_ulong light_pick_first_step(pcl_ulong j, pcl_ulong n)
{
    return (j * LIGHT_PICK_GRID + n - 1u) / n;
}

PATHCL_END

#endif
