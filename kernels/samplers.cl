/* Random numbers, counter-based: each number is a hash of (seed, pixel, sample index,
 * dimension), so a sample's value never depends on which work-item or pass computed it,
 * and a render is reproducible on any device. Later samplers (stratified, Sobol, ...)
 * replace sampler_get_1d's body and keep its signature. */

typedef struct {
    uint pixel;
    uint sample;
    uint seed;
    uint dimension; /* next dimension to hand out */
} SamplerState;

/* A full-avalanche 32-bit mix (the "lowbias32" hash by Chris Wellons). */
static inline uint hash_u32(uint x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

static inline uint hash_combine(uint h, uint v)
{
    return hash_u32(h ^ (v + 0x9e3779b9u + (h << 6) + (h >> 2)));
}

/* 24 random bits to a float in [0, 1): exactly representable, never 1. */
static inline float u32_to_unit_float(uint x)
{
    return (float)(x >> 8) * 0x1.0p-24f;
}

static inline SamplerState sampler_start(uint pixel, uint sample, uint seed, uint dimension)
{
    SamplerState s;
    s.pixel = pixel;
    s.sample = sample;
    s.seed = seed;
    s.dimension = dimension;
    return s;
}

static inline float sampler_get_1d(SamplerState* s)
{
    uint h = hash_combine(hash_combine(hash_combine(hash_u32(s->seed), s->pixel), s->sample),
                          s->dimension);
    s->dimension += 1;
    return u32_to_unit_float(h);
}

static inline float2 sampler_get_2d(SamplerState* s)
{
    float a = sampler_get_1d(s);
    float b = sampler_get_1d(s);
    return (float2)(a, b);
}

/* Warps from the unit square, shared by the camera (lens), BSDFs and lights. */

#define INV_PI 0.31830988618379067f
#define PI_F 3.14159265358979324f

/* The unit square to the unit disk by Shirley and Chiu's concentric map: low distortion,
 * so stratified points stay stratified on the disk. */
static inline float2 sample_concentric_disk(float2 u)
{
    float2 o = 2.0f * u - 1.0f;
    if (o.x == 0.0f && o.y == 0.0f)
        return (float2)(0.0f);
    float r, theta;
    if (fabs(o.x) > fabs(o.y)) {
        r = o.x;
        theta = (PI_F / 4.0f) * (o.y / o.x);
    } else {
        r = o.y;
        theta = (PI_F / 2.0f) - (PI_F / 4.0f) * (o.x / o.y);
    }
    return r * (float2)(cos(theta), sin(theta));
}

