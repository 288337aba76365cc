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

/* [0,1) to [0,1] with density proportional to (1 - x) a + x b (a, b >= 0, not both 0):
 * the root of the quadratic CDF, in the form without cancellation,
 * x = u (a + b) / (a + sqrt((1 - u) a^2 + u b^2)). */
static inline float sample_linear(float u, float a, float b)
{
    float root = a + sqrt(fma(u, b * b - a * a, a * a));
    float x = root > 0.0f ? u * (a + b) / root : u;
    return fmin(x, 1.0f);
}

/* The unit square with density proportional to the bilinear interpolation of the corner
 * weights w = (w(0,0), w(1,0), w(0,1), w(1,1)), all > 0: y from its marginal, then x
 * given y. */
static inline float2 sample_bilinear(float2 u, float4 w)
{
    float y = sample_linear(u.y, w.s0 + w.s1, w.s2 + w.s3);
    float x = sample_linear(u.x, fma(y, w.s2 - w.s0, w.s0), fma(y, w.s3 - w.s1, w.s1));
    return (float2)(x, y);
}

/* The density sample_bilinear draws p with. */
static inline float bilinear_pdf(float2 p, float4 w)
{
    float bottom = fma(p.x, w.s1 - w.s0, w.s0), top = fma(p.x, w.s3 - w.s2, w.s2);
    return 4.0f * fma(p.y, top - bottom, bottom) / (w.s0 + w.s1 + w.s2 + w.s3);
}
