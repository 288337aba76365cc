/* Sampler dimensions: every random decision of a path has its own. A 1D decision takes
 * one dimension, a 2D decision the pair (d, d + 1), drawn as one 2D point set. A
 * bounce's decisions sit at fixed offsets, so a path's numbers never depend on which
 * branches earlier bounces took. The camera consumes the first four; bounce k's decisions
 * start at DIM_PATH_START + k * DIMS_PER_BOUNCE. (The sample visualizer and
 * docs/cameras-and-samplers.md name dimensions by these numbers.) */
#ifndef PATHCL_SAMPLE_DIMENSIONS_H
#define PATHCL_SAMPLE_DIMENSIONS_H

#define DIM_PIXEL 0 /* 2: film position inside the pixel */
#define DIM_LENS 2  /* 2: lens position (thin lens) */
#define DIM_PATH_START 4
#define DIMS_PER_BOUNCE 8

/* Offsets within a bounce; the sampler draws all eight at once (sampler.cl). */
#define DIM_BSDF_LOBE 0 /* 1: BSDF lobe */
#define DIM_LIGHT 1     /* 3: the light pick's alias coin, then the point on the light (2) */
#define DIM_BSDF 4      /* 2: BSDF direction */
#define DIM_RR 6        /* 1: Russian roulette */
#define DIM_TECHNIQUE 7 /* 1: one-sample MIS's coin */
/* The point's pair. Its first number also picks the light's slot and is then rescaled
 * within it (light/light_pick.cl), so each light's points stay a stratified share of one
 * 2D set instead of a random subset drawn by a dimension of its own. */
#define DIM_LIGHT_POINT (DIM_LIGHT + 1)

/* The offsets within a bounce where a 2D decision starts (the point on the light and the
 * BSDF direction); the others are 1D decisions. The sampler draws a bounce's numbers at
 * once by this layout (sample/sampler.cl, sampler_draw_bounce). */
#define DIM_PAIRS_IN_BOUNCE ((1u << DIM_LIGHT_POINT) | (1u << DIM_BSDF))
/* The offsets that hold the second number of such a pair. */
#define DIM_PAIR_SECONDS_IN_BOUNCE (DIM_PAIRS_IN_BOUNCE << 1)

/* Changes whenever the layout above does: a render's key holds it (host/render/
 * renderer.cpp), so sample ranges rendered with different layouts never merge. 2: the
 * light's slot taken from the light point's first number; 1: from a dimension of its own. */
#define DIM_LAYOUT_VERSION 2

#endif
