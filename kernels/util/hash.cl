/* Counter-based randomness: integer hashes, their conversion to uniform floats, and bit
 * reversal. Every random number of a render is a hash of its coordinates (seed, pixel,
 * sample, dimension), so no state is carried between work-items or passes. */

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

static inline uint reverse_bits_u32(uint x)
{
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}
