#pragma once
// A 64-bit mixing function (splitmix64's finaliser): deterministic per-element random streams from
// (seed, index) pairs, independent of thread count and order.
#include <cstdint>

namespace stipple {

inline uint64_t mix64(uint64_t x) {
    x ^= x >> 30;
    x *= 0xBF58476D1CE4E5B9ull;
    x ^= x >> 27;
    x *= 0x94D049BB133111EBull;
    x ^= x >> 31;
    return x;
}

}  // namespace stipple
