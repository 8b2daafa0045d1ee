// results.json: every figure of the run, raw frame times included, for scripts and the tests.
#include <cmath>

#include <nlohmann/json.hpp>

#include "bench/bench_output.hpp"

namespace stipple::bench {

namespace {

using nlohmann::json;

json cell_json(const CellResult& cell) {
    json passes = json::array();
    for (const auto& [pass, ms] : cell.gpu_ms) passes.push_back({{"pass", pass}, {"ms", ms}});
    json j = {
        {"path", density_path_name(cell.column.path)},
        {"silhouettes", cell.column.lines ? "lines" : "none"},
        {"object_lines", object_lines_name(cell.column.object_lines)},
        {"column", cell.column.name()},
        {"median_fps", cell.median_fps},
        {"min_fps", cell.min_fps},
        {"max_fps", cell.max_fps},
        {"median_frame_ms", cell.median_frame_ms},
        {"frame_ms", cell.frame_ms},
        {"gpu_ms", passes},
        {"gpu_total_ms", cell.gpu_total_ms},
        {"candidate_stipples", cell.candidates},
        {"drawn_stipples", cell.drawn},
        {"cpu_density_ms", cell.cpu_density_ms},
    };
    j["paper_fps"] = cell.paper_fps ? json(*cell.paper_fps) : json(nullptr);
    j["ratio_to_paper"] = cell.paper_fps ? json(cell.median_fps / *cell.paper_fps) : json(nullptr);
    return j;
}

json splat_json(const ModelResult& m) {
    const std::optional<SplatAgainstPoints> s = splat_against_points(m);
    if (!s) return nullptr;
    return {{"points_ms", s->points_ms}, {"splat_ms", s->splat_ms}, {"splat_with_copies_ms", s->splat_all_ms},
            {"x", s->x()}, {"x_kernel", s->x_kernel()}};
}

json limit_json(const ModelResult& m) {
    if (!m.limit) return nullptr;
    const ModelResult::LimitProbe& l = *m.limit;
    return {{"culled_points", l.culled},
            {"drawn_points", l.drawn},
            {"vertex_stipples_ms", l.vertex_ms},
            {"probe_ms", l.probe_ms},
            {"probe_frame_ms", l.probe_frame_ms},
            {"x_of_limit", l.ratio()},
            {"state_probe_ms", l.state_probe_ms},
            {"state_probe_frame_ms", l.state_probe_frame_ms},
            {"x_of_state_limit", l.state_ratio()}};
}

json model_json(const ModelResult& m) {
    json buffers = json::object();
    for (const auto& [name, bytes] : m.buffers) buffers[name] = bytes;
    json by_path = json::object();
    for (const auto& [path, bytes] : m.gpu_bytes_by_path)
        by_path[path] = {{"bytes", bytes},
                         {"bytes_per_candidate", m.candidates ? double(bytes) / double(m.candidates) : 0.0}};
    json cells = json::array();
    for (const CellResult& cell : m.cells) cells.push_back(cell_json(cell));
    return {
        {"name", m.entry.name},
        {"paper_polygons", m.entry.target},
        {"triangles", m.entry.triangles},
        {"procedural", m.entry.procedural},
        {"source", m.entry.source},
        {"file", m.entry.path.string()},
        {"load_seconds", m.load_seconds},
        {"preprocessing_seconds", m.generation_seconds},
        {"upload_seconds", m.upload_seconds},
        {"candidate_stipples", m.candidates},
        {"drawn_stipples", m.drawn},
        {"covered_pixels", m.covered_pixels},
        {"ink_fraction", m.ink_fraction},
        {"gpu_buffers", buffers},
        {"gpu_bytes", m.gpu_bytes},
        {"gpu_mesh_bytes", m.mesh_bytes},
        {"gpu_bytes_per_candidate", m.bytes_per_candidate()},
        {"gpu_bytes_per_candidate_without_mesh", m.stipple_bytes_per_candidate()},
        {"gpu_bytes_counted_path", density_path_name(kMemoryPath)},
        {"gpu_bytes_by_path", by_path},
        {"image", m.image},
        {"cells", cells},
        {"limit_probe", limit_json(m)},
        {"splat_against_points", splat_json(m)},
    };
}

json plot_figures_json(const std::optional<PlotOrderFigures>& f) {
    if (!f) return nullptr;
    json j = {{"dots", f->dots}, {"order_seconds", f->order_seconds}, {"travel_ratio", f->travel_ratio}};
    // Each figure only where it was measured: a random order on the blue noise, a capture for the bunny.
    j["random_ratio"] = f->random_ratio > 0.0 ? json(f->random_ratio) : json(nullptr);
    j["capture_seconds"] = f->capture_seconds > 0.0 ? json(f->capture_seconds) : json(nullptr);
    return j;
}

json plot_order_json(const std::optional<PlotOrderRow>& row) {
    if (!row) return nullptr;
    json j = {{"blue noise", plot_figures_json(row->blue_noise)}, {"bunny view", plot_figures_json(row->bunny_view)}};
    if (!row->bunny_note.empty()) j["bunny_note"] = row->bunny_note;
    return j;
}

}  // namespace

std::string json_report(const BenchResults& r) {
    json columns = json::array();
    for (const Column& c : r.columns)
        columns.push_back({{"name", c.name()},
                           {"path", density_path_name(c.path)},
                           {"silhouettes", c.lines ? "lines" : "none"},
                           {"object_lines", object_lines_name(c.object_lines)},
                           {"paper_column", paper_column_name(c)}});
    json paper = json::array();
    for (const PaperRow& row : kPaperTable)
        paper.push_back({{"name", row.name},
                         {"polygons", row.polygons},
                         {"vertex", row.vertex},
                         {"cpu", row.cpu},
                         {"vertex_lines", row.vertex_lines},
                         {"cpu_lines", row.cpu_lines}});
    json models = json::array();
    for (const ModelResult& m : r.models) models.push_back(model_json(m));
    json j = {
        {"command", r.command},
        {"device", r.device},
        {"date", r.date},
        {"width", r.width},
        {"height", r.height},
        {"warmup_frames", r.warmup},
        {"queued_frames", r.queued},
        {"timed_frames", r.frames},
        {"quick", r.quick},
        {"depth_cull", r.depth_cull},
        {"depth_raster", r.depth_raster},
        {"view", {{"yaw_deg", kViewYawDeg}, {"pitch_deg", kViewPitchDeg}, {"distance", kViewDistance}}},
        {"models_dir", r.models_dir},
        {"scans_found", r.scans_found},
        {"sphere_rows", r.sphere_rows},
        {"cache_dir", r.cache_dir},
        {"columns", columns},
        {"paper_table", paper},
        {"models", models},
        {"total_seconds", r.total_seconds},
        {"validation_messages", r.validation_messages},
        {"notes", r.notes},
        {"plot_order", plot_order_json(r.plot_order)},
    };
    if (r.animated) {
        const AnimatedRow& a = *r.animated;
        j["animated"] = {{"model", a.model},
                         {"triangles", a.triangles},
                         {"vertices", a.vertices},
                         {"static_candidates", a.static_candidates},
                         {"animated_candidates", a.animated_candidates},
                         {"max_area_ratio", a.max_area_ratio},
                         {"static_frame_ms", a.static_frame_ms},
                         {"animated_frame_ms", a.animated_frame_ms},
                         {"static_gpu_ms", a.static_gpu_ms},
                         {"animated_gpu_ms", a.animated_gpu_ms},
                         {"deform_gpu_ms", a.deform_gpu_ms},
                         {"deform_share_of_gpu_frame", a.deform_share()},
                         {"static_drawn", a.static_drawn},
                         {"animated_drawn", a.animated_drawn}};
    }
    return j.dump(2) + "\n";
}

}  // namespace stipple::bench
