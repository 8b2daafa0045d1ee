#pragma once
// An on-disk cache of generated stipples: reopening a model with the same parameters reads its
// candidates back instead of generating them again (generation is ~1 s per million stipples).
#include <filesystem>
#include <optional>

#include "mesh/mesh.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {

// $STIPPLE_CACHE_DIR/stipples, else $XDG_CACHE_HOME/stipple/stipples, else ~/.cache/stipple/stipples.
std::filesystem::path default_stipple_cache_dir();

// A key of everything the stipples depend on: the mesh's triangles and positions, the parameters
// that shape generation (the parameter table's Regenerate entries), an animated model's stretch
// headroom (generate_stipples) and the format version.
uint64_t stipple_cache_key(const Mesh& mesh, const GenerationParams& params, std::span<const float> headroom = {});

// The cached set, or nothing when absent, from another version, or damaged in any way (a damaged
// entry is never an error: the caller regenerates and overwrites it).
std::optional<StippleSet> load_cached_stipples(const std::filesystem::path& dir, const Mesh& mesh,
                                               const GenerationParams& params, std::span<const float> headroom = {});

// Writes atomically (a temporary file, then a rename); failures to write are silently skipped.
void store_cached_stipples(const std::filesystem::path& dir, const Mesh& mesh, const GenerationParams& params,
                           const StippleSet& stipples, std::span<const float> headroom = {});

// generate_stipples through the cache in `dir` (bypassed when STIPPLE_NO_CACHE is set and not "0").
StippleSet generate_stipples_cached(const Mesh& mesh, const GenerationParams& params,
                                    const std::filesystem::path& dir = default_stipple_cache_dir(),
                                    std::span<const float> headroom = {});

}  // namespace stipple
