/* The wavefront integrator's path state: a structure of arrays, one 32-bit word per field
 * and path, declared once here for the kernels and the host (as Cycles'
 * kernel/integrator/state_template.h). Field f of slot p is word f * capacity + p of one
 * buffer, so that the LANES paths of a shading work-item read and write each field as one
 * vector (wavefront/lanes.cl), and consecutive work-items touch consecutive words (the
 * coalesced access GPUs need). Every field is a scalar.
 *
 * PATHCL_WAVEFRONT_STATE(X) calls X(name) for each field; a field is a float or an int
 * by the accessor the kernels use (wavefront/state_access.cl). 37 fields: 148 bytes a
 * path. */
#ifndef PATHCL_WAVEFRONT_PATH_STATE_H
#define PATHCL_WAVEFRONT_PATH_STATE_H

/* clang-format off */
#define PATHCL_WAVEFRONT_STATE(X)                                                                                      \
    /* the ray the path follows next */                                                                                \
    X(ray_ox) X(ray_oy) X(ray_oz) X(ray_dx) X(ray_dy) X(ray_dz)                                                        \
    /* throughput and radiance gathered so far (integrator/path_state.cl's PathState) */                              \
    X(beta_r) X(beta_g) X(beta_b) X(radiance_r) X(radiance_g) X(radiance_b)                                            \
    X(prev_bsdf_pdf) /* pdf of the BSDF sample that made the ray */                                                    \
    X(flags)         /* int: WAVEFRONT_PREV_DELTA, WAVEFRONT_PREV_TECHNIQUE_BSDF */                                    \
    /* the ray's closest hit (extend stage); triangle -1: it missed */                                                 \
    X(hit_t) X(hit_triangle) X(hit_b1) X(hit_b2)                                                                       \
    /* the bounce's sampler numbers (extend stage; sample/dimensions.h) */                                             \
    X(u_bsdf0) X(u_bsdf1) X(u_rr) X(u_technique)                                                                       \
    /* the light next event estimation picked (int) and the numbers of its point */                                    \
    X(light) X(light_u0) X(light_u1)                                                                                   \
    /* the shadow ray and what it carries if nothing blocks it; shadow_t_max < 0: none */                              \
    X(shadow_ox) X(shadow_oy) X(shadow_oz) X(shadow_dx) X(shadow_dy) X(shadow_dz) X(shadow_t_max)                      \
    X(shadow_r) X(shadow_g) X(shadow_b)                                                                                \
    X(alive) /* int: 1 while the path goes on */                                                                       \
    X(pixel) /* int: the image pixel the path belongs to */
/* clang-format on */

#define PATHCL_WAVEFRONT_FIELD_ENUM(name) WAVEFRONT_##name,
enum { PATHCL_WAVEFRONT_STATE(PATHCL_WAVEFRONT_FIELD_ENUM) WAVEFRONT_FIELD_COUNT };
#undef PATHCL_WAVEFRONT_FIELD_ENUM

/* flags */
#define WAVEFRONT_PREV_DELTA 1          /* the ray came from the camera or a delta lobe */
#define WAVEFRONT_PREV_TECHNIQUE_BSDF 2 /* one-sample MIS: the coin chose the BSDF technique */

#endif
