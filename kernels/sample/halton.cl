/* Scrambled radical inverses in prime bases: the digits of the Halton sampler, nested
 * (Owen-style) scrambled as pbrt-v4's OwenScrambledRadicalInverse does. */
#include "sample/permute.cl"
#include "util/hash.cl"

/* The first primes: Halton dimension d uses base HALTON_PRIMES[d % 256]. */
/* clang-format off */
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
/* clang-format on */

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
