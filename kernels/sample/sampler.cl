/* Samplers: where every random decision of a path gets its numbers.
 *
 * A decision asks for one number (sampler_get_1d) or a pair (sampler_get_2d) at an
 * explicit dimension index (the camera and the integrator assign each decision its own
 * dimension(s); see sample/dimensions.h). A value depends only on
 * (sampler, spp, seed, pixel, sample index, dimension), never on which work-item, pass
 * or device computed it, so renders are reproducible and samples can be dealt to
 * devices in any order.
 *
 * Every sampler but independent and Halton is "padded" (pbrt-v4's term): the decision at
 * dimension d draws from its own point set of spp points for this pixel (a 1D set for
 * sampler_get_1d, a 2D set for the pair (d, d+1) for sampler_get_2d), and the pixel's
 * sample index is mapped to a point of that set through a random permutation seeded by
 * (seed, pixel, d). Each set is stratified on its own; the independent permutations keep
 * sets of different dimensions from correlating.
 *
 *   independent     a hash of (seed, pixel, sample, dimension)
 *   jittered        cols x rows strata (cols = floor(sqrt(spp)), rows = ceil(spp / cols):
 *                   sqrt(spp) x sqrt(spp) for the square spp the host rounds to), one
 *                   uniform point in each; 1D: spp strata
 *   multi-jittered  Kensler's correlated multi-jittered construction (jittered in 2D and
 *                   one sample per each of the spp columns and rows); 1D: spp strata
 *   n-rooks         one sample in each of spp columns and spp rows (Latin hypercube),
 *                   independent permutations for x and y; 1D: spp strata
 *   sobol           the first two Sobol' dimensions (van der Corput and the Pascal-matrix
 *                   dimension), each Owen-scrambled with Burley's hash (2020); index
 *                   permuted per set. For spp = 2^m each 2D set is a (0,m,2)-net.
 *   halton          dimension d is the radical inverse in the d-th prime base (256
 *                   bases, then they repeat with independent scrambles), each digit
 *                   permuted by a random permutation seeded by the digits above it
 *                   (nested, Owen-style scrambling; base 2 by Burley's hash) down to
 *                   the level that tells the spp points apart, then a uniform offset;
 *                   not padded: the sample index is used as is.
 *   hammersley      (i / spp, radical inverse base 2 of i), both Owen-scrambled; index
 *                   permuted per set. For spp = 2^m (the host rounds to it) a (0,m,2)-net.
 * Owen scrambling and the index permutations are seeded per (seed, pixel, dimension), so
 * neighbouring pixels get independent point sets (no structured aliasing). */
#include "sample/dimensions.h"
#include "sample/halton.cl"
#include "sample/permute.cl"
#include "sample/sobol.cl"
#include "sample/strata.h"
#include "types.h"
#include "util/compat.h"
#include "util/hash.cl"

/* How many numbers sampler_draw_bounce draws at once: all eight decisions of a bounce
 * (DIMS_PER_BOUNCE, sample/dimensions.h). Eight 32-bit lanes are one AVX2 register;
 * sixteen (AVX-512) ran slower than eight in `pathcl bench` on an Intel Xeon under PoCL 3.1,
 * likely for the lower clock the processor runs 512-bit instructions at. */
#define SAMPLER_LANES 8u

typedef struct {
    uint pixel;
    uint sample;
    uint seed;
    uint dimension;       /* next dimension to hand out */
    uint type;            /* SAMPLER_* */
    uint spp;             /* size of the point sets (the render's samples per pixel) */
    uint sample_key;      /* hash of (seed, pixel, sample): every draw extends it by the dimension */
    uint set_key;         /* hash of (seed, pixel): the point sets' seeds extend it */
    uint stratified_dims; /* decisions at dimensions >= this take independent numbers */
    /* A bounce's numbers drawn at once (sampler_draw_bounce): block[k] is the value at
     * dimension block_start + k for k < block_count (0: no block), laid out as
     * DIM_PAIRS_IN_BOUNCE says. */
    uint block_start, block_count;
    float block[SAMPLER_LANES];
} SamplerState;

/* A sampler state for (pixel, sample) starting at `dimension`. */
static inline SamplerState sampler_start_typed(uint type, uint spp, uint pixel, uint sample, uint seed, uint dimension)
{
    SamplerState s;
    s.pixel = pixel;
    s.sample = sample;
    s.seed = seed;
    s.dimension = dimension;
    s.type = type;
    s.spp = spp;
    /* The fixed part of every hash this state draws, computed once. The independent
     * sampler's number for dimension d (also the jitter inside the stratified samplers'
     * strata) is hash_combine(sample_key, d); the point set of (seed, pixel, d) is seeded
     * by hash_combine(hash_combine(set_key, d), k), k picking one of several. */
    s.sample_key = hash_combine(hash_combine(hash_u32(seed), pixel), sample);
    s.set_key = hash_combine(hash_u32(seed ^ 0x5bd1e995u), pixel);
    s.stratified_dims = 0xffffffffu;
    s.block_start = 0u;
    s.block_count = 0u;
    return s;
}

/* Plain counter-based random numbers (the independent sampler), for code that is not a
 * path's decision (test kernels). */
static inline SamplerState sampler_start(uint pixel, uint sample, uint seed, uint dimension)
{
    return sampler_start_typed(SAMPLER_INDEPENDENT, 1u, pixel, sample, seed, dimension);
}

/* The sampler a render pass uses (frame->sampler, frame->spp, frame->sample_index): the
 * decisions at dimensions below frame->stratified_dims (the camera's and those of the
 * first bounces) take the sampler's stratified sets, the deeper ones independent numbers.
 * Nearly all of a stratified sampler's gain is in the first bounce's decisions (direct
 * light at the first hit), while every stratified decision costs more than an
 * independent one (docs/accuracy.md, "On the committed scenes": stratified bounces). */
static inline SamplerState frame_sampler(const FrameParams* frame, uint pixel, uint dimension)
{
    SamplerState s =
        sampler_start_typed(frame->sampler, frame->spp, pixel, frame->sample_index, frame->seed, dimension);
    s.stratified_dims = frame->stratified_dims;
    return s;
}

/* Draws the numbers of the decisions of the bounce whose dimensions start at `start` at
 * once, SAMPLER_LANES of them in the lanes of a uint8, where the sampler is the
 * independent one or Sobol' (or every decision of the bounce takes independent numbers);
 * the others are drawn one by one when asked for. The values are those the decisions
 * would get one by one, bit for bit (the same formulas, written once in util/hash.cl,
 * sample/permute.cl and sample/sobol.cl), laid out as DIM_PAIRS_IN_BOUNCE says: a 2D
 * decision's pair is one 2D set, its first number that of a 1D decision at the same
 * dimension. On a CPU the lanes run as a few vector instructions where one by one the
 * hashes, the permutations and the scrambles run as scalar code per decision. */
static inline void sampler_draw_bounce(SamplerState* s, uint start)
{
    bool all_independent = s->type == SAMPLER_INDEPENDENT || start >= s->stratified_dims;
    if (!all_independent && s->type != SAMPLER_SOBOL)
        return;
    uint8 lane = (uint8)(0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u);
    uint8 dim = (uint8)(start) + lane;
    uint8 value = hash_combine_8((uint8)(s->sample_key), dim); /* the independent sampler's */
    if (!all_independent) {
        /* Sobol' (sampler_value_1d and _2d): a lane is its decision's first number or a
         * pair's second, taken from the pair's set at the dimension before it. */
        uint8 second = ((uint8)(DIM_PAIR_SECONDS_IN_BOUNCE) >> lane) & (uint8)(1u);
        uint8 decision = dim - second;
        uint8 set = hash_combine_8((uint8)(s->set_key), decision);
        uint8 index = permute_element_8(s->sample, max(s->spp, 1u), hash_combine_8(set, (uint8)(0u)));
        uint8 point = select(index, sobol_dimension1_reversed_u32_8(index), second != (uint8)(0u));
        uint8 sobol = owen_scramble_reversed_u32_8(point, hash_combine_8(set, (uint8)(1u) + second));
        value = select(value, sobol, decision < (uint8)(s->stratified_dims));
    }
    vstore8(convert_float8(value >> 8) * 0x1.0p-24f, 0, s->block); /* u32_to_unit_float */
    s->block_start = start;
    s->block_count = min((uint)DIMS_PER_BOUNCE, SAMPLER_LANES);
}

/* The sampler of a path's bounce whose decisions start at dimension `start`, made from
 * the path's sampler (frame_sampler, once per path: its keys are the same at every
 * bounce), its numbers drawn at once where sampler_draw_bounce can (the same values as
 * frame_sampler's). */
static inline SamplerState sampler_bounce(const SamplerState* path, uint start)
{
    SamplerState s = *path;
    s.dimension = start;
    sampler_draw_bounce(&s, start);
    return s;
}

/* The independent sampler's pair at (dim, dim + 1): also the jitter inside a stratum. */
static inline float2 sampler_jitter_2d(const SamplerState* s, uint dim)
{
    return (float2)(u32_to_unit_float(hash_combine(s->sample_key, dim)),
                    u32_to_unit_float(hash_combine(s->sample_key, dim + 1u)));
}

static inline float halton_value(const SamplerState* s, uint dim)
{
    uint base = HALTON_PRIMES[dim % 256u];
    uint seed = hash_combine(hash_combine(s->set_key, dim), 0u);
    /* Base 2: Burley's hash-based Owen scramble of the bit-reversed index does the same
     * nested scrambling in one pass instead of one permutation per digit. */
    if (base == 2u)
        return u32_to_unit_float(owen_scramble_reversed_u32(s->sample, seed));
    return radical_inverse(base, s->sample, max(s->spp, 1u), seed, true);
}

PATHCL_NOINLINE static float sampler_value_1d(const SamplerState* s, uint dim)
{
    uint n = max(s->spp, 1u);
    uint set = hash_combine(s->set_key, dim); /* this decision's point set */
    switch (s->type) {
    case SAMPLER_JITTERED:
    case SAMPLER_MULTI_JITTERED:
    case SAMPLER_N_ROOKS:
        /* One sample in each of spp strata. */
        return stratum_point(permute_element(s->sample, n, hash_combine(set, 0u)), n,
                             u32_to_unit_float(hash_combine(s->sample_key, dim)));
    case SAMPLER_SOBOL: {
        uint index = permute_element(s->sample, n, hash_combine(set, 0u));
        return u32_to_unit_float(owen_scramble_reversed_u32(index, hash_combine(set, 1u)));
    }
    case SAMPLER_HAMMERSLEY: {
        uint index = permute_element(s->sample, n, hash_combine(set, 0u));
        uint x = (uint)(((ulong)index << 32) / n); /* index / n as a 32-bit fraction */
        return u32_to_unit_float(owen_scramble_u32(x, hash_combine(set, 1u)));
    }
    case SAMPLER_HALTON:
        return halton_value(s, dim);
    default: /* SAMPLER_INDEPENDENT */
        return u32_to_unit_float(hash_combine(s->sample_key, dim));
    }
}

PATHCL_NOINLINE static float2 sampler_value_2d(const SamplerState* s, uint dim)
{
    uint n = max(s->spp, 1u);
    uint set = hash_combine(s->set_key, dim); /* this decision's point set */
    switch (s->type) {
    case SAMPLER_JITTERED: {
        /* A random stratum of the cols x rows grid per sample index (a permutation, so each
         * stratum once); with fewer samples than strata the unused strata are random too,
         * which keeps the estimate unbiased. */
        uint cols = strata_cols(n), rows = strata_rows(n, cols);
        uint cell = permute_element(s->sample, cols * rows, hash_combine(set, 0u));
        float2 xi = sampler_jitter_2d(s, dim);
        return (float2)(stratum_point(cell % cols, cols, xi.x), stratum_point(cell / cols, rows, xi.y));
    }
    case SAMPLER_MULTI_JITTERED: {
        /* Kensler's correlated multi-jittered sampling: sample in coarse cell (cx, cy) of
         * the cols x rows grid; its column is subdivided into rows sub-columns and the
         * sub-column is a permutation of the row (the same for every column: correlated),
         * and likewise for rows. Every coarse cell, every one of the cols*rows fine
         * columns and every fine row holds one sample. */
        uint cols = strata_cols(n), rows = strata_rows(n, cols), cells = cols * rows;
        uint cell = permute_element(s->sample, cells, hash_combine(set, 0u));
        uint cx = cell % cols, cy = cell / cols;
        uint sx = permute_element(cx, cols, hash_combine(set, 1u));
        uint sy = permute_element(cy, rows, hash_combine(set, 2u));
        float2 xi = sampler_jitter_2d(s, dim);
        return (float2)(stratum_point(cx * rows + sy, cells, xi.x), stratum_point(cy * cols + sx, cells, xi.y));
    }
    case SAMPLER_N_ROOKS: {
        float2 xi = sampler_jitter_2d(s, dim);
        return (float2)(stratum_point(permute_element(s->sample, n, hash_combine(set, 0u)), n, xi.x),
                        stratum_point(permute_element(s->sample, n, hash_combine(set, 1u)), n, xi.y));
    }
    case SAMPLER_SOBOL: {
        uint index = permute_element(s->sample, n, hash_combine(set, 0u));
        return (float2)(u32_to_unit_float(owen_scramble_reversed_u32(index, hash_combine(set, 1u))),
                        u32_to_unit_float(
                            owen_scramble_reversed_u32(sobol_dimension1_reversed_u32(index), hash_combine(set, 2u))));
    }
    case SAMPLER_HAMMERSLEY: {
        uint index = permute_element(s->sample, n, hash_combine(set, 0u));
        uint x = (uint)(((ulong)index << 32) / n);
        return (float2)(u32_to_unit_float(owen_scramble_u32(x, hash_combine(set, 1u))),
                        u32_to_unit_float(owen_scramble_reversed_u32(index, hash_combine(set, 2u))));
    }
    case SAMPLER_HALTON:
        return (float2)(halton_value(s, dim), halton_value(s, dim + 1u));
    default: /* SAMPLER_INDEPENDENT */
        return sampler_jitter_2d(s, dim);
    }
}

/* The value for the decision at s->dimension; advances by one dimension. */
PATHCL_ALWAYS_INLINE static inline float sampler_get_1d(SamplerState* s)
{
    uint dim = s->dimension;
    s->dimension += 1u;
    uint k = dim - s->block_start;                                     /* wraps below the block */
    if (k < s->block_count && !(DIM_PAIR_SECONDS_IN_BOUNCE >> k & 1u)) /* not a pair's second number */
        return s->block[k];
    if (s->type == SAMPLER_INDEPENDENT || dim >= s->stratified_dims) /* kept small enough to inline */
        return u32_to_unit_float(hash_combine(s->sample_key, dim));
    return sampler_value_1d(s, dim);
}

/* The pair for the 2D decision at (s->dimension, s->dimension + 1); advances by two. */
PATHCL_ALWAYS_INLINE static inline float2 sampler_get_2d(SamplerState* s)
{
    uint dim = s->dimension;
    s->dimension += 2u;
    uint k = dim - s->block_start;
    if (k < s->block_count && (DIM_PAIRS_IN_BOUNCE >> k & 1u)) /* a pair of the layout */
        return (float2)(s->block[k], s->block[k + 1u]);
    if (s->type == SAMPLER_INDEPENDENT || dim >= s->stratified_dims)
        return (float2)(u32_to_unit_float(hash_combine(s->sample_key, dim)),
                        u32_to_unit_float(hash_combine(s->sample_key, dim + 1u)));
    return sampler_value_2d(s, dim);
}
