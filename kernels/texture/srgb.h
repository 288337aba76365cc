/* sRGB (IEC 61966-2-1) decoding, written once for the kernels (16-bit texels, in float)
 * and the host (the 8-bit table of texture/lookup.cl is this formula in double, rounded
 * to float and tested; host texture estimates decode with it). */
#ifndef PATHCL_TEXTURE_SRGB_H
#define PATHCL_TEXTURE_SRGB_H

#include "util/compat.h"

PATHCL_BEGIN

/* An sRGB-encoded value in [0, 1] to linear. */
PATHCL_FN pcl_real srgb_to_linear(pcl_real c)
{
    return c <= PCL_REAL(0.04045) ? c * (PCL_REAL(1.0) / PCL_REAL(12.92))
                                  : pow((c + PCL_REAL(0.055)) * (PCL_REAL(1.0) / PCL_REAL(1.055)), PCL_REAL(2.4));
}

PATHCL_END

#endif
