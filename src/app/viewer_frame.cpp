// One frame of the viewer: the previous frame's figures collected, the frame's work (background results,
// the script, input, the panel and the timeline), the swapchain image recorded, submitted and presented.
#include <algorithm>

#include "app/viewer_session.hpp"
#include "core/error.hpp"
#include "gpu/vk_check.hpp"

namespace stipple::app {

void Viewer::finish_previous_frame() {
    if (!submitted_) return;
    context_.wait_for_fence(frame_done_);
    submitted_ = false;
    renderer_.collect();
    collected_ = renderer_.stats();  // until the next frame's prepare() starts its own
    const FrameStats& latest = collected_;
    if (figures_.stats.gpu_ms.empty()) figures_.stats = latest;  // the first frame's, until the first average
    for (const auto& pass : latest.gpu_ms) {  // a pair, not a structured binding: clang 15 cannot capture one
        auto sum = std::find_if(gpu_ms_sums_.begin(), gpu_ms_sums_.end(),
                                [&](const auto& p) { return p.first == pass.first; });
        if (sum == gpu_ms_sums_.end()) gpu_ms_sums_.push_back(pass);
        else sum->second += pass.second;
    }
    ++gpu_ms_frames_;
    if (options_.benchmark_frames > 0 && frames_drawn_ > kWarmupFrames) {
        for (const auto& [pass, ms] : latest.gpu_ms) bench_gpu_ms_[pass] += ms;
        ++bench_samples_;
    }
    try {
        std::string path = screenshot_.write_pending(options_.screenshot_dir);
        if (!path.empty()) message("screenshot: " + path);
    } catch (const Error& e) {
        message(e.what(), true);
        if (!options_.script.empty()) script_failed_ = true;  // a script's screenshot not written: exit code 1
    }
}

bool Viewer::ensure_swapchain() {
    VkExtent2D size = window_.framebuffer_size();
    VkExtent2D have = swapchain_.made_for();
    const bool unchanged = !recreate_ && size.width == have.width && size.height == have.height;
    if (unchanged && swapchain_.valid()) return true;
    if (unchanged && swapchain_.too_large()) {
        window_.wait_events(0.1);  // nothing can be drawn at this size: wait for a resize without spinning
        return false;
    }
    VK_CHECK(vkDeviceWaitIdle(context_.device));
    recreate_ = false;
    bool ok = swapchain_.recreate(size, vsync_);
    if (!ok && swapchain_.too_large())
        message("the window (" + std::to_string(size.width) + "x" + std::to_string(size.height) +
                ") is larger than the device can draw: drawing paused until it is smaller");
    overlay_->rebuild(swapchain_);
    if (ok && options_.verbose) print_swapchain();
    return ok;
}

void Viewer::print_swapchain() const {
    std::printf("stipple: swapchain %ux%u, %u images, %s\n", swapchain_.extent().width, swapchain_.extent().height,
                swapchain_.image_count(), swapchain_.mode_name().c_str());
    std::fflush(stdout);
}

void Viewer::frame() {
    finish_previous_frame();
    Clock::time_point start = Clock::now();
    last_drawn_ = start;
    if (idled_) {  // the panel's fps counts frames drawn one after another, not the idle time between
        idled_ = false;
        fps_frames_ = 0;
        fps_start_ = start;
        cpu_ms_sum_ = 0.0;
    }
    VkExtent2D size = swapchain_.valid() ? swapchain_.extent() : window_.framebuffer_size();
    float aspect = size.height > 0 ? float(size.width) / float(size.height) : 1.0f;

    // New stipples are made in the background; the old ones are drawn until they are ready.
    for (size_t object : pending_regeneration_)
        if (object < live_.size() && live_.generation_changed(object))
            work_.regenerate(live_.id(object), live_.model(object), live_.scene().objects[object].params);
    pending_regeneration_.clear();
    apply_finished_work();
    run_script();
    if (pending_export_) {
        try {
            export_view(next_screenshot_path(options_.screenshot_dir, pending_export_->extension).string(),
                        pending_export_->options);
        } catch (const Error& e) {
            message(e.what(), true);  // no free name left
        }
        pending_export_.reset();
    }
    if (pending_removal_) live_.remove(*pending_removal_);
    pending_removal_.reset();
    handle_input(window_.take_input(), aspect);
    // The clock moves with real time, whatever the frame rate.
    const Clock::time_point now = Clock::now();
    if (last_frame_) timeline_.advance(std::chrono::duration<double>(now - *last_frame_).count(), live_.scene(), live_.objects());
    last_frame_ = now;
    if (window_.should_close() || !ensure_swapchain()) return;

    uint32_t image = 0;
    VkResult acquired = swapchain_.acquire(acquired_, &image);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        recreate_ = true;
        return;
    }
    if (acquired == VK_TIMEOUT || acquired == VK_NOT_READY) return;
    if (acquired == VK_SUBOPTIMAL_KHR) recreate_ = true;  // the image is ours and signalled: draw it, then recreate

    if (!panel_visible_) {
        overlay_->skip_frame();
        panel_frames_until_open_view_ = 0;  // hidden from the start: the scene's view stands
    } else {
        overlay_->new_frame();
        figures_.device = context_.device_name;
        figures_.extent = swapchain_.extent();
        present_mode_ = swapchain_.mode_name();
        figures_.present_mode = present_mode_.c_str();
        figures_.vsync = vsync_;
        figures_.orthographic = camera_.orthographic;
        figures_.can_disable_vsync = swapchain_.can_disable_vsync();
        figures_.max_point_size = context_.features.max_point_size;
        figures_.scene_path = options_.scene_path;
        figures_.screenshot_dir = options_.screenshot_dir;
        figures_.messages.assign(messages_.begin(), messages_.end());
        figures_.errors_said = errors_said_;
        const auto status = work_.status();
        figures_.work_label = status ? status->label : "";
        figures_.work_fraction = status ? status->fraction : 0.0;
        figures_.work_queued = status ? status->queued : 0;
        handle_requests(draw_panel(live_.scene(), live_.names(), figures_, export_state_), aspect);
        timeline_rect_ = timeline_.draw(live_.scene(), live_.objects(), live_.names(),
                                        glm::vec2(float(figures_.extent.width), float(figures_.extent.height)));
    }
    record(image);

    VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    VkSemaphore done = swapchain_.rendering_done(image);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &acquired_;
    submit.pWaitDstStageMask = &wait_stage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cb_;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &done;
    VK_CHECK(vkResetFences(context_.device, 1, &frame_done_));
    VK_CHECK(vkQueueSubmit(context_.queue, 1, &submit, frame_done_));
    submitted_ = true;
    cpu_ms_sum_ += ms_between(start, Clock::now());

    VkResult presented = swapchain_.present(context_.queue, image, panel_visible_ ? overlay_->panel_pixels() : PixelsOver{});
    // The second column says whether background work (new stipples, a model) was under way, so that a
    // test can see frames keep coming while it runs, whatever the machine's load.
    if (frame_log_) {  // flushed: a test (or tail -f) reads it while the viewer runs
        std::fprintf(frame_log_, "%.3f %d\n", ms_between(started_, Clock::now()), work_.idle() ? 0 : 1);
        std::fflush(frame_log_);
    }
    if (presented != VK_SUCCESS) recreate_ = true;  // out of date or suboptimal: a new swapchain next frame
    ++frames_drawn_;
    ++fps_frames_;
    double elapsed = ms_between(fps_start_, Clock::now());
    if (elapsed >= 500.0) {
        figures_.fps = 1000.0 * fps_frames_ / elapsed;
        figures_.cpu_frame_ms = cpu_ms_sum_ / fps_frames_;
        if (gpu_ms_frames_ > 0) {  // the counts of the last frame collected, the times averaged
            figures_.stats = collected_;
            figures_.stats.gpu_ms = gpu_ms_sums_;
            for (auto& [pass, ms] : figures_.stats.gpu_ms) ms /= gpu_ms_frames_;
        }
        gpu_ms_sums_.clear();
        gpu_ms_frames_ = 0;
        cpu_ms_sum_ = 0.0;
        fps_frames_ = 0;
        fps_start_ = Clock::now();
    }
}

void Viewer::record(uint32_t image) {
    for (const std::string& refused : live_.sync(timeline_.time())) message(refused, true);
    script_set_unapplied_ = false;
    FrameView view = scene_frame_view(live_.scene(), camera_, live_.bounds(), swapchain_.extent());
    renderer_.prepare(view);

    VK_CHECK(vkResetCommandBuffer(cb_, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cb_, &begin));
    RenderTargets targets{swapchain_.image(image),  swapchain_.view(image),   swapchain_.depth().handle(),
                          swapchain_.depth().view(), swapchain_.extent(), swapchain_.writable(),
                          swapchain_.words(image),   swapchain_.words_serial(image)};
    renderer_.record(cb_, targets);
    if (screenshot_.requested()) {
        if (swapchain_.copyable())
            screenshot_.record_copy(cb_, swapchain_.image(image), swapchain_.format(), swapchain_.extent());
        else {
            screenshot_.cancel();
            message("screenshots are not possible: this window's images cannot be copied", true);
        }
    }
    if (panel_visible_) {
        overlay_->record(cb_, image);  // its render pass ends in the swapchain's present_layout()
        renderer_.mark_pass(cb_, "panel");
    } else {
        gpu::image_barrier(cb_, swapchain_.image(image), VK_IMAGE_ASPECT_COLOR_BIT,
                           VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, swapchain_.present_layout(),
                           VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
    }
    if (swapchain_.host_reads())  // presenting copies the pixels on the host
        gpu::memory_barrier(cb_, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    VK_CHECK(vkEndCommandBuffer(cb_));
}

}  // namespace stipple::app
