/* Counter-based randomness: integer hashes, their conversion to uniform floats, and bit
 * reversal. Every random number of a render is a hash of its coordinates (seed, pixel,
 * sample, dimension), so no state is carried between work-items or passes. */

/* The hashes below are written once as statements on a variable of type uint or of a
 * uint vector type (HASH_*), for the scalar functions and for the lanes versions that
 * draw a bounce's numbers eight at a time (sample/sampler.cl): the same arithmetic lane
 * for lane, so either gives the same bits. */

/* A full-avalanche 32-bit mix (the "lowbias32" hash by Chris Wellons). */
#define HASH_U32(x)                                                                                                    \
    do {                                                                                                               \
        x ^= x >> 16;                                                                                                  \
        x *= 0x7feb352du;                                                                                              \
        x ^= x >> 15;                                                                                                  \
        x *= 0x846ca68bu;                                                                                              \
        x ^= x >> 16;                                                                                                  \
    } while (0)

/* h = hash_combine(h, v). */
#define HASH_COMBINE(h, v)                                                                                             \
    do {                                                                                                               \
        h ^= (v) + 0x9e3779b9u + (h << 6) + (h >> 2);                                                                  \
        HASH_U32(h);                                                                                                   \
    } while (0)

static inline uint hash_u32(uint x)
{
    HASH_U32(x);
    return x;
}

static inline uint hash_combine(uint h, uint v)
{
    HASH_COMBINE(h, v);
    return h;
}

static inline uint8 hash_combine_8(uint8 h, uint8 v)
{
    HASH_COMBINE(h, v);
    return h;
}

/* 24 random bits to a float in [0, 1): exactly representable, never 1. */
static inline float u32_to_unit_float(uint x)
{
    return (float)(x >> 8) * 0x1.0p-24f;
}

#define REVERSE_BITS_U32(x)                                                                                            \
    do {                                                                                                               \
        x = (x << 16) | (x >> 16);                                                                                     \
        x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);                                                       \
        x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);                                                       \
        x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);                                                       \
        x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);                                                       \
    } while (0)

static inline uint reverse_bits_u32(uint x)
{
    REVERSE_BITS_U32(x);
    return x;
}
