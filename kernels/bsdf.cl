/* BSDFs: evaluation, sampling and pdf. Needs: shared_types.h, geometry.cl.
 * Directions are world-space unit vectors; wo points away from the surface, towards the
 * previous vertex. The shading point has ng and ns on wo's side. A direction is reflected
 * only if it lies above both the geometric and the shading surface: that keeps shading
 * normals from leaking light through the geometry. */

#define INV_PI 0.31830988618379067f
#define PI_F 3.14159265358979324f

typedef struct {
    float3 wi;
    float3 weight; /* f cos / pdf */
    float pdf;     /* solid angle; 0: no sample */
    bool delta;
} BsdfSample;

typedef struct {
    float3 f_cos; /* f * |cos theta_i| */
    float pdf;    /* of bsdf_sample producing wi */
} BsdfEval;

/* Lambertian with albedo = base colour (metallic and roughness enter with the glTF
 * metallic-roughness BSDF). */
static inline BsdfEval bsdf_eval(const Material* m, const SurfacePoint* sp, float3 wo, float3 wi)
{
    BsdfEval e;
    float cos_i = dot(wi, sp->ns);
    if (cos_i <= 0.0f || dot(wi, sp->ng) <= 0.0f) {
        e.f_cos = (float3)(0.0f);
        e.pdf = 0.0f;
        return e;
    }
    e.f_cos = m->base_color.xyz * (INV_PI * cos_i);
#ifdef PATHCL_FAULT_LAMBERT_NO_COSINE
    /* A deliberate bug, compiled only by the test proving the render tests can fail. */
    e.f_cos = m->base_color.xyz * INV_PI;
#endif
    e.pdf = cos_i * INV_PI;
    return e;
}

/* Cosine-weighted hemisphere sampling via the concentric disk map (Shirley-Chiu). */
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

static inline BsdfSample bsdf_sample(const Material* m, const SurfacePoint* sp, float3 wo, float2 u)
{
    BsdfSample s;
    float2 d = sample_concentric_disk(u);
    float z = sqrt(fmax(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    float3 t, b;
    make_basis(sp->ns, &t, &b);
    s.wi = d.x * t + d.y * b + z * sp->ns;
    s.delta = false;
    if (z <= 0.0f || dot(s.wi, sp->ng) <= 0.0f) {
        s.pdf = 0.0f;
        s.weight = (float3)(0.0f);
        return s;
    }
    s.pdf = z * INV_PI;
    s.weight = m->base_color.xyz; /* (albedo / pi) cos / (cos / pi) */
    return s;
}
