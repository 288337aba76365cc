/* Random permutations and strata: the building blocks of the padded samplers, which map a
 * pixel's sample index through a random permutation onto a stratified point set. */
#include "util/math.cl"

/* One round of the permutation hash below on i (uint or a uint vector) with key p and
 * the mask w of the next power of two: a bijection on [0, w]. Written once for the scalar
 * function and its lanes version. */
#define PERMUTE_ROUND(i, p, w)                                                                                         \
    do {                                                                                                               \
        i ^= p;                                                                                                        \
        i *= 0xe170893du;                                                                                              \
        i ^= p >> 16;                                                                                                  \
        i ^= (i & w) >> 4;                                                                                             \
        i ^= p >> 8;                                                                                                   \
        i *= 0x0929eb3fu;                                                                                              \
        i ^= p >> 23;                                                                                                  \
        i ^= (i & w) >> 1;                                                                                             \
        i *= 1u | p >> 27;                                                                                             \
        i *= 0x6935fa69u;                                                                                              \
        i ^= (i & w) >> 11;                                                                                            \
        i *= 0x74dcb303u;                                                                                              \
        i ^= (i & w) >> 2;                                                                                             \
        i *= 0x9e501cc3u;                                                                                              \
        i ^= (i & w) >> 2;                                                                                             \
        i *= 0xc860a3dfu;                                                                                              \
        i &= w;                                                                                                        \
        i ^= i >> 5;                                                                                                   \
    } while (0)

/* The mask of the smallest power of two >= l, minus one (l >= 1). */
static inline uint permute_mask(uint l)
{
    uint w = l - 1u;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    return w;
}

/* Element i of a random permutation of [0, l) chosen by p (Kensler 2013, "Correlated
 * Multi-Jittered Sampling"): a hash that is a bijection on the next power of two, cycle
 * walked into [0, l). i is reduced mod l first, so a bad index can never loop forever. */
static inline uint permute_element(uint i, uint l, uint p)
{
    if (l <= 1u)
        return 0u;
    uint w = permute_mask(l);
    /* A power of two (every Sobol', Hammersley and square-jittered spp of 4^k) needs no
     * integer division, the slowest instruction here: the same values by masks. */
    bool pow2 = (l & w) == 0u;
    i = pow2 ? (i & w) : (i % l);
    do {
        PERMUTE_ROUND(i, p, w);
    } while (i >= l);
    return pow2 ? ((i + p) & w) : ((i + p) % l);
}

/* permute_element(i, l, p.sN) in each lane N: the lanes that land in [0, l) stop while
 * the others walk on. */
static inline uint8 permute_element_8(uint i, uint l, uint8 p)
{
    if (l <= 1u)
        return (uint8)(0u);
    uint w = permute_mask(l);
    bool pow2 = (l & w) == 0u;
    uint8 x = (uint8)(pow2 ? (i & w) : (i % l));
    int8 inside = (int8)(0);
    do {
        uint8 next = x;
        PERMUTE_ROUND(next, p, w);
        x = select(next, x, inside); /* a lane inside keeps its value */
        inside = x < (uint8)(l);
    } while (!all(inside));
    return pow2 ? ((x + p) & w) : ((x + p) % l);
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
