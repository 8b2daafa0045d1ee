// The Markdown report: the paper's Table 1 beside ours, then every cell's figures, then per model.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/printf_string.hpp"
#include "bench/bench_output.hpp"
#include "core/error.hpp"

namespace stipple::bench {

namespace {

const CellResult* find_cell(const ModelResult& model, const Column& column) {
    for (const CellResult& cell : model.cells)
        if (cell.column == column) return &cell;
    return nullptr;
}

std::string drawn_text(int64_t drawn) { return drawn < 0 ? "n/a" : with_commas(uint64_t(drawn)); }

}  // namespace

std::string models_note(const BenchResults& r) {
    if (r.sphere_rows.size() >= r.rows_run)
        return "PROCEDURAL UV spheres with each row's polygon count (the scans are not in " + r.models_dir + ")";
    std::string rows;
    for (const std::string& row : r.sphere_rows) rows += (rows.empty() ? "" : ", ") + row;
    return "derived from the scans in " + r.models_dir + " (cache: " + r.cache_dir + "), but " + rows +
           (r.sphere_rows.size() == 1 ? ": a PROCEDURAL UV sphere" : ": PROCEDURAL UV spheres") +
           " with the row's polygon count (the scan is not there)";
}

namespace {

void header_lines(std::ostringstream& md, const BenchResults& r) {
    md << "# stipple bench: the paper's Table 1 on this machine\n\n";
    md << "- device: " << r.device << "\n";
    md << "- image: " << r.width << "x" << r.height << "; standard view: the model framed, yaw " << kViewYawDeg
       << "°, pitch " << kViewPitchDeg << "°, the default light; default parameters (the README's look)\n";
    md << "- frames: " << r.warmup << " warm-up + " << r.frames
       << " timed per cell; fps = 1000 / median wall time of a frame (prepare, record, submit, wait; no read-back)"
       << (r.queued > 1 ? printf_string(", with %d frames queued back to back per submission (--queued: the wall time of "
                                        "the batch over %d; GPU ms are its last frame's)",
                                        r.queued, r.queued)
                        : std::string())
       << "; GPU ms: median of each pass's timestamps\n";
    md << "- models: " << (r.scans_found ? "derived from the scans in " + r.models_dir + " (cache: " + r.cache_dir + ")" : models_note(r))
       << "\n";
    md << "- date: " << r.date << (r.quick ? " (--quick: a reduced set, a few frames a cell: a cell alone may be off by tens of percent)" : "") << "; total " << printf_string("%.0f", r.total_seconds)
       << " s\n";
    if (!r.command.empty()) md << "- command: `" << r.command << "`\n";
    md << "\n";
}

std::string ratio_cell(double fps, double paper) {
    const double ratio = fps / paper;
    const std::string ratio_text = printf_string("%.2f×", ratio);
    return fps_text(fps) + " / " + printf_string("%.2f", paper) + " = " + (ratio < 1.0 ? "**" + ratio_text + "**" : ratio_text);
}

// Table 1's own four columns: where the density is computed (GPU: "vertex program"; CPU: "no vertex
// program"), without and with silhouette lines; each cell is our fastest path of that kind.
void table1_layout(std::ostringstream& md, const BenchResults& r) {
    md << "## Table 1 as the paper lays it out\n\n";
    md << "Each cell: our fastest path that computes the density where the paper's column does (GPU: vertex, "
          "indirect, splat; CPU: cpu, cpu-splat), its median fps / the paper's = ours/paper, **bold** below the "
          "paper.\n\n";
    md << "| model | stipple only, GPU density | stipple only, CPU density | + silhouettes, GPU | + silhouettes, CPU |\n";
    md << "|---|---:|---:|---:|---:|\n";
    for (const ModelResult& m : r.models) {
        md << "| " << m.entry.name << " |";
        for (bool lines : {false, true})
            for (bool cpu : {false, true}) {
                const CellResult* best = nullptr;
                for (const CellResult& cell : m.cells)
                    if (cell.column.lines == lines && cell.column.object_lines == ObjectLines::None &&
                        density_on_cpu(cell.column.path) == cpu && cell.paper_fps &&
                        (!best || cell.median_fps > best->median_fps))
                        best = &cell;
                if (best)
                    md << " " << ratio_cell(best->median_fps, *best->paper_fps) << " ("
                       << density_path_name(best->column.path) << ") |";
                else
                    md << " – |";
            }
        md << "\n";
    }
    md << "\n";
}

void comparison_table(std::ostringstream& md, const BenchResults& r) {
    md << "## Frames per second, ours against the paper's\n\n";
    md << "Each cell: our median fps / the paper's (GeForce3 Ti 500, 2002) = the ratio ours/paper, **bold** where we "
          "are below the paper. The paper's columns say where the density is computed: \"vertex program\" (GPU) is "
          "compared with our vertex, indirect and splat paths, \"no vertex program\" (CPU) with our cpu and "
          "cpu-splat paths; \"+ lines\" adds Raskar-Cohen silhouettes; \"+ contours\", \"+ borders\" and \"+ creases\" "
          "add one kind of object-space line instead (beyond the paper, so without a paper figure).\n\n";
    md << "| model | polygons (paper) | triangles (ours) |";
    for (const Column& c : r.columns) md << " " << c.name() << " |";
    md << "\n|---|---:|---:|";
    for (size_t i = 0; i < r.columns.size(); ++i) md << "---:|";
    md << "\n";
    for (const ModelResult& m : r.models) {
        md << "| " << m.entry.name << (m.entry.procedural ? " (sphere)" : "") << " | " << with_commas(m.entry.target)
           << " | " << with_commas(m.entry.triangles) << " |";
        for (const Column& c : r.columns) {
            const CellResult* cell = find_cell(m, c);
            if (!cell) {
                md << " – |";
            } else if (cell->paper_fps) {
                md << " " << ratio_cell(cell->median_fps, *cell->paper_fps) << " |";
            } else {
                md << " " << fps_text(cell->median_fps) << " |";
            }
        }
        md << "\n";
    }
    md << "\n";
}

void cell_table(std::ostringstream& md, const BenchResults& r) {
    md << "## Every cell\n\n";
    md << "| model | column | median fps | min–max fps | frame ms | GPU ms per pass (median) | GPU ms total | "
          "candidates | drawn | CPU density ms |\n";
    md << "|---|---|---:|---:|---:|---|---:|---:|---:|---:|\n";
    for (const ModelResult& m : r.models)
        for (const CellResult& cell : m.cells) {
            std::string passes;
            for (const auto& [pass, ms] : cell.gpu_ms) passes += printf_string("%s%s %.2f", passes.empty() ? "" : ", ", pass.c_str(), ms);
            std::string cpu = density_on_cpu(cell.column.path) ? printf_string("%.2f", cell.cpu_density_ms) : "–";
            md << "| " << m.entry.name << " | " << cell.column.name() << " | " << fps_text(cell.median_fps) << " | "
               << fps_text(cell.min_fps) << "–" << fps_text(cell.max_fps) << " | "
               << printf_string("%.2f", cell.median_frame_ms) << " | " << (passes.empty() ? "–" : passes) << " | "
               << printf_string("%.2f", cell.gpu_total_ms) << " | " << with_commas(cell.candidates) << " | "
               << drawn_text(cell.drawn) << " | " << cpu << " |\n";
        }
    md << "\n";
}

void model_table(std::ostringstream& md, const BenchResults& r) {
    md << "## Per model\n\n";
    md << "Preprocessing is stipple generation (placement, relaxation, progressive order) and the polygons' "
          "selection ranking (§2.3), both of which the stipple cache keeps. Drawn stipples and ink "
          "come from the standard frame with the default parameters (as in the README image); ink is the share "
          "of the covered pixels with red < 128. GPU memory: all the object's buffers when it draws with the "
          "default path (splat; results.json has every path), per candidate, and without the mesh (positions, "
          "normals, indices); a candidate costs 8 bytes and the splat's three lists 3 more (the work list, the "
          "varying polygons' and the ring pass's: a slot per 4 candidates in each), a polygon 48 (TriangleInfo 16, "
          "TriangleDraw 16, its slot in each of the splat's lists 12 and in the list of polygons large on screen 4) "
          "besides its mesh.\n\n";
    md << "| model | source | triangles | load s | preprocessing s | candidates | drawn | ink | GPU MiB | "
          "bytes / candidate (without mesh) |\n";
    md << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const ModelResult& m : r.models)
        md << "| " << m.entry.name << " | " << m.entry.source << " | " << with_commas(m.entry.triangles) << " | "
           << printf_string("%.2f", m.load_seconds) << " | " << printf_string("%.2f", m.generation_seconds) << " | "
           << with_commas(m.candidates) << " | " << drawn_text(m.drawn) << " | "
           << printf_string("%.1f%%", 100.0 * m.ink_fraction) << " | "
           << printf_string("%.1f", double(m.gpu_bytes) / (1024.0 * 1024.0)) << " | "
           << printf_string("%.1f (%.1f)", m.bytes_per_candidate(), m.stipple_bytes_per_candidate()) << " |\n";
    md << "\n";
}

// Issue 17's target 2: the vertex path within 1.3x of what the rasteriser does with as many points.
void limit_table(std::ostringstream& md, const BenchResults& r) {
    bool any = false;
    for (const ModelResult& m : r.models) any = any || m.limit.has_value();
    if (!any) return;
    md << "## The vertex path against the machine's limit\n\n";
    md << "The limit probe draws as many points as the vertex path's stipple pass (vertex, no lines) with a trivial "
          "shader: the culled ones beyond the far plane, the drawn ones as points of the stipples' size over the model's "
          "footprint; GPU ms are medians of timestamps. x of the limit = the stipple pass / the probe. The second probe "
          "draws the same points with the stipple pass's fixed-function state (depth test, coverage stencil, blending) and "
          "the same trivial shaders: the part of the gap that is that state's work, which any drawing of these stipples "
          "does.\n\n";
    md << "| model | culled | drawn | vertex stipple pass ms | probe ms | x of the limit | probe with state ms | x of it "
          "| ns per candidate (vertex, probe) |\n";
    md << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const ModelResult& m : r.models) {
        if (!m.limit) continue;
        const ModelResult::LimitProbe& l = *m.limit;
        const double n = double(std::max<uint64_t>(l.culled + l.drawn, 1));
        md << "| " << m.entry.name << " | " << with_commas(l.culled) << " | " << with_commas(l.drawn) << " | "
           << printf_string("%.2f", l.vertex_ms) << " | " << printf_string("%.2f", l.probe_ms) << " | " << printf_string("%.2f×", l.ratio())
           << " | " << printf_string("%.2f", l.state_probe_ms) << " | " << printf_string("%.2f×", l.state_ratio())
           << " | " << printf_string("%.0f, %.0f", 1e6 * l.vertex_ms / n, 1e6 * l.probe_ms / n) << " |\n";
    }
    md << "\n";
}

// Issue 17's target 5: the compute splat against the points pipeline, per drawn stipple.
void splat_table(std::ostringstream& md, const BenchResults& r) {
    bool any = false;
    for (const ModelResult& m : r.models) any = any || splat_against_points(m).has_value();
    if (!any) return;
    md << "## The splat against the points pipeline\n\n";
    md << "Per drawn stipple: the indirect path draws the same survivors as the splat (GPU densities) as points, "
          "in one indirect draw. Points = its stipples pass; splat = the splat's dispatches, and with what only the "
          "splat needs (the depth copied to words, the paper filled in, the copy out); GPU ms are medians of "
          "timestamps, no lines.\n\n";
    md << "| model | points ms | splat ms | x | splat with its copies ms | x |\n";
    md << "|---|---:|---:|---:|---:|---:|\n";
    for (const ModelResult& m : r.models) {
        const std::optional<SplatAgainstPoints> s = splat_against_points(m);
        if (!s) continue;
        md << "| " << m.entry.name << " | " << printf_string("%.2f | %.2f | %.2f× | %.2f | %.2f×", s->points_ms, s->splat_ms,
                                                             s->x_kernel(), s->splat_all_ms, s->x())
           << " |\n";
    }
    md << "\n";
}

}  // namespace

std::string with_commas(uint64_t n) {
    std::string digits = std::to_string(n), out;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string fps_text(double fps) {
    if (!std::isfinite(fps)) return "–";
    if (fps >= 100.0) return printf_string("%.0f", fps);
    if (fps >= 10.0) return printf_string("%.1f", fps);
    return printf_string("%.2f", fps);
}

namespace {

// The animated row: the same skinned model static and playing its animation (issue 16).
void animated_table(std::ostringstream& md, const BenchResults& r) {
    if (!r.animated) return;
    const AnimatedRow& a = *r.animated;
    md << "## Animated row\n\n";
    md << a.model << ", " << with_commas(a.triangles) << " triangles, " << with_commas(a.vertices)
       << " vertices, splat path, standard view; animated: its \"Bend\" animation advancing 1/30 s per frame, "
          "the mesh skinned and its polygons recomputed on the GPU each frame (candidates with stretch headroom: "
       << with_commas(a.animated_candidates) << " against " << with_commas(a.static_candidates)
       << " static; largest stretch " << printf_string("%.2f", double(a.max_area_ratio)) << "x).\n\n";
    md << "| | ms/frame | fps | GPU ms | deformation GPU ms | share of the GPU frame | drawn |\n";
    md << "|---|---:|---:|---:|---:|---:|---:|\n";
    md << printf_string("| static | %.2f | %s | %.2f | – | – | %s |\n", a.static_frame_ms, fps_text(1000.0 / a.static_frame_ms).c_str(),
                 a.static_gpu_ms, drawn_text(a.static_drawn).c_str());
    md << printf_string("| animated | %.2f | %s | %.2f | %.2f | %.1f%% | %s |\n\n", a.animated_frame_ms,
                 fps_text(1000.0 / a.animated_frame_ms).c_str(), a.animated_gpu_ms, a.deform_gpu_ms,
                 100.0 * a.deform_share(), drawn_text(a.animated_drawn).c_str());
}

}  // namespace

std::string markdown_report(const BenchResults& results) {
    std::ostringstream md;
    header_lines(md, results);
    table1_layout(md, results);
    comparison_table(md, results);
    cell_table(md, results);
    model_table(md, results);
    animated_table(md, results);
    limit_table(md, results);
    splat_table(md, results);
    if (results.plot_order) md << plot_order_markdown(*results.plot_order);
    for (const std::string& note : results.notes) md << "**Note:** " << note << "\n\n";
    if (results.validation_messages > 0)
        md << "**" << results.validation_messages << " Vulkan validation message(s) during the run: the figures are "
           << "not trustworthy.**\n";
    return md.str();
}

void write_text_file(const std::string& path, const std::string& text) {
    std::filesystem::path p(path);
    std::error_code ec;
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path(), ec);
    if (ec) fail_file(path, "cannot create its folder: " + ec.message());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) fail_file(path, "cannot open for writing");
    out << text;
    if (!out.flush()) fail_file(path, "write failed");
}

}  // namespace stipple::bench
