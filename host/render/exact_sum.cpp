#include "render/exact_sum.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace pathcl {
namespace {

// Poisoned: the top limb's most negative value, which no unpoisoned sum reaches
// (|sum| < 2^126 keeps the top limb within +-2^62).
constexpr std::uint64_t kPoison = std::uint64_t(1) << 63;
constexpr double kMaxAddend = 19807040628566084398385987584.0; // 2^94

using Limbs = std::uint64_t[3];
__extension__ typedef unsigned __int128 Uint128; // GCC's and Clang's, for value()'s conversion

void add_limbs(Limbs& a, const Limbs& b)
{
    std::uint64_t carry = 0;
    for (int i = 0; i < 3; ++i) {
        std::uint64_t s = a[i] + b[i];
        std::uint64_t c1 = s < a[i];
        std::uint64_t t = s + carry;
        std::uint64_t c2 = t < s;
        a[i] = t;
        carry = c1 | c2;
    }
}

void negate(Limbs& a)
{
    for (auto& l : a)
        l = ~l;
    const Limbs one = {1, 0, 0};
    add_limbs(a, one);
}

} // namespace

bool ExactSum::poisoned() const
{
    return limb[2] == kPoison;
}

void ExactSum::add(double x)
{
    if (poisoned())
        return;
    if (!(std::fabs(x) < kMaxAddend)) {
        limb[0] = limb[1] = 0;
        limb[2] = kPoison;
        return;
    }
    // x on the grid, an integer count of 2^-64, from the double's own fields: x is
    // mantissa 2^(exponent - 1075), so x 2^64 is mantissa 2^shift. Integer operations
    // only (the film adds 12 of these a pixel a batch).
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    const int exponent = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t mantissa = bits & ((std::uint64_t(1) << 52) - 1);
    if (exponent > 0)
        mantissa |= std::uint64_t(1) << 52;
    int shift = std::max(exponent, 1) - 1075 + 64;
    if (shift < 0) { // below the grid: round to nearest, ties to even
        const int k = -shift;
        if (k > 54) // mantissa < 2^53, so x 2^64 < 1/2
            return;
        const std::uint64_t q = mantissa >> k, rest = mantissa & ((std::uint64_t(1) << k) - 1);
        const std::uint64_t half = std::uint64_t(1) << (k - 1);
        mantissa = q + (rest > half || (rest == half && (q & 1)));
        shift = 0;
    }
    if (mantissa == 0)
        return;
    Limbs v = {0, 0, 0};
    const int word = shift / 64, bit = shift % 64;
    v[word] = mantissa << bit;
    if (bit > 0 && word < 2)
        v[word + 1] = mantissa >> (64 - bit);
    if (bits >> 63)
        negate(v);
    add_limbs(limb, v);
}

void ExactSum::add(const ExactSum& other)
{
    if (poisoned())
        return;
    if (other.poisoned()) {
        *this = other;
        return;
    }
    add_limbs(limb, other.limb);
}

double ExactSum::value() const
{
    if (poisoned())
        return std::numeric_limits<double>::quiet_NaN();
    Limbs m = {limb[0], limb[1], limb[2]};
    const bool negative = (m[2] >> 63) != 0;
    if (negative)
        negate(m);
    // Most sums fit 128 bits: the compiler's conversion of a 128-bit integer rounds once,
    // to nearest (scaling by 2^-64 is exact: the result is at least 2^-64).
    if (m[2] == 0) {
        const Uint128 v = (static_cast<Uint128>(m[1]) << 64) | m[0];
        const double d = static_cast<double>(v) * 0x1p-64;
        return negative ? -d : d;
    }
    // Past 128 bits: the 64 bits below the leading one, the bits under them folded into
    // the last (a sticky bit): converting those 64 bits to double then rounds exactly as
    // the whole number would, as 64 > 53 + 2.
    const int drop = 128 - __builtin_clzll(m[2]); // bits below the 64 kept: 65 .. 128
    const int word = drop / 64, bit = drop % 64;  // word 1 or 2
    std::uint64_t kept = m[word] >> bit;
    if (bit > 0 && word < 2)
        kept |= m[word + 1] << (64 - bit);
    bool sticky = (m[word] & ((std::uint64_t(1) << bit) - 1)) != 0;
    for (int i = 0; i < word; ++i)
        sticky |= m[i] != 0;
    if (sticky)
        kept |= 1;
    const double v = std::ldexp(static_cast<double>(kept), drop - 64);
    return negative ? -v : v;
}

} // namespace pathcl
