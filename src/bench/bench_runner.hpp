#pragma once
// The benchmark run: for each model of the set, stipple generation (timed), a counting frame per
// column (drawn stipples), a read-back frame of the standard view (ink coverage), then per column
// warm-up frames and timed frames (wall clock per frame and GPU time per pass from timestamps).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "bench/model_set.hpp"
#include "bench/plot_order_row.hpp"
#include "bench/table1.hpp"
#include "params/object_params.hpp"
#include "render/depth_raster.hpp"
#include "render/depth_triangles.hpp"

namespace stipple {
struct ObjectGpu;
}

namespace stipple::bench {

// The standard view: the model framed (its bounding sphere fills the view), seen from a little to
// the right and above, with the renderer's default light (upper left, in front, moving with the camera).
inline constexpr float kViewYawDeg = 30.0f;
inline constexpr float kViewPitchDeg = 15.0f;
inline constexpr float kViewDistance = 1.0f;  // multiple of the framing distance

struct BenchOptions {
    std::vector<std::string> models;  // Table 1 row names; empty: all
    std::vector<DensityPath> paths;   // empty: all
    int frames = 20;                  // timed frames per cell
    int warmup = 3;                   // untimed frames before them
    // Frames queued back to back per submission (OffscreenTarget::draw_queued); each timed frame is then
    // the batch's wall time over this. 1: every frame waited on; 0: by the device
    // (OffscreenTarget::default_queued_frames).
    int queued = 0;
    uint32_t width = 1280, height = 1024;
    int device = -1;                  // Vulkan device index (-1: the best)
    bool quick = false;               // recorded in the results (the caller picks the reduced set)
    bool object_lines = true;         // also the columns with contours, borders, creases (beyond the paper)
    std::filesystem::path models_dir = ModelSetOptions::default_models_dir();
    std::filesystem::path cache_dir = ModelSetOptions::default_cache_dir();
    std::filesystem::path image_dir;  // where to write each model's standard frame as PNG ("" = none)
    // The animated row (issue 16): a skinned bending cylinder of at least this many triangles, timed with
    // and without its animation. 0: no animated row.
    uint32_t animated_triangles = 100'000;
    bool animated_only = false;  // the animated row alone (no Table 1 rows)
    DepthCull depth_cull = DepthCull::Auto;  // the depth pass's triangle lists (render/depth_triangles.hpp)
    DepthRaster depth_raster = DepthRaster::Auto;  // the depth pass as compute (render/depth_raster.hpp)
    std::string command;              // the command line, recorded in the results
};

struct CellResult {
    Column column;
    std::vector<double> frame_ms;  // each timed frame, wall clock (prepare + record + submit + wait)
    double median_fps = 0.0, min_fps = 0.0, max_fps = 0.0;
    double median_frame_ms = 0.0;
    std::vector<std::pair<std::string, double>> gpu_ms;  // median GPU time per pass, in pass order
    double gpu_total_ms = 0.0;                           // sum of those medians
    double cpu_density_ms = 0.0;                         // median CPU density time (cpu path)
    uint64_t candidates = 0;
    int64_t drawn = -1;  // from the counting frame of this column; -1 when the path does not count
    std::optional<double> paper_fps;
};

// Declared outside ModelResult: clang 15 cannot use a nested struct's default member initialisers in
// std::optional before the enclosing class is complete.
struct LimitProbeResult {
    uint64_t culled = 0, drawn = 0;
    double vertex_ms = 0.0;  // the vertex column's "stipples" pass, median GPU ms
    double probe_ms = 0.0;   // the probe's pass, median GPU ms
    std::vector<double> probe_frame_ms;  // each frame's
    // The same points with the stipple pass's depth, stencil and blending (limit_probe.hpp).
    double state_probe_ms = 0.0;
    std::vector<double> state_probe_frame_ms;
    double ratio() const { return probe_ms > 0.0 ? vertex_ms / probe_ms : 0.0; }  // "x of the limit"
    double state_ratio() const { return state_probe_ms > 0.0 ? vertex_ms / state_probe_ms : 0.0; }
};

struct ModelResult {
    ModelEntry entry;
    double load_seconds = 0.0;
    double generation_seconds = 0.0;  // preprocessing: stipple generation (relaxation, progressive order), selection ranking
    double upload_seconds = 0.0;      // add_object: GPU buffers created and filled
    uint64_t candidates = 0;
    int64_t drawn = -1;               // standard frame (default parameters)
    uint64_t covered_pixels = 0;
    double ink_fraction = 0.0;        // share of covered pixels with red < 128
    std::vector<std::pair<std::string, uint64_t>> buffers;  // the object's GPU buffers with kMemoryPath, bytes
    uint64_t gpu_bytes = 0;           // all of them
    std::vector<std::pair<std::string, uint64_t>> gpu_bytes_by_path;  // the same total with each density path
    uint64_t mesh_bytes = 0;          // positions, normals, indices (the depth pass's)
    std::string image;                // the standard frame's PNG, when written
    std::vector<CellResult> cells;
    // The limit probe (issue 17): the vertex path's stipple pass against a bare pass drawing as many
    // culled and drawn points (bench/limit_probe.hpp); measured when the vertex column is in the run.
    using LimitProbe = LimitProbeResult;
    std::optional<LimitProbe> limit;

    double bytes_per_candidate() const { return candidates ? double(gpu_bytes) / double(candidates) : 0.0; }
    double stipple_bytes_per_candidate() const {
        return candidates ? double(gpu_bytes - mesh_bytes) / double(candidates) : 0.0;
    }
};

// Issue 17's target 5, the splat against the points pipeline per drawn stipple: the indirect path draws
// the same survivors as the splat (the same GPU densities) through the rasteriser's points, one indirect
// draw of the listed stipples, so the ratio of the two passes' GPU times is the ratio per drawn stipple.
// From the cells without lines of both paths; none when either is not in the run.
struct SplatAgainstPoints {
    double points_ms = 0.0;      // the indirect cell's "stipples" pass, median GPU ms
    double splat_ms = 0.0;       // the splat cell's "splat" pass (the dispatches)
    double splat_all_ms = 0.0;   // with what only the splat needs: the depth's copy, the paper fill, the copy out
    double x() const { return splat_all_ms > 0.0 ? points_ms / splat_all_ms : 0.0; }
    double x_kernel() const { return splat_ms > 0.0 ? points_ms / splat_ms : 0.0; }
};
std::optional<SplatAgainstPoints> splat_against_points(const ModelResult& model);

// The animated row: the same skinned model drawn static (its rest mesh, stipples without headroom) and
// playing its animation (deformation pass each frame, stipples with headroom), standard view, splat path.
struct AnimatedRow {
    std::string model;                  // what it is, e.g. "bending cylinder, 2 joints (200 rings x 256 segments)"
    uint64_t triangles = 0, vertices = 0;
    uint64_t static_candidates = 0, animated_candidates = 0;
    float max_area_ratio = 1.0f;        // the animation's largest polygon stretch
    double static_frame_ms = 0.0, animated_frame_ms = 0.0;  // median wall time per frame (as the cells)
    double static_gpu_ms = 0.0, animated_gpu_ms = 0.0;      // median GPU time of all passes
    double deform_gpu_ms = 0.0;         // median GPU time of the deformation pass (skinning + polygon constants)
    int64_t static_drawn = -1, animated_drawn = -1;  // drawn stipples in a counting frame
    double deform_share() const { return animated_gpu_ms > 0.0 ? deform_gpu_ms / animated_gpu_ms : 0.0; }
};

struct BenchResults {
    std::string command;
    std::string device;
    std::string date;  // UTC, ISO 8601
    uint32_t width = 0, height = 0;
    int frames = 0, warmup = 0, queued = 1;
    bool quick = false;
    std::string depth_cull = "auto", depth_raster = "auto";  // the options' names, for --compare
    std::string models_dir;
    bool scans_found = false;                 // every row run from its scan
    std::vector<std::string> sphere_rows;     // the rows run without their scans, as UV spheres
    size_t rows_run = 0;                      // rows asked (the animated row not counted)
    std::string cache_dir;
    std::vector<Column> columns;
    std::vector<ModelResult> models;
    std::optional<AnimatedRow> animated;
    double total_seconds = 0.0;
    uint32_t validation_messages = 0;
    std::vector<std::string> notes;  // checks that did not hold (printed and written with the tables)
    std::optional<PlotOrderRow> plot_order;  // filled by the caller after the run, when it measures it
};

// The check of the default look: the bunny's standard frame holds 50k-150k drawn stipples and
// 15-35% ink inside its footprint. Returns "" when it holds (or for other models), else a note.
std::string look_note(const ModelResult& model);

using Logger = std::function<void(const std::string&)>;

// Runs the benchmark. Throws stipple::Error on a bad model name, a failed load or a Vulkan failure.
BenchResults run_bench(const BenchOptions& options, const Logger& log);

// The object's GPU buffers by name and size (what "GPU bytes per candidate" sums).
std::vector<std::pair<std::string, uint64_t>> object_buffers(const ObjectGpu& object, DensityPath path);

// The path whose buffers the per-model GPU memory figures count: the default one.
inline constexpr DensityPath kMemoryPath = DensityPath::Splat;

// Median of the values (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> values);

}  // namespace stipple::bench
