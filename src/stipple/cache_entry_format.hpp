#pragma once
// The stipple cache's entry layout (stipple_cache.cpp writes and reads it, cache_folder.cpp lists it):
// this header, then one zstd frame (with its content checksum) of
//   uint32 count[triangles]       candidates per polygon
//   uint16 selection[triangles]   the fixed selection value's 16-bit step (§2.3)
//   uint32 uv[stipples]           each stipple's (u, v) in its polygon, 16-bit unorm each
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/hash.hpp"

namespace stipple::cache_format {

inline constexpr uint64_t kMagic = 0x5350495453454C50ull;  // "PLESTIPS"
// 3: compressed barycentric entries with checksums; 4: selection values uniform per area class;
// 5: generation with two buckets per point in the grids and large triangles ordered in pieces;
// 6: stratified (R2) initial positions, the progressive order in windows of tau; 7: slabs at least
// 4 search caps wide (5-7: same kind of stipples, other positions for the same parameters); 8: the
// point grids' windows at offsets over the whole bucket table (the relaxation's sums, in their last bits);
// 9: jittered stratified positions and Gauss-Seidel relaxation (better spread, no hexagonal domains),
// selection values ranked by the polygons' first stipples; 10: selection values uniform per class of
// candidate count and area (the stipples unchanged); 11: the relaxation's grid at one bucket a point
// instead of two (its Gauss-Seidel chunks, fixed ranges of buckets, hold other stipples); 12: the
// relaxation's force with a single falloff, 5 iterations by default instead of 6; 13: the progressive
// order's search reaching 24 spacings instead of 12 (the prefixes down to 1/256 spread); 14: the pieces of
// a cut triangle merged with phases rotated per triangle (slivers side by side drew their prefixes in bands);
// 15: the progressive order's slabs across the axis (or, for slivers along no axis, the direction across
// them) that cuts the fewest triangles, judged by their extent along it (slivers are left whole; scans,
// cut nowhere, unchanged); 16: selection values uniform per facing too (the normal's octant and longest
// axis), in classes whose ranks follow the facing (z > 5, 64 polygons or more; the stipples unchanged); 17:
// the selection's sites offered to its ranking in order of arrival weighted by the candidate count, the
// triangles without a candidate ranked after all others (the stipples unchanged); 18: the triangles without a
// candidate, which never draw, given the last selection value rather than ranked and calibrated (the other
// triangles' values and the stipples unchanged); 19: the coarse_class parameter (stipple_classes.hpp), whose
// stipples the fingerprint covers too (without it, the stipples unchanged)
inline constexpr uint32_t kVersion = 19;
// What generation makes for kVersion, fingerprinted by tests/test_stipple_cache.cpp
// (GenerationChangesComeWithANewCacheVersion): it fails when generation changes without a new kVersion.
inline constexpr uint64_t kGenerationFingerprint = 0x5bfef1a6a13005c3;
inline constexpr char kExtension[] = ".stipples";

struct Header {
    uint64_t magic;
    uint32_t version;
    uint32_t header_bytes;  // sizeof(Header)
    uint64_t key;
    uint64_t triangles;
    uint64_t stipples;
    double density_per_area;
    double poisson_radius;
    uint64_t raw_bytes;         // the payload before compression
    uint64_t compressed_bytes;  // the zstd frame that follows
    char model[128];            // the mesh's source file (for `stipple cache --list`), NUL-terminated
    uint64_t header_hash;       // of every byte before it
};
static_assert(sizeof(Header) == 208 && offsetof(Header, header_hash) == 200, "no padding: the hash reads raw bytes");

inline uint64_t hash_header(const Header& header) {
    uint64_t h = mix64(kMagic);
    const auto* bytes = reinterpret_cast<const unsigned char*>(&header);
    for (size_t i = 0; i < offsetof(Header, header_hash); i += 8) {
        uint64_t word = 0;
        std::memcpy(&word, bytes + i, 8);
        h = mix64(h ^ word);
    }
    return h;
}

// The header is intact: right magic, version, size and hash.
inline bool header_valid(const Header& header) {
    return header.magic == kMagic && header.version == kVersion && header.header_bytes == sizeof(Header) &&
           header.header_hash == hash_header(header) && header.model[sizeof(header.model) - 1] == '\0';
}

}  // namespace stipple::cache_format
