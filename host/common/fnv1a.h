// FNV-1a, 64 bits: the hash of the scene fingerprint and the checksum of the kernel-cache
// entries and checkpoints (fast, no dependency; each step is invertible, so one changed
// byte always changes it). Not for adversaries: a check against damage, not tampering.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pathcl {

constexpr std::uint64_t kFnv1aBasis = 0xcbf29ce484222325ull;

// The hash of n bytes at p, continuing from h (the basis, or an earlier result).
inline std::uint64_t fnv1a64(const void* p, std::size_t n, std::uint64_t h = kFnv1aBasis)
{
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
        h ^= b[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

} // namespace pathcl
