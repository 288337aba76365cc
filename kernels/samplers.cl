/* Samplers: where every random decision of a path gets its numbers.
 *
 * A decision asks for one number (sampler_get_1d) or a pair (sampler_get_2d) at an
 * explicit dimension index (the camera and the integrator assign each decision its own
 * dimension(s); see DIM_* in shared_types.h and integrator.cl). A value depends only on
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

typedef struct {
    uint pixel;
    uint sample;
    uint seed;
    uint dimension; /* next dimension to hand out */
    uint type;      /* SAMPLER_* */
    uint spp;       /* size of the point sets (the render's samples per pixel) */
    uint sample_key; /* hash of (seed, pixel, sample): every draw extends it by the dimension */
    uint set_key;    /* hash of (seed, pixel): the point sets' seeds extend it */
} SamplerState;

/* A full-avalanche 32-bit mix (the "lowbias32" hash by Chris Wellons). */
static inline uint hash_u32(uint x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

static inline uint hash_combine(uint h, uint v)
{
    return hash_u32(h ^ (v + 0x9e3779b9u + (h << 6) + (h >> 2)));
}

/* 24 random bits to a float in [0, 1): exactly representable, never 1. */
static inline float u32_to_unit_float(uint x)
{
    return (float)(x >> 8) * 0x1.0p-24f;
}

#define ONE_MINUS_EPSILON 0x1.fffffep-1f

/* A sampler state for (pixel, sample) starting at `dimension`. */
static inline SamplerState sampler_start_typed(uint type, uint spp, uint pixel, uint sample, uint seed,
                                               uint dimension)
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
    return s;
}

/* Plain counter-based random numbers (the independent sampler), for code that is not a
 * path's decision (test kernels). */
static inline SamplerState sampler_start(uint pixel, uint sample, uint seed, uint dimension)
{
    return sampler_start_typed(SAMPLER_INDEPENDENT, 1u, pixel, sample, seed, dimension);
}

/* The sampler a render pass uses (frame->sampler, frame->spp, frame->sample_index). */
static inline SamplerState frame_sampler(const FrameParams* frame, uint pixel, uint dimension)
{
    return sampler_start_typed(frame->sampler, frame->spp, pixel, frame->sample_index, frame->seed, dimension);
}

/* ---- building blocks ---- */

/* Element i of a random permutation of [0, l) chosen by p (Kensler 2013, "Correlated
 * Multi-Jittered Sampling"): a hash that is a bijection on the next power of two, cycle
 * walked into [0, l). i is reduced mod l first, so a bad index can never loop forever. */
static inline uint permute_element(uint i, uint l, uint p)
{
    if (l <= 1u)
        return 0u;
    uint w = l - 1u;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    /* A power of two (every Sobol', Hammersley and square-jittered spp of 4^k) needs no
     * integer division, the slowest instruction here: the same values by masks. */
    bool pow2 = (l & w) == 0u;
    i = pow2 ? (i & w) : (i % l);
    do {
        i ^= p;
        i *= 0xe170893du;
        i ^= p >> 16;
        i ^= (i & w) >> 4;
        i ^= p >> 8;
        i *= 0x0929eb3fu;
        i ^= p >> 23;
        i ^= (i & w) >> 1;
        i *= 1u | p >> 27;
        i *= 0x6935fa69u;
        i ^= (i & w) >> 11;
        i *= 0x74dcb303u;
        i ^= (i & w) >> 2;
        i *= 0x9e501cc3u;
        i ^= (i & w) >> 2;
        i *= 0xc860a3dfu;
        i &= w;
        i ^= i >> 5;
    } while (i >= l);
    return pow2 ? ((i + p) & w) : ((i + p) % l);
}

/* A uniform point of stratum j of n equal strata of [0, 1), exactly inside it:
 * j / n <= x < (j + 1) / n holds in exact arithmetic (for n <= 2^24). The division may
 * round across a stratum boundary; fma gives the exact sign of x n - j, and one ulp
 * moves the point back. */
static inline float stratum_point(uint j, uint n, float xi)
{
    float fj = (float)j, fn = (float)n;
    float x = fmin((fj + xi) / fn, ONE_MINUS_EPSILON);
    if (fma(x, fn, -fj) < 0.0f)
        x = nextafter(x, 1.0f);
    if (fma(x, fn, -(fj + 1.0f)) >= 0.0f)
        x = nextafter(x, 0.0f);
    return x;
}

static inline uint reverse_bits_u32(uint x)
{
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

/* Owen scrambling of a 32-bit binary fraction (Burley 2020, "Practical Hash-based Owen
 * Scrambling"): in bit-reversed order, the Laine-Karras hash flips each bit as a function
 * of the bits below it only, i.e. of the more significant bits of x: a nested uniform
 * scramble, which maps every dyadic elementary interval onto one of the same size and so
 * keeps (0,m,2)-nets nets. */
static inline uint owen_scramble_u32(uint x, uint seed)
{
    x = reverse_bits_u32(x);
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return reverse_bits_u32(x);
}

/* owen_scramble_u32(reverse_bits_u32(r), seed): for a value at hand in bit-reversed
 * order (a van der Corput index), two of the three reversals cancel. */
static inline uint owen_scramble_reversed_u32(uint r, uint seed)
{
    uint x = r + seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return reverse_bits_u32(x);
}

/* reverse_bits_u32(sobol_dimension1_u32(a)), built directly in reversed order. */
static inline uint sobol_dimension1_reversed_u32(uint a)
{
    uint v = 1u, r = 0u;
    for (; a != 0u; a >>= 1, v ^= v << 1)
        if (a & 1u)
            r ^= v;
    return r;
}

/* Sobol' dimension 1 (generator matrix: Pascal's triangle mod 2) as a 32-bit fraction.
 * Dimension 0 is the van der Corput sequence, reverse_bits_u32(a). */
static inline uint sobol_dimension1_u32(uint a)
{
    uint v = 1u << 31, r = 0u;
    for (; a != 0u; a >>= 1, v ^= v >> 1)
        if (a & 1u)
            r ^= v;
    return r;
}

/* The first primes: Halton dimension d uses base HALTON_PRIMES[d % 256]. */
__constant ushort HALTON_PRIMES[256] = {
    2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53,
    59, 61, 67, 71, 73, 79, 83, 89, 97, 101, 103, 107, 109, 113, 127, 131,
    137, 139, 149, 151, 157, 163, 167, 173, 179, 181, 191, 193, 197, 199, 211, 223,
    227, 229, 233, 239, 241, 251, 257, 263, 269, 271, 277, 281, 283, 293, 307, 311,
    313, 317, 331, 337, 347, 349, 353, 359, 367, 373, 379, 383, 389, 397, 401, 409,
    419, 421, 431, 433, 439, 443, 449, 457, 461, 463, 467, 479, 487, 491, 499, 503,
    509, 521, 523, 541, 547, 557, 563, 569, 571, 577, 587, 593, 599, 601, 607, 613,
    617, 619, 631, 641, 643, 647, 653, 659, 661, 673, 677, 683, 691, 701, 709, 719,
    727, 733, 739, 743, 751, 757, 761, 769, 773, 787, 797, 809, 811, 821, 823, 827,
    829, 839, 853, 857, 859, 863, 877, 881, 883, 887, 907, 911, 919, 929, 937, 941,
    947, 953, 967, 971, 977, 983, 991, 997, 1009, 1013, 1019, 1021, 1031, 1033, 1039, 1049,
    1051, 1061, 1063, 1069, 1087, 1091, 1093, 1097, 1103, 1109, 1117, 1123, 1129, 1151, 1153, 1163,
    1171, 1181, 1187, 1193, 1201, 1213, 1217, 1223, 1229, 1231, 1237, 1249, 1259, 1277, 1279, 1283,
    1289, 1291, 1297, 1301, 1303, 1307, 1319, 1321, 1327, 1361, 1367, 1373, 1381, 1399, 1409, 1423,
    1427, 1429, 1433, 1439, 1447, 1451, 1453, 1459, 1471, 1481, 1483, 1487, 1489, 1493, 1499, 1511,
    1523, 1531, 1543, 1549, 1553, 1559, 1567, 1571, 1579, 1583, 1597, 1601, 1607, 1609, 1613, 1619,
};

/* Radical inverse of a in `base` (a prime), as the integer digits reversed / scale
 * (scale = base^k): the nested (Owen-style) scrambling of pbrt-v4's
 * OwenScrambledRadicalInverse, with random affine digit permutations (one hash per digit
 * instead of a cycle-walked permutation).
 *   Unscrambled: a's own digits, so small values convert to float exactly.
 *   Scrambled: every digit is permuted by a random permutation chosen by `seed` and the
 *   digits above it, for as many digits as it takes to tell the first n points apart
 *   (base^k >= n; at most base^k <= 2^24, float resolution). Below that level every one
 *   of the n points has digit-tree nodes of its own, so its remaining scrambled digits
 *   are independent uniform digits: `rest` is the hash the caller turns into a uniform
 *   offset inside [reversed / scale, (reversed + 1) / scale). */
static inline void radical_inverse_digits(uint base, uint a, uint n, uint seed, bool scramble, ulong* reversed,
                                          ulong* scale, uint* rest)
{
    ulong r = 0ul, s = 1ul;
    uint level = 0u;
    for (; scramble ? (s < n && s * base <= (1ul << 24)) : a != 0u; ++level) {
        uint next = a / base;
        uint digit = a - next * base;
        /* One random permutation per node (level, digits above) of the digit tree: an
         * affine map d -> (m d + o) mod base with m in [1, base) (a bijection: base is
         * prime) and a uniform offset o, so each scrambled digit is uniform. The digits
         * above are r < base^level <= 2^24, so 32 bits of r name the node. */
        if (scramble) {
            uint h = hash_combine(seed + level * 0x9e3779b9u, (uint)r);
            uint m = 1u + hash_u32(h ^ 0x2c1b3c6du) % (base - 1u);
            digit = (digit * m + h % base) % base;
        }
        r = r * base + digit;
        s *= base;
        a = next;
    }
    *reversed = r;
    *scale = s;
    /* The node below the last digit (a's remaining digits included: nonzero only past
     * float resolution). */
    *rest = hash_combine(hash_combine(seed + level * 0x9e3779b9u, (uint)r), a);
}

/* The radical inverse of point a of a set of n (n only matters when scrambled). */
static inline float radical_inverse(uint base, uint a, uint n, uint seed, bool scramble)
{
    ulong r, s;
    uint rest;
    radical_inverse_digits(base, a, n, seed, scramble, &r, &s, &rest);
    if (scramble)
        return stratum_point((uint)r, (uint)s, u32_to_unit_float(rest));
    return fmin((float)r / (float)s, ONE_MINUS_EPSILON);
}

/* ---- the samplers ---- */

/* The independent sampler's pair at (dim, dim + 1): also the jitter inside a stratum. */
static inline float2 sampler_jitter_2d(const SamplerState* s, uint dim)
{
    return (float2)(u32_to_unit_float(hash_combine(s->sample_key, dim)),
                    u32_to_unit_float(hash_combine(s->sample_key, dim + 1u)));
}

/* floor(sqrt(n)) exactly. */
static inline uint sqrt_floor_u32(uint n)
{
    uint r = (uint)sqrt((float)n);
    while ((ulong)r * r > n)
        --r;
    while ((ulong)(r + 1u) * (r + 1u) <= n)
        ++r;
    return r;
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
        uint cols = max(sqrt_floor_u32(n), 1u), rows = (n + cols - 1u) / cols;
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
        uint cols = max(sqrt_floor_u32(n), 1u), rows = (n + cols - 1u) / cols, cells = cols * rows;
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
        return (float2)(
            u32_to_unit_float(owen_scramble_reversed_u32(index, hash_combine(set, 1u))),
            u32_to_unit_float(owen_scramble_reversed_u32(sobol_dimension1_reversed_u32(index), hash_combine(set, 2u))));
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
    if (s->type == SAMPLER_INDEPENDENT) /* the common case, kept small enough to inline */
        return u32_to_unit_float(hash_combine(s->sample_key, dim));
    return sampler_value_1d(s, dim);
}

/* The pair for the 2D decision at (s->dimension, s->dimension + 1); advances by two. */
static inline float2 sampler_get_2d(SamplerState* s)
{
    uint dim = s->dimension;
    s->dimension += 2u;
    if (s->type == SAMPLER_INDEPENDENT)
        return (float2)(u32_to_unit_float(hash_combine(s->sample_key, dim)),
                        u32_to_unit_float(hash_combine(s->sample_key, dim + 1u)));
    return sampler_value_2d(s, dim);
}

/* The sample visualizer's and the sampler tests' view of the samplers: out[p * count + k]
 * holds sample first_sample + k of pixel pixels[p], as the decision at dim0 sees it: the
 * 2D pair when dim1 == dim0 + 1, else the two 1D values of decisions at dim0 and dim1.
 * Global size (count, number of pixels). */
__kernel void sampler_points(uint type, uint spp, uint seed, uint dim0, uint dim1, __global const uint* pixels,
                             uint first_sample, uint count, __global float2* out)
{
    uint k = get_global_id(0), p = get_global_id(1);
    if (k >= count)
        return;
    SamplerState s = sampler_start_typed(type, spp, pixels[p], first_sample + k, seed, dim0);
    float2 v;
    if (dim1 == dim0 + 1u) {
        v = sampler_get_2d(&s);
    } else {
        v.x = sampler_get_1d(&s);
        s.dimension = dim1;
        v.y = sampler_get_1d(&s);
    }
    out[p * count + k] = v;
}

/* Warps from the unit square, shared by the camera (lens), BSDFs and lights. */

#define INV_PI 0.31830988618379067f
#define PI_F 3.14159265358979324f

/* sin x (returned) and cos x for |x| <= pi/4, by the minimax polynomials of Cephes'
 * sinf and cosf (within 1 ulp, tested). PoCL's built-in sincos reduces its argument in
 * an out-of-line call first (5 % of a Cornell box render's profile; without it the
 * render is 9 % faster); every angle a sampler warp needs is a known fraction of a turn,
 * which reduces exactly by symmetry instead. */
static inline float sin_cos_small(float x, float* c)
{
    float x2 = x * x;
    *c = fma(fma(fma(fma(2.443315711809948e-5f, x2, -1.388731625493765e-3f), x2, 4.166664568298827e-2f), x2, -0.5f),
             x2, 1.0f);
    return fma(fma(fma(-1.9515295891e-4f, x2, 8.3321608736e-3f), x2, -1.6666654611e-1f), x2 * x, x);
}

/* sin (returned) and cos of 2 pi t, for t a number of turns (|t| < 2^21): t is split
 * exactly into the nearest quarter turn q and a remainder |r| <= 1/8 turn, and the
 * quarter turn is applied by symmetry. Near every zero of sin and cos the result is then
 * accurate relative to its own size, unlike sincos(2 pi t), whose rounded argument is
 * off by up to half an ulp of 2 pi t. */
static inline float sin_cos_turns(float t, float* c)
{
    float q = rint(4.0f * t);
    float r = 4.0f * t - q; /* exact: 4t and q are within 1/2 of each other */
    /* The angle r pi/2 as a + a_lo, pi/2 split in two floats, and the polynomials
     * corrected to first order in a_lo: only their own error remains. */
    const float pio2_hi = 0x1.921fb6p0f, pio2_lo = -0x1.777a5cp-25f;
    float a = r * pio2_hi, a_lo = fma(r, pio2_hi, -a) + r * pio2_lo;
    float cs0, sn0 = sin_cos_small(a, &cs0);
    float sn = fma(cs0, a_lo, sn0), cs = fma(-sn0, a_lo, cs0);
    int k = (int)q & 3;
    *c = k == 0 ? cs : k == 1 ? -sn : k == 2 ? -cs : sn;
    return k == 0 ? sn : k == 1 ? cs : k == 2 ? -sn : -cs;
}

/* The unit square to the unit disk by Shirley and Chiu's concentric map: low distortion,
 * so stratified points stay stratified on the disk. */
static inline float2 sample_concentric_disk(float2 u)
{
    float2 o = 2.0f * u - 1.0f;
    if (o.x == 0.0f && o.y == 0.0f)
        return (float2)(0.0f);
    float c, s;
    if (fabs(o.x) > fabs(o.y)) { /* theta = pi/4 (y/x), within [-pi/4, pi/4] */
        s = sin_cos_small((PI_F / 4.0f) * (o.y / o.x), &c);
        return o.x * (float2)(c, s);
    }
    /* theta = pi/2 - a with a = pi/4 (x/y): cos theta = sin a, sin theta = cos a */
    s = sin_cos_small((PI_F / 4.0f) * (o.x / o.y), &c);
    return o.y * (float2)(s, c);
}
