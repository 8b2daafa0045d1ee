#pragma once
// A 64-bit mixing function (splitmix64's finaliser): deterministic per-element random streams from
// (seed, index) pairs, independent of thread count and order; and a hash of bytes built on it.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

namespace stipple {

inline uint64_t mix64(uint64_t x) {
    x ^= x >> 30;
    x *= 0xBF58476D1CE4E5B9ull;
    x ^= x >> 27;
    x *= 0x94D049BB133111EBull;
    x ^= x >> 31;
    return x;
}

// A hash of `bytes` continuing from `seed` (not for adversaries: it tells apart data that happen to differ,
// such as the GPU data of two objects, one chance in 2^64 of a collision). Four lanes, so that the mixing's
// latency overlaps: about 2 GB/s.
inline uint64_t hash_bytes(std::span<const std::byte> bytes, uint64_t seed) {
    uint64_t lanes[4] = {mix64(seed ^ bytes.size()), mix64(seed + 1), mix64(seed + 2), mix64(seed + 3)};
    size_t i = 0;
    for (; i + 32 <= bytes.size(); i += 32) {
        uint64_t words[4];
        std::memcpy(words, bytes.data() + i, sizeof(words));
        for (int lane = 0; lane < 4; ++lane) lanes[lane] = mix64(lanes[lane] ^ words[lane]);
    }
    uint64_t tail[4] = {0, 0, 0, 0};
    if (i < bytes.size()) std::memcpy(tail, bytes.data() + i, bytes.size() - i);
    for (int lane = 0; lane < 4; ++lane) lanes[lane] = mix64(lanes[lane] ^ tail[lane]);
    return mix64(lanes[0] ^ mix64(lanes[1] ^ mix64(lanes[2] ^ mix64(lanes[3]))));
}

template <typename T>
uint64_t hash_values(std::span<const T> values, uint64_t seed) {
    return hash_bytes(std::as_bytes(values), seed);
}

}  // namespace stipple
