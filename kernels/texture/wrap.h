/* glTF sampler wrap modes (TEXTURE_WRAP_*), written once for the kernels' lookups
 * (texture/lookup.cl) and the host's nearest-texel estimates (host/compile/texture_lookup.cpp). */
#ifndef PATHCL_TEXTURE_WRAP_H
#define PATHCL_TEXTURE_WRAP_H

#include "types.h"
#include "util/compat.h"

PATHCL_BEGIN

/* A texel index wrapped into [0, n) by the sampler's mode. */
PATHCL_FN pcl_int wrap_texel(pcl_int i, pcl_int n, pcl_uint mode)
{
    if (mode == TEXTURE_WRAP_REPEAT) {
        pcl_int r = i % n;
        return r < 0 ? r + n : r;
    }
    if (mode == TEXTURE_WRAP_MIRRORED_REPEAT) {
        pcl_int period = 2 * n;
        pcl_int r = i % period;
        if (r < 0)
            r += period;
        return r < n ? r : period - 1 - r;
    }
    return clamp(i, 0, n - 1);
}

/* A coordinate moved into one period of its wrap mode before it is scaled to texels, so
 * that large coordinates keep their fraction and texel indices stay small: [0, 1] for
 * repeat, [0, 2] for mirrored repeat, [-1, 2] for clamp (indices are clamped after). */
PATHCL_FN pcl_real wrap_coordinate(pcl_real u, pcl_uint mode)
{
    if (!isfinite(u))
        return PCL_REAL(0.0);
    if (mode == TEXTURE_WRAP_REPEAT)
        return u - floor(u);
    if (mode == TEXTURE_WRAP_MIRRORED_REPEAT)
        return u - PCL_REAL(2.0) * floor(PCL_REAL(0.5) * u);
    return clamp(u, PCL_REAL(-1.0), PCL_REAL(2.0));
}

PATHCL_END

#endif
