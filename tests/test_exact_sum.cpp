// ExactSum (render/exact_sum.h): the film's order-independent totals. A sum must not depend
// on the order of its addends (merged sample ranges rely on it), value() must be the
// exact sum rounded once, and what cannot be held must poison the sum rather than wrap.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "render/exact_sum.h"

namespace pathcl::test_exact_sum {
namespace {

std::vector<double> film_like_addends(std::uint32_t seed, std::size_t n)
{
    // Batch sums of radiance and its square: positive, 20 decades apart, full mantissas.
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> exponent(-8.0, 12.0), mantissa(1.0, 10.0);
    std::vector<double> v(n);
    for (double& x : v)
        x = mantissa(rng) * std::pow(10.0, exponent(rng));
    return v;
}

TEST(ExactSum, TheSumDoesNotDependOnTheOrderOfItsAddends)
{
    std::vector<double> v = film_like_addends(1, 2000);
    v.push_back(-3.5e11); // and cancellation
    ExactSum forward;
    for (double x : v)
        forward.add(x);
    std::mt19937 rng(2);
    for (int trial = 0; trial < 5; ++trial) {
        std::shuffle(v.begin(), v.end(), rng);
        // Also as partial sums merged, as sample ranges are.
        ExactSum a, b, c;
        for (std::size_t i = 0; i < v.size(); ++i)
            (i % 3 == 0 ? a : i % 3 == 1 ? b : c).add(v[i]);
        c.add(a);
        c.add(b);
        EXPECT_TRUE(c == forward) << "trial " << trial;
        EXPECT_EQ(c.value(), forward.value());
    }
    // The double sum of the same addends does depend on their order: the test can tell.
    double d1 = 0.0, d2 = 0.0;
    for (double x : v)
        d1 += x;
    std::reverse(v.begin(), v.end());
    for (double x : v)
        d2 += x;
    EXPECT_NE(d1, d2);
}

TEST(ExactSum, ValueIsTheExactSumRoundedOnce)
{
    // Three addends whose exact sum fits __float128's 113 bits, so its rounding to double
    // is the correctly rounded reference, and the sequential double sum (rounded twice)
    // differs from it now and then. At two scales: sums under 2^64 (held in 128 bits) and
    // above 2^70 (all three limbs), which value() converts in different ways.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(1.0, 2.0);
    int differs_from_double_sums = 0;
    for (int i = 0; i < 40000; ++i) {
        const int scale = i % 2 == 0 ? 0 : 50;
        const double a = std::ldexp(u(rng), 30 + scale), b = std::ldexp(u(rng), -20 + scale),
                     c = -std::ldexp(u(rng), 29 + scale);
        ExactSum s;
        s.add(a);
        s.add(b);
        s.add(c);
        const double reference = static_cast<double>(static_cast<__float128>(a) + b + c);
        ASSERT_EQ(s.value(), reference) << a << " " << b << " " << c;
        differs_from_double_sums += ((a + b) + c) != reference;
    }
    EXPECT_GT(differs_from_double_sums, 0); // the sequential double sum is not always right
}

TEST(ExactSum, ATieBrokenOnlyByTheLowestBitRoundsAway)
{
    // x (1 + 2^-53) + 2^-64: just above the tie between x and x (1 + 2^-52), so it rounds
    // up; only the 2^-64 breaks the tie, so a conversion that rounds twice (its lower
    // half first) lands on the tie and rounds to even, down. Held in 128 bits (x = 2^42)
    // and in all three limbs (x = 2^90).
    for (int e : {42, 90}) {
        ExactSum s;
        s.add(std::ldexp(1.0, e));
        s.add(std::ldexp(1.0, e - 53));
        s.add(std::ldexp(1.0, -64));
        EXPECT_EQ(s.value(), std::ldexp(1.0, e) + std::ldexp(1.0, e - 52)) << "x = 2^" << e;
    }
}

TEST(ExactSum, ValuesOnTheGridComeBackUnchanged)
{
    // A double is on the grid when its last mantissa bit weighs 2^-64 or more (|x| >= 2^-12),
    // or when it is a multiple of 2^-64.
    for (double x : {1.0, -1.0, 0.1, 3.0e20, -7.25e-3, std::ldexp(1.0, -64), std::ldexp(1.0, 93) * 1.5}) {
        ExactSum s;
        s.add(x);
        EXPECT_EQ(s.value(), x);
        s.add(-x);
        EXPECT_EQ(s.value(), 0.0);
    }
}

TEST(ExactSum, AddendsRoundToTheGridOnceToNearestEven)
{
    const double unit = std::ldexp(1.0, -64);
    ExactSum s;
    s.add(0.4 * unit); // below half a unit: nothing
    EXPECT_EQ(s.value(), 0.0);
    s.add(1.5 * unit); // a tie: to the even 2
    EXPECT_EQ(s.value(), 2.0 * unit);
    s.add(2.5 * unit); // a tie: to the even 2
    EXPECT_EQ(s.value(), 4.0 * unit);
}

TEST(ExactSum, WhatItCannotHoldPoisonsTheSumInAnyOrder)
{
    for (double bad : {double(INFINITY), -double(INFINITY), double(NAN), std::ldexp(1.0, 94), -1e30}) {
        ExactSum first, last;
        first.add(bad);
        first.add(1.0);
        last.add(1.0);
        last.add(bad);
        EXPECT_TRUE(first.poisoned() && last.poisoned()) << bad;
        EXPECT_TRUE(std::isnan(first.value()) && std::isnan(last.value()));
        ExactSum merged;
        merged.add(2.0);
        merged.add(first);
        EXPECT_TRUE(merged.poisoned());
    }
    // The largest sums that are allowed stay exact: 2^32 addends just under 2^94.
    ExactSum big;
    const double x = std::ldexp(1.0, 94) - std::ldexp(1.0, 41); // the largest double below 2^94
    for (int i = 0; i < 64; ++i)
        big.add(x);
    ExactSum doubled = big; // 2^6 addends; double it 26 more times: 2^32
    for (int i = 0; i < 26; ++i) {
        ExactSum copy = doubled;
        doubled.add(copy);
    }
    EXPECT_FALSE(doubled.poisoned());
    EXPECT_EQ(doubled.value(), std::ldexp(x, 32));
    ExactSum negative;
    negative.add(-x);
    for (int i = 0; i < 32; ++i) {
        ExactSum copy = negative;
        negative.add(copy);
    }
    EXPECT_EQ(negative.value(), -std::ldexp(x, 32));
}

} // namespace
} // namespace pathcl::test_exact_sum
