/* Punctual lights (KHR_lights_punctual): point, cone spot, rectangular spot and
 * directional. They are delta lights: never hit by a ray, sampled exactly (a shadow ray
 * to the position, or along the direction), with the spot's angular falloff. */
#include "features.h"
#include "light/light_sample_record.cl"
#include "types.h"

#if defined(PATHCL_HAS_POINT_LIGHTS) || defined(PATHCL_HAS_SPOT_LIGHTS)

/* Angular factor of a spot light for light leaving along unit direction `out`. */
static inline float spot_falloff(const Light* light, float3 out)
{
#ifdef PATHCL_HAS_SPOT_LIGHTS
    if (light->type == LIGHT_SPOT) {
        /* KHR_lights_punctual: t = clamp((cos - cos_outer) / max(0.001, cos_inner - cos_outer)) */
        const SpotLight* spot = &light->data.spot;
        float z = dot(out, spot->axis.xyz);
        float t = clamp((z - spot->cos_outer) / fmax(0.001f, spot->cos_inner - spot->cos_outer), 0.0f, 1.0f);
        return t * t;
    }
    if (light->type == LIGHT_RECT_SPOT) {
        /* Inside the frustum |x/z| <= tan(hfov/2), |y/z| <= tan(vfov/2): full intensity. */
        const RectSpotLight* spot = &light->data.rect_spot;
        float3 axis = spot->axis.xyz;
        float z = dot(out, axis);
        float3 right = spot->right.xyz;
        float3 up = cross(right, axis);
        if (!(z > 0.0f))
            return 0.0f;
        bool inside = fabs(dot(out, right)) <= spot->tan_half_h * z && fabs(dot(out, up)) <= spot->tan_half_v * z;
        return inside ? 1.0f : 0.0f;
    }
#endif
    return 1.0f;
}

/* Where a point or spot light sits. */
static inline float3 punctual_position(const Light* light)
{
    if (light->type == LIGHT_SPOT)
        return light->data.spot.position.xyz;
    if (light->type == LIGHT_RECT_SPOT)
        return light->data.rect_spot.position.xyz;
    return light->data.point.position.xyz;
}

/* The shadow ray to a point or spot light: irradiance I falloff / d^2. */
static inline void sample_point_light(const Light* light, float pmf, float3 ref, LightSample* ls)
{
    ls->delta = true;
    ls->p = punctual_position(light);
    float3 to_light = ls->p - ref;
    float d2 = dot(to_light, to_light);
    if (!(d2 > 0.0f))
        return;
    ls->wi = to_light * rsqrt(d2);
    ls->n = -ls->wi;
    float falloff = spot_falloff(light, -ls->wi);
    if (!(falloff > 0.0f))
        return;
    ls->radiance = light->radiance.xyz * (falloff / d2);
    ls->pdf = pmf;
}

#endif

#ifdef PATHCL_HAS_DIRECTIONAL_LIGHTS

/* The unbounded shadow ray against a directional light's direction: irradiance E. */
static inline void sample_directional_light(const Light* light, float pmf, float3 ref, LightSample* ls)
{
    ls->delta = true;
    ls->at_infinity = true;
    ls->wi = -light->data.directional.direction.xyz;
    ls->p = ref; /* unused */
    ls->n = light->data.directional.direction.xyz;
    ls->radiance = light->radiance.xyz;
    ls->pdf = pmf;
}

#endif
