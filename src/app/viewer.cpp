// `stipple view` (app/viewer.hpp): the viewer opened, its loop (drawing on demand), the script, the
// input and the panel's requests. One frame is viewer_frame.cpp's.
#include "app/viewer.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "app/frame_export.hpp"
#include "export/plot_file.hpp"
#include "export/text_format.hpp"
#include "app/viewer_session.hpp"
#include "core/error.hpp"
#include "core/printf_string.hpp"
#include "gpu/vk_check.hpp"
#include "params/param_table.hpp"
#include "render/object_gpu.hpp"
#include "render/offscreen.hpp"

namespace stipple::app {

namespace {

RendererOptions renderer_options(const ViewerOptions& options) {
    RendererOptions r;
    r.count_drawn = options.count_drawn;
    r.depth_cull = options.depth_cull;
    r.depth_raster = options.depth_raster;
    return r;
}

// Mesa's software swapchain sends each frame through the X socket unless the server has DRI3 (Xvfb,
// Xvnc, X without a GPU driver do not): on a CPU device, X11 shared memory instead where it works.
std::unique_ptr<X11SharedMemory> shared_memory_for(const ViewerOptions& options, const gpu::Context& context,
                                                   const Window& window) {
    const auto say = [&](const char* how, const std::string& why) {
        if (options.verbose) std::printf("stipple: presenting through %s: %s\n", how, why.c_str());
    };
    if (options.present == PresentMethod::Swapchain) {
        say("the swapchain", "--present swapchain");
        return nullptr;
    }
    if (options.present == PresentMethod::Auto && context.properties.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU) {
        say("the swapchain", "a GPU device");
        return nullptr;
    }
    std::string why;
    std::unique_ptr<X11SharedMemory> shared = X11SharedMemory::open(window.handle(), &why);
    if (!shared && options.present == PresentMethod::SharedMemory) fail("--present shm: " + why);
    if (!shared) say("the swapchain", why);
    else say("X11 shared memory", options.present == PresentMethod::SharedMemory
                                      ? "--present shm"
                                      : "a CPU device, whose swapchain would write every frame into the X socket");
    return shared;
}

gpu::ContextOptions context_options(const ViewerOptions& options) {
    gpu::ContextOptions o;
    o.device_index = options.device_index;
    o.verbose = options.verbose;
    o.instance_extensions = Window::required_instance_extensions();
    o.swapchain = true;
    return o;
}

std::string window_title(const Scene& scene) {
    std::string name = scene.source.empty() ? std::filesystem::path(scene.objects.at(0).model).filename().string()
                                            : std::filesystem::path(scene.source).filename().string();
    return "stipple - " + name;
}

}  // namespace

Viewer::Viewer(Scene scene, SceneContent content, const ViewerOptions& options)
    : options_(options),
      window_(options.width, options.height, window_title(scene)),
      context_(context_options(options)),
      surface_(context_, window_),
      swapchain_(context_, surface_.handle, shared_memory_for(options, context_, window_), window_.refresh_rate()),
      renderer_(context_, swapchain_.format(), context_.depth_format, renderer_options(options)),
      live_(std::move(scene), std::move(content), renderer_),
      screenshot_(context_),
      vsync_(options.vsync),
      panel_visible_(options.panel) {
    if (!options.script.empty()) script_ = read_viewer_script(options.script);
    if (!options.frame_log.empty()) {
        // Into a folder made if missing, as screenshots and saved scenes are.
        const std::filesystem::path log_path(options.frame_log);
        std::error_code made;
        if (log_path.has_parent_path()) std::filesystem::create_directories(log_path.parent_path(), made);
        frame_log_ = std::fopen(options.frame_log.c_str(), "w");
        if (!frame_log_) fail_file(options.frame_log, std::string("cannot write the frame log: ") + std::strerror(errno));
    }
    swapchain_.recreate(window_.framebuffer_size(), vsync_);
    if (options.verbose) print_swapchain();
    overlay_ = std::make_unique<Overlay>(context_, window_.handle(), swapchain_);
    // ImGui 1.86 updates its capture flags once per frame; the panel's rectangle makes a press on the
    // panel the panel's even when it comes before the frame that would have noticed the cursor there.
    window_.set_capture_queries(
        [this](glm::dvec2 cursor) {
            auto over = [&](const glm::vec4& r) {
                return cursor.x >= r.x && cursor.y >= r.y && cursor.x < r.x + r.z && cursor.y < r.y + r.w;
            };
            return panel_visible_ && (over(panel_rect_) || over(timeline_rect_) || overlay_->wants_mouse());
        },
        [this] { return panel_visible_ && overlay_->wants_keys(); });
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = context_.command_pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(context_.device, &alloc, &cb_));
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // the first frame has nothing to wait for
    VK_CHECK(vkCreateFence(context_.device, &fence, nullptr, &frame_done_));
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VK_CHECK(vkCreateSemaphore(context_.device, &semaphore, nullptr, &acquired_));

    VkExtent2D size = window_.framebuffer_size();
    float aspect = size.height > 0 ? float(size.width) / float(size.height) : 1.25f;
    camera_ = resolve_camera(live_.scene().camera, live_.bounds(), aspect);
    const SceneCamera& asked = live_.scene().camera;
    if (!asked.target && !asked.world_distance) open_distance_multiple_ = asked.distance;
    timeline_.set_time(options.start_time);
    timeline_.set_playing(!live_.scene().paused);  // a scene saved while paused opens paused
    if (!live_.scene().camera_path.empty())
        message("the scene's camera_path is for render's frame sequences: the viewer shows its camera, and Ctrl+S keeps the path");
}


Viewer::~Viewer() {
    if (frame_log_) std::fclose(frame_log_);
    vkDeviceWaitIdle(context_.device);
    vkDestroySemaphore(context_.device, acquired_, nullptr);
    vkDestroyFence(context_.device, frame_done_, nullptr);
    vkFreeCommandBuffers(context_.device, context_.command_pool, 1, &cb_);
}


bool Viewer::wants_frame_now() {
    const Clock::time_point now = Clock::now();
    if (window_.activity() != seen_activity_) {  // and for a while after: ImGui's hover and tooltips want frames
        seen_activity_ = window_.activity();
        draw_until_ = std::max(draw_until_, now + kSettle);
    }
    const bool animating = timeline_.playing() && timeline_length(live_.scene(), live_.objects()) > 0.0;
    const bool script_running = script_at_ < script_.size();
    const bool typing = panel_visible_ && overlay_->wants_text();  // a text field's cursor blinks
    return options_.benchmark_frames > 0 || script_running || animating || typing || recreate_ || now < draw_until_;
}

bool Viewer::progress_due() const {  // background work shows its progress bar (and is taken when done)
    return !work_.idle() && Clock::now() - last_drawn_ >= kProgressInterval;
}

void Viewer::message(const std::string& text, bool error) {
    // An error while a script runs (a setting the scene refuses when it is applied, such as the cpu density path
    // for an animated model) ends it with exit code 1, named at the script's last `set` (or the last line begun):
    // the viewer went on with the old setting and the script's screenshots showed that, exit code 0.
    // An error of the action running now (an export that cannot write, an object that is not there) is named at
    // its own line: it was named at the line before, and a missing object's line twice.
    if (error && !script_.empty() && (script_at_ > 0 || script_action_line_ > 0) && !script_failed_) {
        const int line = script_action_line_ > 0 ? script_action_line_
                         : script_set_line_ > 0  ? script_set_line_
                                                 : script_[std::min(script_at_, script_.size()) - 1].line;
        std::fprintf(stderr, "stipple: %s:%d: %s\n", options_.script.c_str(), line, text.c_str());
        std::fflush(stderr);
        script_failed_ = true;
        window_.request_close();
        return;
    }
    // Errors go to stderr too (the panel may be hidden); confirmations to stdout for scripts.
    std::fprintf(error ? stderr : stdout, "stipple: %s\n", text.c_str());
    std::fflush(error ? stderr : stdout);
    messages_.push_back(error ? "error: " + text : text);
    errors_said_ += error;
    draw_until_ = std::max(draw_until_, Clock::now() + kSettle);  // shown in the panel
    while (messages_.size() > 20) messages_.pop_front();
}

void Viewer::save_scene() {
    try {
        const size_t clamped = live_.save(options_.scene_path, camera_, timeline_.time(), timeline_.speed(), !timeline_.playing());
        message("scene saved: " + options_.scene_path);
        if (clamped > 0)
            message(printf_string("%zu object(s) play faster than a scene file's speed allows (%g): saved at %g", clamped,
                                  kMaxAnimationSpeed, kMaxAnimationSpeed), true);
        // render follows a camera_path over every other camera: say where the view just saved goes.
        if (!live_.scene().camera_path.empty())
            message("its camera_path is kept, and render draws the path's frames; the view is saved as its camera, "
                    "which render draws once the path is taken out");
    } catch (const std::exception& e) {  // a failed save is a message: the session goes on
        message(e.what(), true);
    }
}

// Where the panel is drawn into a layer of its own (app/panel_layer.hpp): how often it was drawn.
void Viewer::print_panel_draws(const char* prefix) const {
    if (overlay_->panel_draws() == 0) return;
    std::printf("%s: the panel's layer drawn in %llu of %lld frames (the others laid the layer drawn before "
                "over the frame); windows that change every frame drawn into %llu frames\n",
                prefix, (unsigned long long)overlay_->panel_draws(), frames_drawn_,
                (unsigned long long)overlay_->panel_direct_frames());
}

int Viewer::run() {
    Clock::time_point bench_start;
    while (!window_.should_close()) {
        if (window_.hidden()) {
            if (!paused_) message("window hidden: drawing paused");
            paused_ = true;
            last_frame_.reset();  // the animation clock stands while nothing is shown
            window_.wait_events(0.25);  // nothing to draw: sleep until the window manager shows it again
            continue;
        }
        if (paused_) {
            message("window shown: drawing resumed");
            paused_ = false;
            recreate_ = true;
        }
        if (wants_frame_now()) {
            window_.poll_events();
        } else {
            // Nothing moves and nothing was touched: the frame on screen stays right. Sleep until an event
            // (input, a resize, an expose) or the next look at background work, instead of drawing the same
            // frame again and again on cores that a software GPU and that work share.
            finish_previous_frame();  // its screenshot written, its figures taken
            const bool working = !work_.idle();
            window_.wait_events(working ? std::chrono::duration<double>(kProgressInterval).count() : 0.5);
            // While background work runs, frames come every kProgressInterval to show its progress: they
            // count as frames drawn one after another (reset at each, the figures froze as long as it ran).
            if (!working) idled_ = true;
            if (!wants_frame_now() && !progress_due()) continue;
        }
        if (window_.should_close()) break;
        frame();
        if (options_.benchmark_frames > 0) {
            if (frames_drawn_ == kWarmupFrames) bench_start = Clock::now();
            if (frames_drawn_ == kWarmupFrames + options_.benchmark_frames) break;
        }
    }
    VK_CHECK(vkDeviceWaitIdle(context_.device));
    if (options_.benchmark_frames > 0 && frames_drawn_ >= kWarmupFrames + options_.benchmark_frames) {
        double ms = ms_between(bench_start, Clock::now()) / double(options_.benchmark_frames);
        VkExtent2D e = swapchain_.extent();
        std::printf("benchmark: %lld frames at %ux%u, panel %s, %s: mean %.2f fps (%.2f ms per frame)\n",
                    options_.benchmark_frames, e.width, e.height, panel_visible_ ? "on" : "off",
                    swapchain_.mode_name().c_str(), 1000.0 / ms, ms);
        const FrameStats& st = collected_;
        if (panel_visible_) print_panel_draws("benchmark");
        // Negative where the drawn stipples are not counted (--no-count-drawn): said, not printed as -1.
        const std::string drawn = st.drawn_stipples >= 0 ? std::to_string(st.drawn_stipples) + " drawn (last frame)"
                                                         : "drawn not counted (--no-count-drawn)";
        std::printf("benchmark: %zu objects, %llu polygons, %llu candidate stipples, %s\n", live_.size(),
                    (unsigned long long)st.triangles, (unsigned long long)st.candidate_stipples, drawn.c_str());
        for (const auto& [pass, total] : bench_gpu_ms_)
            std::printf("benchmark: gpu %-12s mean %.3f ms\n", pass.c_str(), total / std::max(bench_samples_, 1));
    }
    if (options_.verbose) print_panel_draws("stipple");
    if (uint32_t n = gpu::validation_messages_in_process()) {  // the probe device's too
        std::fprintf(stderr, "stipple: %u Vulkan validation message(s)\n", n);
        return 2;
    }
    return script_failed_ ? 1 : 0;
}

void Viewer::apply_finished_work() {
    for (FinishedWork& work : work_.take_finished()) {
        try {
            switch (work.kind) {
                case FinishedWork::Kind::Regenerated: {
                    const auto start = Clock::now();
                    if (!live_.apply_stipples(work.object_id, work.params.generation, work.data.stipples, *work.upload))
                        break;  // stale: the panel asks for other parameters now (a newer job makes them, if needed)
                    char text[96];
                    std::snprintf(text, sizeof text, "new stipples: %zu candidates (uploaded in %.0f ms)",
                                  work.data.stipples->size(), ms_between(start, Clock::now()));
                    message(text);
                    break;
                }
                case FinishedWork::Kind::Loaded:
                    if (live_.add_loaded(work.path, std::move(work.data), *work.upload, work.params))
                        message("added " + work.path + " (it moves: drawn on the splat path, which computes its densities on the GPU)");
                    else
                        message("added " + work.path);
                    break;
                case FinishedWork::Kind::Failed: message(work.error, true); break;
            }
        } catch (const Error& e) {
            message(e.what(), true);  // e.g. the device refused the upload: the old stipples stay
        }
    }
}

void Viewer::run_script() {
    while (script_at_ < script_.size()) {
        // A screenshot shows the state at its line: the actions after it wait until it is taken (a `set`
        // right after one changed what it showed, and a second screenshot replaced the first, until
        // 2026-12-04).
        if (screenshot_.pending()) return;
        const ScriptAction& action = script_[script_at_];
        switch (action.kind) {
            case ScriptAction::Kind::Wait:
                if (!script_wait_until_) script_wait_until_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                                                  std::chrono::duration<double>(action.seconds));
                if (Clock::now() < *script_wait_until_) return;
                script_wait_until_.reset();
                break;
            case ScriptAction::Kind::WaitIdle:
                if (!pending_regeneration_.empty() || !work_.idle()) return;
                break;
            case ScriptAction::Kind::Set: {
                if (action.object >= live_.size()) {
                    script_action_line_ = action.line;
                    message("there is no object " + std::to_string(action.object) + " (the scene's objects are 0.." +
                                std::to_string(live_.size() - 1) + ")",
                            true);
                    script_action_line_ = 0;
                    script_failed_ = true;
                    window_.request_close();
                    return;
                }
                const ParamSpec& spec = *find_param(action.key);
                script_set_line_ = action.line;
                script_set_unapplied_ = true;
                spec.set(live_.scene().objects[action.object].params, action.value);
                if (spec.effect == ParamEffect::Regenerate) pending_regeneration_.push_back(action.object);
                message("script: object " + std::to_string(action.object) + " " + action.key + " = " +
                        format_param_value(spec, action.value));
                break;
            }
            case ScriptAction::Kind::Screenshot:
                screenshot_.request(action.path);
                ++script_at_;
                return;  // this frame draws what it shows
            case ScriptAction::Kind::Export:
                script_action_line_ = action.line;
                if (!export_view(action.path, plot::ExportOptions{})) script_failed_ = true;  // exit code 1 at the end
                script_action_line_ = 0;
                break;
            case ScriptAction::Kind::Quit:
                // Not before the next frame has applied the settings: one the scene refuses there (the cpu density
                // path for an animated model) must still end the run with exit code 1 (`set` then `quit` exited 0).
                // At most a couple of seconds (a window that draws no frame, minimised, applies nothing).
                if (script_set_unapplied_) {
                    if (!script_wait_until_) script_wait_until_ = Clock::now() + std::chrono::seconds(2);
                    if (Clock::now() < *script_wait_until_) return;
                }
                script_wait_until_.reset();
                window_.request_close();
                break;
        }
        ++script_at_;
    }
}

void Viewer::handle_input(const Input& input, float aspect) {
    Sphere bounds = live_.bounds();
    if (input.orbit_drag != glm::dvec2(0.0)) orbit(camera_, glm::vec2(input.orbit_drag));
    if (input.pan_drag != glm::dvec2(0.0)) pan(camera_, glm::vec2(input.pan_drag), float(swapchain_.extent().height));
    if (input.scroll != 0.0) zoom(camera_, float(input.scroll), bounds, aspect);
    for (KeyCommand c : input.commands) {
        switch (c) {
            case KeyCommand::OrbitLeft: orbit_degrees(camera_, -kKeyOrbitDegrees, 0.0f); break;
            case KeyCommand::OrbitRight: orbit_degrees(camera_, kKeyOrbitDegrees, 0.0f); break;
            case KeyCommand::OrbitUp: orbit_degrees(camera_, 0.0f, kKeyOrbitDegrees); break;
            case KeyCommand::OrbitDown: orbit_degrees(camera_, 0.0f, -kKeyOrbitDegrees); break;
            case KeyCommand::ZoomIn: zoom(camera_, 1.0f, bounds, aspect); break;
            case KeyCommand::ZoomOut: zoom(camera_, -1.0f, bounds, aspect); break;
            case KeyCommand::FrameAll: frame_all(camera_, bounds, aspect, free_columns()); break;
            case KeyCommand::TogglePanel: panel_visible_ = !panel_visible_; break;
            case KeyCommand::Screenshot: screenshot_.request(); break;
            case KeyCommand::ToggleVsync:
                vsync_ = !vsync_;
                recreate_ = true;
                break;
            case KeyCommand::SaveScene: save_scene(); break;
            case KeyCommand::Quit: window_.request_close(); break;
            case KeyCommand::TogglePlay: timeline_.toggle_play(live_.scene(), live_.objects()); break;
            case KeyCommand::ToggleProjection: camera_.orthographic = !camera_.orthographic; break;  // the target's scale kept
        }
    }
    for (const std::string& path : input.dropped) {
        // Loaded in the background; a bad file costs a message, never the session.
        if (path.find("://") != std::string::npos) {  // a link dragged from a browser, not a file
            message(path + ": not a local file (only model files on this machine can be dropped)", true);
            continue;
        }
        if (is_scene_file(path)) {
            message(path + ": is a scene file: open it with `stipple view " + path + "`", true);
            continue;
        }
        // A model the scene draws already, with the same generation parameters: a copy of it, at once, sharing
        // its mesh, stipples and GPU buffers (each drop loaded the file again and held it all anew).
        const ObjectParams params = live_.params_for_new_object();
        if (const std::optional<size_t> source = live_.copy_source(path, params)) {
            try {
                live_.add_copy(*source, params);
                message("added " + path + " (a copy of object " + std::to_string(*source) + ": its stipples shared)");
            } catch (const Error& e) {
                message(e.what(), true);
            }
            continue;
        }
        work_.load(path, params, live_.planned_beyond_held());
        message("loading " + path);
    }
}

glm::vec2 Viewer::free_columns() const {
    if (!panel_visible_ || !panel_open_) return {0.0f, 1.0f};
    return columns_left_free(panel_rect_, panel_display_);
}

void Viewer::handle_requests(const PanelRequests& r, float aspect) {
    panel_rect_ = r.rect;
    panel_open_ = r.open;
    panel_display_ = r.display;
    if (panel_frames_until_open_view_ > 0 && --panel_frames_until_open_view_ == 0 && r.open)
        frame_at_open(camera_, live_.bounds(), aspect, free_columns(), open_distance_multiple_);
    if (r.screenshot) screenshot_.request();
    if (r.save_scene) save_scene();
    if (r.frame_all) frame_all(camera_, live_.bounds(), aspect, free_columns());
    if (r.toggle_projection) camera_.orthographic = !camera_.orthographic;
    if (r.toggle_vsync) {
        vsync_ = !vsync_;
        recreate_ = true;
    }
    if (r.hide) panel_visible_ = false;
    // Done at the start of the next frame, once the GPU has finished with the objects.
    pending_regeneration_.insert(pending_regeneration_.end(), r.regenerate.begin(), r.regenerate.end());
    if (r.remove) pending_removal_ = r.remove;
    if (r.export_view) pending_export_ = r.export_view;
}

// The view as the window shows it, drawn again offscreen by the export (app::export_frame) at the
// window's size. Called between frames, when no frame is in flight; the window waits meanwhile.
bool Viewer::export_view(const std::string& path, const plot::ExportOptions& options) {
    try {
        const VkExtent2D extent = swapchain_.valid() ? swapchain_.extent() : window_.framebuffer_size();
        if (extent.width == 0 || extent.height == 0) fail_file(path, "the window has no size to export");
        // The export draws the scene again, with a renderer of its own and a list of each object's visible
        // stipples (20 bytes a candidate): checked beside what the device holds, as render checks vector output
        // (a crowd that render refused exported from the viewer, and a smaller GPU would have run out instead).
        uint64_t needed = live_.planned_bytes();
        for (const ObjectData& object : live_.objects()) needed += check_visible_list_fits(context_, object.stipples->size());
        if (const uint64_t free = context_.device_memory_available(); needed > free)
            fail_file(path, "exporting needs about " + mebibytes(needed) + " of GPU memory (the scene drawn again, with a list of "
                            "each object's visible stipples), and the device has " + mebibytes(free) +
                            " free: fewer objects, or lighter ones (a lower D_max), or a screenshot");
        const FrameView view = scene_frame_view(live_.scene(), camera_, live_.bounds(), extent);
        const plot::PlotStats stats = export_frame(context_, live_.scene(), live_.objects(), view, options, path,
                                                         timeline_.time());
        // A CSV holds the dots alone (render says the same).
        const std::string lines = plot::is_csv_path(path)
                                      ? (stats.polylines ? "; its " + std::to_string(stats.polylines) + " polylines are not written to CSV" : "")
                                      : ", " + std::to_string(stats.polylines) + " polylines";
        message("exported: " + path + " (" + plot::format_number(stats.page.width_mm, 0) + "x" +
                plot::format_number(stats.page.height_mm, 0) + " mm page: " + std::to_string(stats.dots) + " dots" + lines + ")");
        return true;
    } catch (const Error& e) {
        message(e.what(), true);
        return false;
    }
}

int run_viewer(Scene scene, SceneContent content, const ViewerOptions& options) {
    Viewer viewer(std::move(scene), std::move(content), options);
    return viewer.run();
}

}  // namespace stipple::app
