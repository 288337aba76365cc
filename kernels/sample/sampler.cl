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
#include "util/hash.cl"

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
 * light at the first hit), while every stratified decision costs about six times an
 * independent one (README "Samplers"). */
static inline SamplerState frame_sampler(const FrameParams* frame, uint pixel, uint dimension)
{
    SamplerState s =
        sampler_start_typed(frame->sampler, frame->spp, pixel, frame->sample_index, frame->seed, dimension);
    s.stratified_dims = frame->stratified_dims;
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

static inline float sampler_value_1d(const SamplerState* s, uint dim)
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

static inline float2 sampler_value_2d(const SamplerState* s, uint dim)
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
static inline float sampler_get_1d(SamplerState* s)
{
    uint dim = s->dimension;
    s->dimension += 1u;
    if (s->type == SAMPLER_INDEPENDENT || dim >= s->stratified_dims) /* kept small enough to inline */
        return u32_to_unit_float(hash_combine(s->sample_key, dim));
    return sampler_value_1d(s, dim);
}

/* The pair for the 2D decision at (s->dimension, s->dimension + 1); advances by two. */
static inline float2 sampler_get_2d(SamplerState* s)
{
    uint dim = s->dimension;
    s->dimension += 2u;
    if (s->type == SAMPLER_INDEPENDENT || dim >= s->stratified_dims)
        return (float2)(u32_to_unit_float(hash_combine(s->sample_key, dim)),
                        u32_to_unit_float(hash_combine(s->sample_key, dim + 1u)));
    return sampler_value_2d(s, dim);
}
