/* Light selection and sampling. Needs: shared_types.h, samplers.cl, geometry.cl, textures.cl.
 * Lights are picked in proportion to their emitted power through an alias table (O(1));
 * each light's selection probability is in radiance.w, which MIS needs for BSDF-found
 * hits on area lights too. Only the light types a scene has are compiled
 * (PATHCL_HAS_*_LIGHTS). */

#if defined(PATHCL_HAS_AREA_LIGHTS) || defined(PATHCL_HAS_POINT_LIGHTS) || \
    defined(PATHCL_HAS_SPOT_LIGHTS) || defined(PATHCL_HAS_DIRECTIONAL_LIGHTS) || \
    defined(PATHCL_HAS_SPHERE_LIGHTS) || defined(PATHCL_HAS_ENVIRONMENT)
#define PATHCL_HAS_LIGHTS
#endif

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
        float t = ray_sphere(lights[i].p0.xyz, lights[i].p0.w, origin, dir, *t_hit, &outside);
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
 * from `ref`: uniform over the subtended cone, times the selection pmf; 0 from inside. */
static inline float sphere_light_pdf(const Light* light, float3 ref)
{
    float3 d = light->p0.xyz - ref;
    float dc2 = dot(d, d);
    float r = light->p0.w;
    if (!(dc2 > r * r))
        return 0.0f;
    return light->radiance.w / (2.0f * PI_F * sphere_cone_one_minus_cos(r, dc2));
}

typedef struct {
    float3 p;        /* point on the light (position for point lights) */
    float3 p_error;  /* rounding bound on p (0 for positions given exactly) */
    float3 n;        /* area lights: surface normal on the emitting side */
    float3 wi;       /* unit direction from the shading point towards the light */
    float3 radiance; /* what arrives: area lights: radiance; delta lights: irradiance
                      * at normal incidence (I / d^2, or E) */
    float pdf;       /* solid angle for area lights, selection included; delta lights:
                      * selection probability only; 0: no sample */
    bool delta;      /* cannot be hit by a ray (point, spot, directional) */
    bool at_infinity; /* directional: the shadow ray is unbounded */
} LightSample;

/* The slot and the coin, each an integer on the LIGHT_PICK_GRID: every sampler's numbers
 * fall on it the same way, and build_light_alias_table gives each light's pmf (radiance.w)
 * exactly as this picks it, down to lights far rarer than one grid step. */
static inline int light_pick(__global const Light* lights, uint count, float u_index, float u_alias)
{
    uint k = min((uint)(u_index * (float)LIGHT_PICK_GRID), LIGHT_PICK_GRID - 1u);
    int i = (int)(((ulong)k * count) >> 24);
    uint coin = min((uint)(u_alias * (float)LIGHT_PICK_GRID), LIGHT_PICK_GRID - 1u);
    return (coin < lights[i].alias_threshold) ? i : lights[i].alias;
}

/* Solid-angle pdf of reaching a point on triangle light `light` from a point dist away,
 * where cos_light is the cosine at the light: selection pmf / (area * cos / d^2). */
static inline float triangle_light_pdf(const Light* light, float dist, float cos_light)
{
    if (cos_light <= 0.0f)
        return 0.0f;
    return light->radiance.w * dist * dist / (light->p0.w * cos_light);
}

/* Angular factor of a spot light for light leaving along unit direction `out`. */
static inline float spot_falloff(const Light* light, float3 out)
{
#ifdef PATHCL_HAS_SPOT_LIGHTS
    float3 axis = light->p1.xyz;
    float z = dot(out, axis);
    if (light->type == LIGHT_SPOT) {
        /* KHR_lights_punctual: t = clamp((cos - cos_outer) / max(0.001, cos_inner - cos_outer)) */
        float t = clamp((z - light->p2.x) / fmax(0.001f, light->p2.y - light->p2.x), 0.0f, 1.0f);
        return t * t;
    }
    if (light->type == LIGHT_RECT_SPOT) {
        /* Inside the frustum |x/z| <= tan(hfov/2), |y/z| <= tan(vfov/2): full intensity. */
        float3 right = light->p2.xyz;
        float3 up = cross(right, axis);
        if (!(z > 0.0f))
            return 0.0f;
        bool inside = fabs(dot(out, right)) <= light->p2.w * z && fabs(dot(out, up)) <= light->p1.w * z;
        return inside ? 1.0f : 0.0f;
    }
#endif
    return 1.0f;
}

static inline LightSample light_sample(__global const Light* lights, uint count, const EnvironmentBuffers* env,
                                       const TextureBuffers* tex, float3 ref, SamplerState* sampler)
{
    LightSample ls;
    ls.pdf = 0.0f;
    ls.delta = false;
    ls.at_infinity = false;
    ls.p_error = (float3)(0.0f);
    ls.radiance = (float3)(0.0f);
    ls.wi = ls.n = ls.p = (float3)(0.0f);
    float u_index = sampler_get_1d(sampler);
    float u_alias = sampler_get_1d(sampler);
    float2 u = sampler_get_2d(sampler);
    Light light = lights[light_pick(lights, count, u_index, u_alias)];

#ifdef PATHCL_HAS_ENVIRONMENT
    if (light.type == LIGHT_ENVIRONMENT) {
        ls.at_infinity = true;
        ls.radiance = environment_sample(&light, env, u, &ls.wi, &ls.pdf);
        ls.p = ref; /* unused */
        ls.n = -ls.wi;
        return ls;
    }
#endif
#ifdef PATHCL_HAS_SPHERE_LIGHTS
    if (light.type == LIGHT_SPHERE) {
        /* Uniform direction in the cone the sphere subtends (pbrt's sphere sampling). */
        float3 c = light.p0.xyz;
        float r = light.p0.w;
        float3 to_centre = c - ref;
        float dc2 = dot(to_centre, to_centre);
        if (!(dc2 > r * r))
            return ls; /* inside the sphere: it is not seen from here */
        float dc = sqrt(dc2);
        float omc = sphere_cone_one_minus_cos(r, dc2);
        float one_minus_cos_theta = u.x * omc;
        float cos_theta = 1.0f - one_minus_cos_theta;
        float sin2_theta = one_minus_cos_theta * (2.0f - one_minus_cos_theta);
        float sin_theta = sqrt(fmax(0.0f, sin2_theta));
        float3 axis = to_centre / dc, t, b;
        make_basis(axis, &t, &b);
        float cos_phi, sin_phi = sin_cos_turns(u.y, &cos_phi); /* phi = 2 pi u.y */
        ls.wi = normalize(sin_theta * cos_phi * t + sin_theta * sin_phi * b + cos_theta * axis);
        /* Distance to the near side of the sphere along wi. */
        float ds = dc * cos_theta - sqrt(fmax(0.0f, r * r - dc2 * sin2_theta));
        ls.p = ref + ds * ls.wi;
        ls.n = normalize(ls.p - c);
        ls.p_error = FLOAT_GAMMA(16) * (fabs(ref) + fabs(c) + (float3)(r));
        ls.radiance = light.radiance.xyz;
        ls.pdf = light.radiance.w / (2.0f * PI_F * omc);
        return ls;
    }
#endif
#ifdef PATHCL_HAS_DIRECTIONAL_LIGHTS
    if (light.type == LIGHT_DIRECTIONAL) {
        ls.delta = true;
        ls.at_infinity = true;
        ls.wi = -light.p1.xyz;
        ls.p = ref; /* unused */
        ls.n = light.p1.xyz;
        ls.radiance = light.radiance.xyz;
        ls.pdf = light.radiance.w;
        return ls;
    }
#endif
#if defined(PATHCL_HAS_POINT_LIGHTS) || defined(PATHCL_HAS_SPOT_LIGHTS)
    if (light.type == LIGHT_POINT || light.type == LIGHT_SPOT || light.type == LIGHT_RECT_SPOT) {
        ls.delta = true;
        ls.p = light.p0.xyz;
        float3 to_light = ls.p - ref;
        float d2 = dot(to_light, to_light);
        if (!(d2 > 0.0f))
            return ls;
        ls.wi = to_light * rsqrt(d2);
        ls.n = -ls.wi;
        float falloff = spot_falloff(&light, -ls.wi);
        if (!(falloff > 0.0f))
            return ls;
        ls.radiance = light.radiance.xyz * (falloff / d2);
        ls.pdf = light.radiance.w;
        return ls;
    }
#endif
#ifdef PATHCL_HAS_AREA_LIGHTS
    /* Uniform point on the triangle (square-root parameterization). */
    float su = sqrt(u.x);
    float b1 = 1.0f - su;
    float b2 = u.y * su;
    float3 v0 = light.p0.xyz, v1 = light.p1.xyz, v2 = light.p2.xyz;
    ls.p = barycentric_point(v0, v1, v2, b1, b2, &ls.p_error);
    ls.n = normalize(cross(v1 - v0, v2 - v0));
    float3 to_light = ls.p - ref;
    float dist = length(to_light);
    if (!(dist > 0.0f))
        return ls;
    ls.wi = to_light / dist;
    float cos_light = -dot(ls.wi, ls.n);
    ls.pdf = triangle_light_pdf(&light, dist, cos_light);
    ls.radiance = (ls.pdf > 0.0f) ? light.radiance.xyz : (float3)(0.0f);
#ifdef PATHCL_HAS_TEXTURES
    /* The emissive texture at the sampled point, as a ray hitting it would see it. */
    if (light.texture != TEXTURE_NONE && ls.pdf > 0.0f)
        ls.radiance *= texture_at(tex, light.texture, as_int(light.p1.w), b1, b2).xyz;
#endif
#endif
    return ls;
}
