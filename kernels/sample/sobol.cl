/* The base-2 constructions: Owen scrambling by Burley's hash (2020) and the first two
 * Sobol' dimensions (van der Corput and the Pascal-matrix dimension), whose scrambled
 * first 2^m points form a (0,m,2)-net. */
#include "util/hash.cl"

/* Owen scrambling (owen_scramble_u32 below) of a value at hand in bit-reversed order (a
 * van der Corput index): the Laine-Karras hash, then one reversal back to a fraction. */
#define OWEN_SCRAMBLE_REVERSED(x, seed)                                                                                \
    do {                                                                                                               \
        x += seed;                                                                                                     \
        x ^= x * 0x6c50b47cu;                                                                                          \
        x ^= x * 0xb82f1e52u;                                                                                          \
        x ^= x * 0xc7afe638u;                                                                                          \
        x ^= x * 0x8d22f6e6u;                                                                                          \
        REVERSE_BITS_U32(x);                                                                                           \
    } while (0)

static inline uint owen_scramble_reversed_u32(uint r, uint seed)
{
    OWEN_SCRAMBLE_REVERSED(r, seed);
    return r;
}

static inline uint8 owen_scramble_reversed_u32_8(uint8 r, uint8 seed)
{
    OWEN_SCRAMBLE_REVERSED(r, seed);
    return r;
}

/* Owen scrambling of a 32-bit binary fraction (Burley 2020, "Practical Hash-based Owen
 * Scrambling"): in bit-reversed order, the Laine-Karras hash flips each bit as a function
 * of the bits below it only, i.e. of the more significant bits of x: a nested uniform
 * scramble, which maps every dyadic elementary interval onto one of the same size and so
 * keeps (0,m,2)-nets nets. */
static inline uint owen_scramble_u32(uint x, uint seed)
{
    return owen_scramble_reversed_u32(reverse_bits_u32(x), seed);
}

/* Sobol' dimension 1 (generator matrix: Pascal's triangle mod 2) as a 32-bit fraction,
 * in bit-reversed order (its bit j is the fraction's digit j + 1). Dimension 0 is the van
 * der Corput sequence, reverse_bits_u32(a). Index bit k contributes direction number v_k,
 * whose digit j + 1 is C(k, j) mod 2, which by Lucas's theorem is 1 exactly when the bits
 * of j are a subset of those of k: bit j of the result is the XOR of the index bits k
 * whose bits include j's, a superset sum computed in five shift-and-mask steps instead of
 * a loop over the index bits (tested against the loop). */
#define SOBOL_DIMENSION1_REVERSED(a)                                                                                   \
    do {                                                                                                               \
        a ^= (a >> 16) & 0x0000ffffu;                                                                                  \
        a ^= (a >> 8) & 0x00ff00ffu;                                                                                   \
        a ^= (a >> 4) & 0x0f0f0f0fu;                                                                                   \
        a ^= (a >> 2) & 0x33333333u;                                                                                   \
        a ^= (a >> 1) & 0x55555555u;                                                                                   \
    } while (0)

static inline uint sobol_dimension1_reversed_u32(uint a)
{
    SOBOL_DIMENSION1_REVERSED(a);
    return a;
}

static inline uint8 sobol_dimension1_reversed_u32_8(uint8 a)
{
    SOBOL_DIMENSION1_REVERSED(a);
    return a;
}
