#pragma once
// The benchmark's model set: one model per row of the paper's Table 1, each with the row's polygon
// count within 2%, derived deterministically from the real scans in ../shared/models (simplified with
// meshoptimizer, or subdivided and then simplified) and cached as binary PLY outside the repository.
// Without the scans, each row is a procedural UV sphere of the row's count.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace stipple::bench {

// Bumped whenever the derivation changes, so cached files are rebuilt.
inline constexpr int kDerivationVersion = 4;
inline constexpr double kRowTolerance = 0.02;  // ±2% of the row's polygon count

// How a row is made: from which scan (a file in the models folder). The number of subdivisions is
// the smallest that reaches the row's count; simplification then brings it down to the row. A scan
// stored Z-up is turned Y-up in the derived file, so that every model stands upright in the bench's view;
// a scan wound inside out (the horse) has its triangles reversed.
struct Recipe {
    const char* row;
    const char* source;
    bool z_up = false;
};
extern const std::vector<Recipe> kRecipes;  // one per Table 1 row, in the table's order

struct ModelEntry {
    std::string name;            // Table 1's row name
    size_t target = 0;           // the row's polygon count
    size_t triangles = 0;        // the model's
    bool procedural = false;     // a UV sphere (no scans found)
    std::string source;          // what it was made from, for tables: "horse.ply, simplified", "procedural UV sphere"
    std::filesystem::path path;  // the file to load ("" when procedural)
    bool derived_now = false;    // written during this call (not from the cache)
};

struct ModelSetOptions {
    std::filesystem::path models_dir = default_models_dir();
    std::filesystem::path cache_dir = default_cache_dir();
    std::vector<std::string> only;  // row names to prepare; empty: all
    std::function<void(const std::string&)> log;  // progress lines (may be empty)

    static std::filesystem::path default_models_dir();  // $STIPPLE_SHARED_MODELS, or <source>/../shared/models
    static std::filesystem::path default_cache_dir();   // $STIPPLE_CACHE_DIR/bench-models, or <build>/bench-models
};

// True when every scan the rows need is in `models_dir` (`rows`: names of Table 1's rows; empty: all).
bool scans_available(const std::filesystem::path& models_dir, const std::vector<std::string>& rows = {});
// The rows (of `rows`, or all) whose scan is not in `models_dir`: each is a UV sphere of its polygon count.
std::vector<std::string> rows_without_scans(const std::filesystem::path& models_dir, const std::vector<std::string>& rows = {});

// Prepares the requested rows: with the scans, derives each missing or stale model into the cache
// (stale: the key file's source size, mtime, target or derivation version differ); without them,
// procedural entries. Throws stipple::Error on an unknown row name or a failed derivation.
std::vector<ModelEntry> prepare_model_set(const ModelSetOptions& options);

// The entry's mesh: its file loaded, or the procedural sphere.
Mesh load_model(const ModelEntry& entry);
// load_model, but a derived model that does not load (truncated or damaged in the cache) is derived again from
// its scan, said through options.log, and `entry` updated: the stipple cache regenerates a damaged entry too.
Mesh load_model(ModelEntry& entry, const ModelSetOptions& options);

}  // namespace stipple::bench
