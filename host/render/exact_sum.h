// A sum of doubles that does not depend on the order of its addends. The film's totals
// are ExactSums, so a render split into sample ranges (on several machines, in any order)
// and merged is the uninterrupted render bit for bit: floating-point addition is not
// associative, integer addition is.
//
// The value is a 192-bit two's-complement fixed-point number with 64 bits after the binary
// point: resolution 2^-64 (5.4e-20), range +-2^127. Each addend is rounded to that grid
// once (to nearest, ties to even; a film total's addends are a batch's sums, which for
// radiance above ~1e-7 lie on the grid already) and the rest is integer arithmetic. An
// addend of magnitude 2^94 (2e28) or more, an infinity or a NaN poisons the sum: its
// value() is NaN from then on, as a float sum would be Inf or NaN. Below that, 2^32
// addends cannot overflow. 24 bytes, trivially copyable (checkpoints and EXR channels
// store the limbs).
#pragma once

#include <cstdint>

namespace pathcl {

struct ExactSum {
    std::uint64_t limb[3] = {0, 0, 0}; // least significant first

    void add(double x);
    void add(const ExactSum& other);
    // The sum rounded once to the nearest double (ties to even); NaN when poisoned.
    double value() const;
    bool poisoned() const;

    friend bool operator==(const ExactSum& a, const ExactSum& b)
    {
        return a.limb[0] == b.limb[0] && a.limb[1] == b.limb[1] && a.limb[2] == b.limb[2];
    }
};

} // namespace pathcl
