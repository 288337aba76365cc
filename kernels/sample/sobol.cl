/* The base-2 constructions: Owen scrambling by Burley's hash (2020) and the first two
 * Sobol' dimensions (van der Corput and the Pascal-matrix dimension), whose scrambled
 * first 2^m points form a (0,m,2)-net. */
#include "util/hash.cl"

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
