/* Light selection and sampling. Needs: shared_types.h, samplers.cl, geometry.cl.
 * Lights are picked in proportion to their emitted power through an alias table (O(1));
 * each light's selection probability is in radiance.w, which MIS needs for BSDF-found
 * hits on the light too. */

typedef struct {
    float3 p;       /* point on the light */
    float3 p_error;
    float3 n;       /* light surface normal (front side) */
    float3 radiance; /* emitted towards the shading point; 0 if facing away */
    float pdf;       /* solid angle at the shading point, selection included; 0: none */
} LightSample;

inline int light_pick(__global const Light* lights, uint count, float u_index, float u_alias)
{
    int i = min((int)(u_index * (float)count), (int)count - 1);
    return (u_alias < lights[i].alias_threshold) ? i : lights[i].alias;
}

/* Solid-angle pdf of reaching a point on triangle light `light` from a point dist away,
 * where cos_light is the cosine at the light: selection pmf / (area * cos / d^2). */
inline float triangle_light_pdf(const Light* light, float dist, float cos_light)
{
    if (cos_light <= 0.0f)
        return 0.0f;
    return light->radiance.w * dist * dist / (light->p0.w * cos_light);
}

inline LightSample light_sample(__global const Light* lights, uint count, float3 ref,
                                SamplerState* sampler)
{
    LightSample ls;
    ls.pdf = 0.0f;
    float u_index = sampler_get_1d(sampler);
    float u_alias = sampler_get_1d(sampler);
    float2 u = sampler_get_2d(sampler);
    Light light = lights[light_pick(lights, count, u_index, u_alias)];
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
    float cos_light = -dot(to_light, ls.n) / dist;
    ls.pdf = triangle_light_pdf(&light, dist, cos_light);
    ls.radiance = (ls.pdf > 0.0f) ? light.radiance.xyz : (float3)(0.0f);
    return ls;
}
