/* The state a path carries from one bounce to the next. Every stage of the integrator
 * (the files of integrator/, called in order by integrator/megakernel.cl) reads and writes it. */
#include "features.h"
#include "types.h"

typedef struct {
    float3 origin, dir;       /* the ray the path follows next */
    float3 radiance;          /* L gathered so far */
    float3 beta;              /* throughput: f cos / pdf along the path (and roulette's 1/q) */
    float eta2_product;       /* product of the eta^2 that beta holds the inverse of */
    float prev_bsdf_pdf;      /* pdf of the BSDF sample that made the ray */
    bool prev_delta;          /* it came from the camera or a delta lobe: emission has full weight */
    bool prev_technique_bsdf; /* one-sample MIS: the coin chose the BSDF technique */
#ifdef PATHCL_HAS_VOLUME_ABSORPTION
    int medium; /* the solid the ray travels inside (its material), -1: outside every solid */
#endif
#ifdef PATHCL_HAS_UNLIT
    bool specular_chain; /* every bounce so far was a delta lobe: unlit surfaces are seen */
#endif
#ifdef PATHCL_KEEPS_PREV_REF
    float3 prev_ref; /* the point the ray left from: the light tree's pmf and a triangle's solid
                      * angle for a light the ray hits are the ones a light sample there had */
#endif
#ifdef PATHCL_LIGHT_TREE
    float3 prev_n; /* and its shading normal, which the light tree weighs */
#endif
} PathState;

/* A path starting along a camera ray. */
static inline PathState path_state_start(Ray ray)
{
    PathState ps;
    ps.origin = ray.origin.xyz;
    ps.dir = ray.direction.xyz;
    ps.radiance = (float3)(0.0f);
    ps.beta = (float3)(1.0f);
    ps.eta2_product = 1.0f;
    ps.prev_bsdf_pdf = 0.0f;
    ps.prev_delta = true; /* camera rays see emission with full weight */
    ps.prev_technique_bsdf = true;
#ifdef PATHCL_HAS_VOLUME_ABSORPTION
    ps.medium = -1; /* cameras are outside every solid */
#endif
#ifdef PATHCL_HAS_UNLIT
    ps.specular_chain = true;
#endif
#ifdef PATHCL_KEEPS_PREV_REF
    ps.prev_ref = (float3)(0.0f); /* read only after a non-delta bounce */
#endif
#ifdef PATHCL_LIGHT_TREE
    ps.prev_n = (float3)(0.0f);
#endif
    return ps;
}
