/* Warps from the unit square, shared by the camera (lens), the BSDFs and the lights. */
#include "util/math.cl"
#include "util/sincos.cl"

/* The unit square to the unit disk by Shirley and Chiu's concentric map: low distortion,
 * so stratified points stay stratified on the disk. */
static inline float2 sample_concentric_disk(float2 u)
{
    float2 o = 2.0f * u - 1.0f;
    if (o.x == 0.0f && o.y == 0.0f)
        return (float2)(0.0f);
    float c, s;
    if (fabs(o.x) > fabs(o.y)) { /* theta = pi/4 (y/x), within [-pi/4, pi/4] */
        s = sin_cos_small((PI_F / 4.0f) * (o.y / o.x), &c);
        return o.x * (float2)(c, s);
    }
    /* theta = pi/2 - a with a = pi/4 (x/y): cos theta = sin a, sin theta = cos a */
    s = sin_cos_small((PI_F / 4.0f) * (o.x / o.y), &c);
    return o.y * (float2)(s, c);
}

/* Cosine-weighted hemisphere sampling via the concentric disk map. */
static inline float3 sample_cosine_hemisphere(float2 u)
{
    float2 d = sample_concentric_disk(u);
    return (float3)(d.x, d.y, sqrt(fmax(0.0f, 1.0f - d.x * d.x - d.y * d.y)));
}
