#pragma once
// An on-disk cache of generated stipples: reopening a model with the same parameters reads its
// candidates back instead of generating them again (generation is ~1 s per million stipples).
//
// An entry holds what the GPU holds: each stipple as its 16-bit (u, v) in its polygon
// (stipple/barycentric.hpp), the polygons' candidate counts and 16-bit selection values, compressed with
// zstd (whose frame checksum covers the data) behind a header that carries its own hash. About 4-5 bytes
// per stipple on disk (the (u, v) pairs are near random: zstd keeps most of their 4 bytes). Every set this cache hands out, fresh or read back, has its positions on that
// 16-bit grid, so a hit and a miss give the same stipples to the byte.
//
// Entries are written to a temporary file and renamed into place (a killed process never leaves half an
// entry), touched when read (their modification time is their last use), and the folder is kept under a
// size limit by evicting the least recently used. A damaged entry is detected, reported in one warning
// line on stderr, and regenerated.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <span>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {

// $STIPPLE_CACHE_DIR/stipples, else $XDG_CACHE_HOME/stipple/stipples, else ~/.cache/stipple/stipples.
std::filesystem::path default_stipple_cache_dir();

inline constexpr uint64_t kDefaultStippleCacheBytes = uint64_t(1) << 30;  // 1 GiB

// The process's cache: where, how big, whether on. Commands set it from --cache-dir and --cache-size;
// STIPPLE_NO_CACHE=1 turns it off.
struct StippleCacheSettings {
    std::filesystem::path dir = default_stipple_cache_dir();
    uint64_t max_bytes = kDefaultStippleCacheBytes;
    bool enabled = true;
};
StippleCacheSettings& stipple_cache_settings();

// "1G", "500M", "64k", "123456" (bytes); throws stipple::Error naming `option` on anything else.
uint64_t parse_byte_size(const std::string& option, const std::string& text);

// A key of everything the stipples depend on: the mesh's triangles and positions, the parameters
// that shape generation (the parameter table's Regenerate entries), an animated model's stretch
// headroom (generate_stipples) and the format version.
uint64_t stipple_cache_key(const Mesh& mesh, const GenerationParams& params, std::span<const float> headroom = {});

// The cached set, or nothing when absent or from another version or mesh. A damaged entry (bad header
// hash, truncation, checksum, inconsistent counts) is also nothing, after a warning on stderr.
std::optional<StippleSet> load_cached_stipples(const std::filesystem::path& dir, const Mesh& mesh,
                                               const GenerationParams& params, std::span<const float> headroom = {});

// Writes atomically (a temporary file, then a rename), then evicts least recently used entries until
// the folder holds at most `max_bytes` (never the one just written). Failures to write are skipped.
void store_cached_stipples(const std::filesystem::path& dir, const Mesh& mesh, const GenerationParams& params,
                           const StippleSet& stipples, uint64_t max_bytes = kDefaultStippleCacheBytes,
                           std::span<const float> headroom = {});

// What every generated set goes through before use: positions onto the 16-bit barycentric grid, and the
// polygons' selection values (§2.3) ranked and put on their 16-bit steps, as the GPU and the cache hold
// them. So a fresh set equals the one the cache would give back.
void finish_generated_stipples(const Mesh& mesh, uint64_t seed, StippleSet& stipples);

// A selection value's 16-bit step (what TriangleInfo holds), and the value in the middle of a step.
inline uint16_t selection_step(float value) { return uint16_t(std::min(uint32_t(value * 65536.0f), 65535u)); }
inline float selection_from_step(uint16_t step) { return (float(step) + 0.5f) / 65536.0f; }

// generate_stipples through the cache of stipple_cache_settings() (or `dir`, when given): read back
// when present, else generated, with its selection values, and stored. `headroom`: an animated model's
// per-polygon stretch headroom (generate_stipples), part of the key.
StippleSet generate_stipples_cached(const Mesh& mesh, const GenerationParams& params,
                                    std::span<const float> headroom = {});
StippleSet generate_stipples_cached(const Mesh& mesh, const GenerationParams& params,
                                    const std::filesystem::path& dir, std::span<const float> headroom = {});

// The folder's entries (stipple/cache_folder.cpp).
struct CacheEntryInfo {
    std::filesystem::path path;
    uint64_t bytes = 0;
    std::filesystem::file_time_type last_used;
    uint64_t triangles = 0, stipples = 0;
    std::string model;  // the mesh's source file, as loaded
    bool readable = false;  // its header is intact
};
std::vector<CacheEntryInfo> list_cache_entries(const std::filesystem::path& dir);  // most recently used first
// Removes least recently used entries (and temporary files older than an hour, left by killed
// processes) until the folder holds at most `max_bytes`; `keep` is never removed. Returns bytes freed.
uint64_t enforce_cache_limit(const std::filesystem::path& dir, uint64_t max_bytes,
                             const std::filesystem::path& keep = {});
// Removes every entry and temporary file; returns the bytes freed.
uint64_t clear_cache(const std::filesystem::path& dir);

}  // namespace stipple
