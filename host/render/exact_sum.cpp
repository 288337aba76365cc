#include "render/exact_sum.h"

#include <cmath>
#include <limits>

namespace pathcl {
namespace {

// Poisoned: the top limb's most negative value, which no unpoisoned sum reaches
// (|sum| < 2^126 keeps the top limb within +-2^62).
constexpr std::uint64_t kPoison = std::uint64_t(1) << 63;
constexpr double kMaxAddend = 19807040628566084398385987584.0; // 2^94

using Limbs = std::uint64_t[3];

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
    // x on the grid: an integer count of 2^-64, exact below 2^158 in a double.
    const double r = std::nearbyint(std::ldexp(x, 64)); // the default mode: to nearest, ties to even
    if (r == 0.0)
        return;
    int e = 0;
    const double f = std::frexp(std::fabs(r), &e);                          // |r| = f 2^e, f in [0.5, 1)
    std::uint64_t mantissa = static_cast<std::uint64_t>(std::ldexp(f, 53)); // |r| = mantissa 2^(e - 53)
    int shift = e - 53;
    if (shift < 0) { // |r| < 2^53: an integer, so the shifted-out bits are zero
        mantissa >>= -shift;
        shift = 0;
    }
    Limbs v = {0, 0, 0};
    const int word = shift / 64, bit = shift % 64;
    v[word] = mantissa << bit;
    if (bit > 0 && word < 2)
        v[word + 1] = mantissa >> (64 - bit);
    if (r < 0.0)
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
    int top = 2;
    while (top >= 0 && m[top] == 0)
        --top;
    if (top < 0)
        return 0.0;
    // The 64 bits below the leading one, the bits under them folded into the last (a
    // sticky bit): converting those 64 bits to double then rounds exactly as the whole
    // number would, as 64 > 53 + 2.
    const int lead = top * 64 + 63 - __builtin_clzll(m[top]); // bit index of the leading one
    const int drop = lead - 63;                               // bits below the 64 kept
    std::uint64_t kept;
    bool sticky = false;
    if (drop <= 0) {
        kept = m[0];
    } else {
        const int word = drop / 64, bit = drop % 64;
        kept = m[word] >> bit;
        if (bit > 0 && word < 2)
            kept |= m[word + 1] << (64 - bit);
        for (int i = 0; i < word; ++i)
            sticky |= m[i] != 0;
        if (bit > 0)
            sticky |= (m[word] & ((std::uint64_t(1) << bit) - 1)) != 0;
    }
    if (sticky)
        kept |= 1;
    const double v = std::ldexp(static_cast<double>(kept), (drop > 0 ? drop : 0) - 64);
    return negative ? -v : v;
}

} // namespace pathcl
