/* Sampler dimensions: every random decision of a path has its own. A 1D decision takes
 * one dimension, a 2D decision the pair (d, d + 1), drawn as one 2D point set. A
 * bounce's decisions sit at fixed offsets, so a path's numbers never depend on which
 * branches earlier bounces took. The camera consumes the first four; bounce k's decisions
 * start at DIM_PATH_START + k * DIMS_PER_BOUNCE. (The sample visualizer and the README
 * name dimensions by these numbers.) */
#ifndef PATHCL_SAMPLE_DIMENSIONS_H
#define PATHCL_SAMPLE_DIMENSIONS_H

#define DIM_PIXEL 0 /* 2: film position inside the pixel */
#define DIM_LENS 2  /* 2: lens position (thin lens) */
#define DIM_PATH_START 4
#define DIMS_PER_BOUNCE 9

/* Offsets within a bounce. The sampler draws the first eight at once (sampler.cl), so
 * the one decision that the default strategy never makes, one-sample MIS's coin, is last. */
#define DIM_BSDF_LOBE 0 /* 1: BSDF lobe */
#define DIM_LIGHT 1     /* 4: light pick (index, alias coin) and the point on it (2) */
#define DIM_BSDF 5      /* 2: BSDF direction */
#define DIM_RR 7        /* 1: Russian roulette */
#define DIM_TECHNIQUE 8 /* 1: one-sample MIS's coin */

/* The offsets within a bounce where a 2D decision starts (the point on the light and the
 * BSDF direction); the others are 1D decisions. The sampler draws a bounce's numbers at
 * once by this layout (sample/sampler.cl, sampler_draw_bounce). */
#define DIM_PAIRS_IN_BOUNCE ((1u << (DIM_LIGHT + 2)) | (1u << DIM_BSDF))
/* The offsets that hold the second number of such a pair. */
#define DIM_PAIR_SECONDS_IN_BOUNCE (DIM_PAIRS_IN_BOUNCE << 1)

#endif
