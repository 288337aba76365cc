/* Sphere lights: uniform outward radiance over a sphere, seen by camera and BSDF rays
 * (tested directly against each ray, outside the BVH: they come first in the light
 * array) and sampled uniformly in the cone they subtend (pbrt's sphere sampling). */
#include "features.h"
#include "kernel_data.cl"
#include "light/light_sample_record.cl"
#include "util/math.cl"
#include "util/sincos.cl"

#ifdef PATHCL_HAS_SPHERE_LIGHTS

/* Nearest t in (0, t_max) where origin + t dir meets the sphere, INFINITY if none. The
 * discriminant is computed from the ray's closest approach, r^2 - |l|^2, which does not
 * cancel catastrophically when the sphere is small or far (Ray Tracing Gems, ch. 7). */
static inline float ray_sphere(float3 centre, float radius, float3 origin, float3 dir, float t_max, bool* from_outside)
{
    float3 f = origin - centre;
    float a = dot(dir, dir);
    float b = dot(f, dir);
    float c = dot(f, f) - radius * radius;
    float3 l = f - (b / a) * dir;
    float disc = radius * radius - dot(l, l);
    *from_outside = c > 0.0f;
    if (disc < 0.0f)
        return INFINITY;
    float q = -b - copysign(sqrt(a * disc), b);
    float t0 = c / q, t1 = q / a;
    float t_near = fmin(t0, t1), t_far = fmax(t0, t1);
    if (t_near > 0.0f && t_near < t_max)
        return t_near;
    if (t_far > 0.0f && t_far < t_max)
        return t_far;
    return INFINITY;
}

/* Nearest sphere light along the ray before t_max: its index, or -1 (t in *t_hit). */
static inline int closest_sphere_light(__global const Light* lights, uint sphere_count, float3 origin, float3 dir,
                                       float t_max, float* t_hit, bool* from_outside)
{
    int best = -1;
    *t_hit = t_max;
    for (uint i = 0; i < sphere_count; ++i) {
        bool outside;
        float t =
            ray_sphere(lights[i].data.sphere.centre.xyz, lights[i].data.sphere.radius, origin, dir, *t_hit, &outside);
        if (t < *t_hit) {
            *t_hit = t;
            *from_outside = outside;
            best = (int)i;
        }
    }
    return best;
}

/* 1 - cos(theta_max) of the cone a sphere of radius r subtends from distance^2 dc2,
 * without cancellation: sin^2 / (1 + cos). */
static inline float sphere_cone_one_minus_cos(float r, float dc2)
{
    float sin2 = r * r / dc2;
    return sin2 / (1.0f + sqrt(fmax(0.0f, 1.0f - sin2)));
}

/* Solid-angle pdf with which light_sample picks a direction towards sphere light `light`
 * (picked with probability pmf) from `ref`: uniform over the subtended cone, times the
 * pmf; 0 from inside. */
static inline float sphere_light_pdf(const Light* light, float pmf, float3 ref)
{
    float3 d = light->data.sphere.centre.xyz - ref;
    float dc2 = dot(d, d);
    float r = light->data.sphere.radius;
    if (!(dc2 > r * r))
        return 0.0f;
    return pmf / (2.0f * PI_F * sphere_cone_one_minus_cos(r, dc2));
}

/* A uniform direction in the cone the sphere subtends from ref. */
static inline void sample_sphere_light(const Light* light, float pmf, float3 ref, float2 u, LightSample* ls)
{
    float3 c = light->data.sphere.centre.xyz;
    float r = light->data.sphere.radius;
    float3 to_centre = c - ref;
    float dc2 = dot(to_centre, to_centre);
    if (!(dc2 > r * r))
        return; /* inside the sphere: it is not seen from here */
    float dc = sqrt(dc2);
    float omc = sphere_cone_one_minus_cos(r, dc2);
    float one_minus_cos_theta = u.x * omc;
    float cos_theta = 1.0f - one_minus_cos_theta;
    float sin2_theta = one_minus_cos_theta * (2.0f - one_minus_cos_theta);
    float sin_theta = sqrt(fmax(0.0f, sin2_theta));
    float3 axis = to_centre / dc, t, b;
    make_basis(axis, &t, &b);
    float cos_phi, sin_phi = sin_cos_turns(u.y, &cos_phi); /* phi = 2 pi u.y */
    ls->wi = normalize(sin_theta * cos_phi * t + sin_theta * sin_phi * b + cos_theta * axis);
    /* Distance to the near side of the sphere along wi. */
    float ds = dc * cos_theta - sqrt(fmax(0.0f, r * r - dc2 * sin2_theta));
    ls->p = ref + ds * ls->wi;
    ls->n = normalize(ls->p - c);
    ls->p_error = FLOAT_GAMMA(16) * (fabs(ref) + fabs(c) + (float3)(r));
    ls->radiance = light->radiance.xyz;
    ls->pdf = pmf / (2.0f * PI_F * omc);
}

#endif /* PATHCL_HAS_SPHERE_LIGHTS */
