/* A triangle as seen from a point: the spherical triangle its corners' directions span,
 * its solid angle, and directions drawn uniformly within it (Arvo 1995, "Stratified
 * sampling of spherical triangles"). Emissive triangles near the shading point are sampled
 * this way (light/triangle.cl): by area, the pdf in solid angle grows with the distance
 * squared over the cosine at the light, which varies without bound across a triangle seen
 * from close by. */
#include "util/atan.cl"
#include "util/compat.h"
#include "util/math.cl"
#include "util/sincos.cl"

/* The triangle v0 v1 v2 seen from p: its corners' unit directions. */
typedef struct {
    float3 a, b, c;
} SphericalTriangle;

static inline SphericalTriangle spherical_triangle(float3 p, float3 v0, float3 v1, float3 v2)
{
    SphericalTriangle s;
    s.a = normalize(v0 - p);
    s.b = normalize(v1 - p);
    s.c = normalize(v2 - p);
    return s;
}

/* Its solid angle, by Van Oosterom and Strackee's tan(omega / 2) = |a.(b x c)| /
 * (1 + a.b + b.c + c.a), which stays accurate for small triangles where the sum of the
 * corner angles less pi cancels. Between 0 and 2 pi (a point in the triangle's plane and
 * inside it); NaN only for a point on a corner. */
static inline float spherical_triangle_solid_angle(const SphericalTriangle* s)
{
    float triple = fabs(dot(s->a, cross(s->b, s->c)));
    float denominator = 1.0f + dot(s->a, s->b) + dot(s->b, s->c) + dot(s->c, s->a);
    return 2.0f * atan2_fast(triple, denominator);
}

/* A direction uniform over the spherical triangle of solid angle omega, from u in [0,1)^2:
 * u.x chooses the sub-triangle a b c' of area A = u.x omega (c' on the arc from a to c),
 * u.y the point along the arc from b to c'. Arvo's construction, with two changes for
 * float: the angle alpha at a enters only through its sine and cosine, which the corners
 * give without trigonometry, |a x b| |a x c| (cos alpha, sin alpha) = (b.c - (a.b)(a.c),
 * |a.(b x c)|); and the arcs' cosines are carried as 1 - cos, which for a small A or u.y
 * Arvo's formulas would only give as a difference of nearly equal numbers (their sines,
 * from a square root of that, off by the square root of a rounding error, put samples
 * outside the triangle). With s, t = sin, cos(A - alpha) and Arvo's u = t - cos alpha,
 * v = s + sin alpha cos(a b), the cosine q of the arc from a to c' has
 * 1 - q = 2 sin^2(A/2) (1 + a.b) / (v s + u t), and u = 2 sin(A/2) sin(alpha - A/2). */
PATHCL_NOINLINE static float3 sample_spherical_triangle(const SphericalTriangle* s, float omega, float2 u)
{
    float3 a = s->a, b = s->b, c = s->c;
    float cos_ab = dot(a, b);
    float y = fabs(dot(a, cross(b, c)));
    float x = dot(b, c) - cos_ab * dot(a, c);
    float r = sqrt(x * x + y * y);
    float cos_alpha = r > 0.0f ? x / r : 1.0f;
    float sin_alpha = r > 0.0f ? y / r : 0.0f;

    /* Half the sub-triangle's area, A/2 = u.x omega / 2, in turns for sin_cos_turns. */
    float cos_half, sin_half = sin_cos_turns(u.x * omega * (0.25f * INV_PI), &cos_half);
    float sin_area = 2.0f * sin_half * cos_half;
    float cos_area = 1.0f - 2.0f * sin_half * sin_half;
    float sn = sin_area * cos_alpha - cos_area * sin_alpha;
    float cs = cos_area * cos_alpha + sin_area * sin_alpha;
    float arvo_u = 2.0f * sin_half * (sin_alpha * cos_half - cos_alpha * sin_half);
    float arvo_v = sn + sin_alpha * cos_ab;
    float denominator = arvo_v * sn + arvo_u * cs;
    float one_minus_q = denominator > 0.0f ? 2.0f * sin_half * sin_half * (1.0f + cos_ab) / denominator : 0.0f;
    one_minus_q = fmin(fmax(one_minus_q, 0.0f), 2.0f); /* fmax drops a NaN */
    float3 c_along = c - dot(c, a) * a;
    float c_len = length(c_along);
    float3 c_dir = c_len > 0.0f ? c_along / c_len : (float3)(0.0f);
    float3 c_prime = (1.0f - one_minus_q) * a + sqrt(one_minus_q * (2.0f - one_minus_q)) * c_dir;

    /* Along the arc from b to c': uniform in the cosine about b, 1 - cos = u.y (1 - b.c'),
     * with 1 - b.c' = |c' - b|^2 / 2. */
    float3 d = c_prime - b;
    float one_minus_z = u.y * 0.5f * dot(d, d);
    float3 cp_along = c_prime - dot(c_prime, b) * b;
    float cp_len = length(cp_along);
    float3 cp_dir = cp_len > 0.0f ? cp_along / cp_len : (float3)(0.0f);
    return normalize((1.0f - one_minus_z) * b + sqrt(fmax(0.0f, one_minus_z * (2.0f - one_minus_z))) * cp_dir);
}

/* Where the ray from p along w crosses the triangle v0 v1 v2's plane, as barycentrics
 * (b1, b2) of v1 and v2, clamped into the triangle (a direction sampled within the
 * spherical triangle lies inside it but for rounding); false if w is parallel to it. */
static inline bool triangle_barycentrics_along(float3 p, float3 w, float3 v0, float3 v1, float3 v2, float* b1,
                                               float* b2)
{
    float3 e1 = v1 - v0, e2 = v2 - v0;
    float3 pv = cross(w, e2);
    float det = dot(e1, pv);
    if (det == 0.0f)
        return false;
    float3 tv = p - v0;
    float x = dot(tv, pv) / det;
    float y = dot(w, cross(tv, e1)) / det;
    x = fmin(fmax(x, 0.0f), 1.0f);
    y = fmin(fmax(y, 0.0f), 1.0f);
    float sum = x + y;
    if (sum > 1.0f) {
        x /= sum;
        y /= sum;
    }
    *b1 = x;
    *b2 = y;
    return true;
}
