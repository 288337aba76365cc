/* What a light sample carries to the integrator (LightSample), filled by the per-type
 * samplers in light/ and dispatched by light/light_sample.cl. */

typedef struct {
    float3 p;         /* point on the light (position for point lights) */
    float3 p_error;   /* rounding bound on p (0 for positions given exactly) */
    float3 n;         /* area lights: surface normal on the emitting side */
    float3 wi;        /* unit direction from the shading point towards the light */
    float3 radiance;  /* what arrives: area lights: radiance; delta lights: irradiance
                       * at normal incidence (I / d^2, or E) */
    float pdf;        /* solid angle for area lights, selection included; delta lights:
                       * selection probability only; 0: no sample */
    bool delta;       /* cannot be hit by a ray (point, spot, directional) */
    bool at_infinity; /* directional: the shadow ray is unbounded */
} LightSample;
