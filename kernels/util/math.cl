/* Generic math the rest of the device code shares: constants, pbrt's rounding-error
 * bound, component reductions and orthonormal frames. */

#define INV_PI 0.31830988618379067f
#define PI_F 3.14159265358979324f

/* The largest float below 1. */
#define ONE_MINUS_EPSILON 0x1.fffffep-1f

/* pbrt's gamma(n): bound on the relative error of n chained float operations. */
#define FLOAT_GAMMA(n) ((float)(n)*0x1.0p-24f / (1.0f - (float)(n)*0x1.0p-24f))

static inline float max3(float3 v)
{
    return fmax(v.x, fmax(v.y, v.z));
}

static inline float mean3(float3 v)
{
    return (v.x + v.y + v.z) * (1.0f / 3.0f);
}

/* Orthonormal basis around a unit vector (Duff et al. 2017, branchless). */
static inline void make_basis(float3 n, float3* t, float3* b)
{
    float sign = copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float c = n.x * n.y * a;
    *t = (float3)(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = (float3)(c, sign + n.y * n.y * a, -n.y);
}

static inline float3 to_local(float3 v, float3 t, float3 b, float3 n)
{
    return (float3)(dot(v, t), dot(v, b), dot(v, n));
}

static inline float3 to_world(float3 v, float3 t, float3 b, float3 n)
{
    return v.x * t + v.y * b + v.z * n;
}
