#include "core/printf_string.hpp"
#include "bench/bench_runner.hpp"

#include "bench/animated_row.hpp"
#include "bench/bench_output.hpp"
#include "bench/limit_probe.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "io/png_io.hpp"
#include "render/camera.hpp"
#include "render/offscreen.hpp"
#include "render/path_buffers.hpp"
#include "render/stipple_renderer.hpp"
#include "core/timing.hpp"
#include "stipple/object_data.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple::bench {

namespace {

std::string utc_now() {
    std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

std::string file_slug(const std::string& name) {
    std::string s;
    for (char c : name) s += c == ' ' ? '-' : c;
    return s;
}

FrameView standard_view(const Sphere& bounds, VkExtent2D extent) {
    float aspect = float(extent.width) / float(extent.height);
    FrameView view;  // default light, ink and paper
    view.extent = extent;
    view.camera = camera_matrices(frame_sphere(bounds, aspect, kViewDistance, kViewYawDeg, kViewPitchDeg), aspect, bounds);
    return view;
}

void set_column(StippleRenderer& renderer, const Column& column) {
    ObjectParams& params = renderer.params(0);
    params.density_path = column.path;
    params.silhouette_lines = column.lines;
    params.contours = column.object_lines == ObjectLines::Contours;
    params.borders = column.object_lines == ObjectLines::Borders;
    params.creases = column.object_lines == ObjectLines::Creases;
}

// Share of covered pixels (depth < 1) whose red channel is below 128.
double ink_inside(const RenderedFrame& frame, uint64_t* covered_out) {
    uint64_t covered = 0, inked = 0;
    for (size_t i = 0; i < frame.depth.size(); ++i) {
        if (frame.depth[i] >= 1.0f) continue;
        ++covered;
        inked += frame.color.pixels[4 * i] < 128;
    }
    *covered_out = covered;
    return covered ? double(inked) / double(covered) : 0.0;
}

// The standard frame's figures and one counting frame per column, on a renderer that counts drawn
// stipples (the counting shader variant is never timed).
void count_frames(const gpu::Context& context, OffscreenTarget& target, const Mesh& mesh, const StippleSet& stipples,
                  const FrameView& view, const BenchOptions& options, const std::vector<Column>& columns,
                  ModelResult& model) {
    RendererOptions counting;
    counting.count_drawn = true;
    StippleRenderer renderer(context, kColorFormat, context.depth_format, counting);
    renderer.add_object(mesh, stipples, glm::mat4(1.0f), ObjectParams{});
    RenderedFrame frame = target.render(renderer, view);
    model.drawn = renderer.stats().drawn_stipples;
    model.candidates = renderer.stats().candidate_stipples;
    model.ink_fraction = ink_inside(frame, &model.covered_pixels);
    if (!options.image_dir.empty()) {
        std::filesystem::path png = options.image_dir / (file_slug(model.entry.name) + ".png");
        write_png(png.string(), frame.color);
        model.image = png.string();
    }
    for (const Column& column : columns) {
        set_column(renderer, column);
        target.draw(renderer, view);
        CellResult cell;
        cell.column = column;
        cell.drawn = renderer.stats().drawn_stipples;
        model.cells.push_back(cell);
    }
}

// `after_frame(timed)` runs after each warm-up (false) and timed (true) frame: the limit probe's frames
// alternate with the cell's, so that both see the same load on a shared machine.
void time_cell(OffscreenTarget& target, StippleRenderer& renderer, const FrameView& view, const BenchOptions& options,
               CellResult& cell, const std::function<void(bool)>& after_frame = {}) {
    set_column(renderer, cell.column);
    for (int i = 0; i < options.warmup; ++i) {
        target.draw_queued(renderer, view, options.queued);
        if (after_frame) after_frame(false);
    }
    std::map<std::string, std::vector<double>> pass_ms;
    std::vector<std::string> pass_order;
    std::vector<double> cpu_ms;
    for (int i = 0; i < options.frames; ++i) {
        cell.frame_ms.push_back(target.draw_queued(renderer, view, options.queued));
        if (after_frame) after_frame(true);
        const FrameStats& stats = renderer.stats();
        for (const auto& [pass, ms] : stats.gpu_ms) {
            if (!pass_ms.count(pass)) pass_order.push_back(pass);
            pass_ms[pass].push_back(ms);
        }
        cpu_ms.push_back(stats.cpu_density_ms);
        cell.candidates = stats.candidate_stipples;
    }
    cell.median_frame_ms = median(cell.frame_ms);
    auto [fastest, slowest] = std::minmax_element(cell.frame_ms.begin(), cell.frame_ms.end());
    cell.median_fps = 1000.0 / cell.median_frame_ms;
    cell.min_fps = 1000.0 / *slowest;
    cell.max_fps = 1000.0 / *fastest;
    for (const std::string& pass : pass_order) {
        double ms = median(pass_ms[pass]);
        cell.gpu_ms.emplace_back(pass, ms);
        cell.gpu_total_ms += ms;
    }
    cell.cpu_density_ms = median(cpu_ms);
}

double pass_ms(const CellResult& cell, const std::string& pass) {
    for (const auto& [name, ms] : cell.gpu_ms)
        if (name == pass) return ms;
    return 0.0;
}

// The probe goes with the vertex column without lines (the paper's "stipple only"), with its counts.
bool probed(const CellResult& cell) { return cell.column == Column{DensityPath::Vertex, false, ObjectLines::None} && cell.drawn >= 0; }

std::string passes_text(const CellResult& cell) {
    std::string text;
    for (const auto& [pass, ms] : cell.gpu_ms) text += printf_string(" %s %.2f", pass.c_str(), ms);
    return text.empty() ? " (no timestamps)" : text;
}

}  // namespace

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<std::pair<std::string, uint64_t>> object_buffers(const ObjectGpu& object, DensityPath path) {
    std::vector<std::pair<std::string, uint64_t>> buffers = {
        {"positions", object.geometry.positions.size()},         {"normals", object.geometry.normals.size()},
        {"indices", object.geometry.indices.size()},             {"stipples", object.geometry.stipples.size()},
        {"triangle_info", object.polygons.gpu.size()}, {"triangle_draw", object.frame.triangle_draw.size()},
        {"debug", object.frame.debug.size()},                 {"object_uniforms", object.frame.object_uniforms.size()},
    };
    for (PathBuffer kind : kPathBuffers) {  // the path's own at full size, the others placeholders
        uint64_t bytes = path_buffer_bytes(object, path, kind);
        buffers.emplace_back(path_buffer_name(kind), bytes ? bytes : kPathBufferPlaceholderBytes);
    }
    return buffers;
}

std::string look_note(const ModelResult& model) {
    if (model.entry.name != "bunny" || model.entry.procedural) return "";
    // 51,450 drawn with solid last dots (the default since 2026-12-06), 64,036 with the paper's faint ones.
    bool drawn_ok = model.drawn >= 35'000 && model.drawn <= 150'000;
    bool ink_ok = model.ink_fraction >= 0.15 && model.ink_fraction <= 0.35;
    if (drawn_ok && ink_ok) return "";
    return printf_string("the bunny's standard frame holds %lld drawn stipples and %.1f%% ink inside its footprint; "
                  "the default look should give 35k-150k and 15-35%%",
                  (long long)model.drawn, 100.0 * model.ink_fraction);
}

BenchResults run_bench(const BenchOptions& requested, const Logger& log) {
    auto run_start = Clock::now();
    BenchOptions options = requested;
    BenchResults results;
    results.command = options.command;
    results.date = utc_now();
    results.width = options.width;
    results.height = options.height;
    results.frames = options.frames;
    results.warmup = options.warmup;
    results.quick = options.quick;
    results.depth_cull = depth_cull_name(options.depth_cull);
    results.depth_raster = depth_raster_name(options.depth_raster);
    results.models_dir = options.models_dir.string();
    results.cache_dir = options.cache_dir.string();
    results.sphere_rows = options.animated_only ? std::vector<std::string>{} : rows_without_scans(options.models_dir, options.models);
    results.scans_found = results.sphere_rows.empty();
    results.rows_run = options.animated_only ? 0 : options.models.empty() ? std::size(kPaperTable) : options.models.size();
    results.columns = make_columns(options.paths.empty() ? all_density_paths() : options.paths, options.object_lines);

    // The device first: a bad --device fails before any model is derived.
    gpu::ContextOptions context_options;
    context_options.device_index = options.device;
    gpu::Context context(context_options);
    results.device = context.device_name;
    if (options.queued == 0) options.queued = OffscreenTarget::default_queued_frames(context);
    results.queued = options.queued;

    if (!results.scans_found) log("NOTE: " + models_note(results));
    ModelSetOptions set_options;
    set_options.models_dir = options.models_dir;
    set_options.cache_dir = options.cache_dir;
    set_options.only = options.models;
    set_options.log = log;
    std::vector<ModelEntry> entries = options.animated_only ? std::vector<ModelEntry>{} : prepare_model_set(set_options);

    const VkExtent2D extent{options.width, options.height};
    auto target_holder = std::make_unique<OffscreenTarget>(context, extent);
    OffscreenTarget& target = *target_holder;
    auto probe_holder = std::make_unique<LimitProbe>(context, extent);
    log(printf_string("device: %s; %ux%u; %d warm-up + %d timed frames per cell; view yaw %.0f, pitch %.0f",
               context.device_name.c_str(), options.width, options.height, options.warmup, options.frames,
               double(kViewYawDeg), double(kViewPitchDeg)));

    for (ModelEntry& entry : entries) {
        ModelResult model;
        auto start = Clock::now();
        Mesh mesh = load_model(entry, set_options);  // a damaged derived model is derived again
        model.entry = entry;
        model.load_seconds = seconds_since(start);
        ObjectParams params;  // the defaults: the README's look
        // Generated every time (not from the stipple cache): the benchmark times the preprocessing. Checked
        // against the machine's memory first, as every command's models are.
        check_generation_fits_memory(entry.path.empty() ? entry.source : entry.path.string(),
                                     planned_stipple_count(mesh, params.generation));
        const std::shared_ptr<const StippleSet> generated = make_stipples(mesh, params.generation, StippleSource::Generate);
        const StippleSet& stipples = *generated;
        model.generation_seconds = stipples.generation_seconds;
        Sphere bounds = compute_bounding_sphere(mesh);
        bounds.center += glm::vec3(mesh.origin);  // where the renderer puts it (object_to_world)
        const FrameView view = standard_view(bounds, extent);

        count_frames(context, target, mesh, stipples, view, options, results.columns, model);
        log(printf_string("%s: %zu triangles (%s); load %.2f s, stipple generation %.2f s; %llu candidates, "
                   "%lld drawn, ink %.1f%% of %llu covered pixels",
                   entry.name.c_str(), mesh.triangle_count(), entry.source.c_str(), model.load_seconds,
                   model.generation_seconds, (unsigned long long)model.candidates, (long long)model.drawn,
                   100.0 * model.ink_fraction, (unsigned long long)model.covered_pixels));

        if (std::string note = look_note(model); !note.empty()) {
            log("NOTE: " + note);
            results.notes.push_back(note);
        }

        RendererOptions renderer_options;
        renderer_options.depth_cull = options.depth_cull;
        renderer_options.depth_raster = options.depth_raster;
        StippleRenderer renderer(context, kColorFormat, context.depth_format, renderer_options);
        start = Clock::now();
        renderer.add_object(mesh, stipples, glm::mat4(1.0f), params);
        model.upload_seconds = seconds_since(start);
        model.buffers = object_buffers(renderer.object(0), kMemoryPath);
        for (const auto& [name, bytes] : model.buffers) {
            model.gpu_bytes += bytes;
            if (name == "positions" || name == "normals" || name == "indices") model.mesh_bytes += bytes;
        }
        for (DensityPath path : kAllDensityPaths) {
            uint64_t bytes = 0;
            for (const auto& entry : object_buffers(renderer.object(0), path)) bytes += entry.second;
            model.gpu_bytes_by_path.emplace_back(density_path_name(path), bytes);
        }
        const PaperRow* row = find_paper_row(entry.name);
        for (CellResult& cell : model.cells) {
            std::optional<ModelResult::LimitProbe> limit;
            std::function<void(bool)> probe_frame;
            if (probed(cell)) {
                limit.emplace();
                limit->drawn = uint64_t(cell.drawn);
                limit->culled = model.candidates - std::min<uint64_t>(model.candidates, limit->drawn);
                probe_frame = [&](bool timed) {
                    const float point_size = drawn_point_size(renderer.params(0).point_size);  // as the stipples are drawn
                    const double ms = probe_holder->frame(limit->culled, limit->drawn, model.covered_pixels, point_size);
                    const double state_ms =
                        probe_holder->frame(limit->culled, limit->drawn, model.covered_pixels, point_size, true);
                    if (timed) limit->probe_frame_ms.push_back(ms), limit->state_probe_frame_ms.push_back(state_ms);
                };
            }
            time_cell(target, renderer, view, options, cell, probe_frame);
            if (limit) {
                limit->vertex_ms = pass_ms(cell, "stipples");
                limit->probe_ms = median(limit->probe_frame_ms);
                limit->state_probe_ms = median(limit->state_probe_frame_ms);
                model.limit = std::move(limit);
            }
            if (row) cell.paper_fps = paper_fps(*row, cell.column);
            std::string paper = cell.paper_fps ? printf_string(" (paper %.2f, x%.2f)", *cell.paper_fps,
                                                        cell.median_fps / *cell.paper_fps)
                                               : std::string();
            log(printf_string("  %-18s %8.2f fps%s, min-max %.2f-%.2f; gpu ms:%s; drawn %lld of %llu",
                       cell.column.name().c_str(), cell.median_fps, paper.c_str(), cell.min_fps, cell.max_fps,
                       passes_text(cell).c_str(), (long long)cell.drawn, (unsigned long long)cell.candidates));
        }
        if (model.limit)
            log(printf_string("  limit probe: %llu culled + %llu drawn points in %.2f ms (%.2f with the stipple pass's depth, "
                       "stencil and blending); the vertex path's stipple pass %.2f ms = %.2fx the limit (%.2fx with that state)",
                       (unsigned long long)model.limit->culled, (unsigned long long)model.limit->drawn,
                       model.limit->probe_ms, model.limit->state_probe_ms, model.limit->vertex_ms, model.limit->ratio(),
                       model.limit->state_ratio()));
        std::string by_path;
        for (const auto& [path, bytes] : model.gpu_bytes_by_path)
            by_path += printf_string(" %s %.1f", path.c_str(), model.candidates ? double(bytes) / double(model.candidates) : 0.0);
        log(printf_string("  GPU memory (%s path): %.1f MiB, %.1f bytes per candidate (%.1f without the mesh); by path:%s",
                   density_path_name(kMemoryPath), double(model.gpu_bytes) / (1024.0 * 1024.0),
                   model.bytes_per_candidate(), model.stipple_bytes_per_candidate(), by_path.c_str()));
        results.models.push_back(std::move(model));
    }
    if (options.animated_triangles > 0) results.animated = run_animated_row(context, target, options, log);
    probe_holder.reset();
    target_holder.reset();  // everything but the context is gone: destruction messages are counted too
    results.validation_messages = context.validation_message_count();
    results.total_seconds = seconds_since(run_start);
    return results;
}

std::optional<SplatAgainstPoints> splat_against_points(const ModelResult& model) {
    const CellResult *points = nullptr, *splat = nullptr;
    for (const CellResult& cell : model.cells) {
        if (cell.column.lines || cell.column.object_lines != ObjectLines::None) continue;
        if (cell.column.path == DensityPath::Indirect) points = &cell;
        if (cell.column.path == DensityPath::Splat) splat = &cell;
    }
    if (!points || !splat) return std::nullopt;
    auto pass_ms = [](const CellResult& cell, const std::string& pass) {
        for (const auto& [name, ms] : cell.gpu_ms)
            if (name == pass) return ms;
        return 0.0;
    };
    SplatAgainstPoints r;
    r.points_ms = pass_ms(*points, "stipples");
    r.splat_ms = pass_ms(*splat, "splat");
    r.splat_all_ms = r.splat_ms;
    for (const char* pass : {"depth_copy", "splat_in", "splat_out"}) r.splat_all_ms += pass_ms(*splat, pass);
    if (r.points_ms <= 0.0 || r.splat_ms <= 0.0) return std::nullopt;
    return r;
}

}  // namespace stipple::bench
