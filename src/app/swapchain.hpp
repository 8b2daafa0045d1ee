#pragma once
// The window's swapchain, its image views, a depth image of the same size, and one "rendering done"
// semaphore per image. Recreated whenever the window's size changes or presentation reports it out
// of date; vsync chooses FIFO, otherwise MAILBOX or IMMEDIATE where the surface offers them.
//
// Or, given X11 shared memory (x11_shared_memory.hpp), the same interface over images of our own:
// linear and host-visible, the splat drawing in their pixels (unless their rows are padded), each frame handed to the X server from
// them. Acquiring signals the semaphore with an empty submission; presenting waits for the frame,
// copies it into a shared segment and asks the server to show it; vsync holds presents to the
// monitor's refresh interval.
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "app/pixel_over.hpp"

#include "app/x11_shared_memory.hpp"
#include "gpu/resources.hpp"

namespace stipple::gpu {
class Context;
}

namespace stipple::app {

class Swapchain {
public:
    // Chooses the colour format once (the renderer's pipelines are built for it). Throws when the
    // device's queue cannot present to `surface`.
    // With `shared_memory`, frames go through it (refresh_hz: what vsync holds them to) and no
    // VkSwapchainKHR is made.
    Swapchain(const gpu::Context& context, VkSurfaceKHR surface, std::unique_ptr<X11SharedMemory> shared_memory = nullptr,
              double refresh_hz = 60.0);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // (Re)creates for the surface's current size (`window_size` where the surface leaves it to us).
    // The GPU must be idle. Returns false, with no swapchain, when the surface has no area (minimized).
    bool recreate(VkExtent2D window_size, bool vsync);
    bool valid() const { return swapchain_ != VK_NULL_HANDLE || !shared_images_.empty(); }

    VkFormat format() const { return format_.format; }
    VkExtent2D extent() const { return extent_; }
    // The window size the frames were last made for (the extent may be smaller: the device's limit).
    VkExtent2D made_for() const { return made_for_; }
    // Whether the last recreate made nothing because the surface's fixed size exceeds the device's limits.
    bool too_large() const { return too_large_; }
    // "fifo (vsync)", "mailbox", "immediate"; "X11 shared memory" with ", vsync" where it paces frames.
    std::string mode_name() const;
    // The layout the frame's last pass leaves the image in for presentation (PRESENT_SRC_KHR, or
    // GENERAL where the host reads it), and whether the host reads it (a HOST_READ barrier then).
    VkImageLayout present_layout() const;
    bool host_reads() const { return shared_memory_ != nullptr; }
    // The image's pixels as words for the splat (RenderTargets::color_words), or null.
    VkBuffer words(uint32_t i) const { return shared_images_.empty() ? VK_NULL_HANDLE : shared_images_.at(i).words(); }
    uint64_t words_serial(uint32_t i) const { return shared_images_.empty() ? 0 : shared_images_.at(i).words_serial(); }
    uint32_t image_count() const { return uint32_t(images_.size()); }
    uint32_t min_image_count() const { return min_image_count_; }
    VkImage image(uint32_t i) const { return images_.at(i); }
    VkImageView view(uint32_t i) const { return views_.at(i); }
    const gpu::Image& depth() const { return depth_; }
    VkSemaphore rendering_done(uint32_t i) const { return rendering_done_.at(i); }
    // Swapchain images can be copied from (screenshots of the current frame).
    bool copyable() const { return copyable_; }
    bool writable() const { return writable_; }  // images can also be copied into
    // Whether vsync off can mean anything here (MAILBOX or IMMEDIATE exists).
    bool can_disable_vsync() const;

    // Acquire and present; VK_ERROR_OUT_OF_DATE_KHR and VK_SUBOPTIMAL_KHR are returned for the caller
    // to recreate, every other failure throws. `over`: pixels laid over the frame as the host copies it
    // to the window (the panel's layer; only where host_reads()).
    VkResult acquire(VkSemaphore signal, uint32_t* image_index);
    VkResult present(VkQueue queue, uint32_t image_index, const PixelsOver& over = {});

private:
    void destroy_views();
    bool recreate_shared(VkExtent2D extent);
    void add_semaphores_and_depth(VkExtent2D extent);  // after the images: one semaphore each (kept), a new depth image
    VkResult present_shared(VkQueue queue, uint32_t image_index, const PixelsOver& over);

    const gpu::Context& context_;
    VkSurfaceKHR surface_;
    VkSurfaceFormatKHR format_{};
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkExtent2D extent_{};
    VkExtent2D made_for_{};
    bool too_large_ = false;
    VkPresentModeKHR present_mode_ = VK_PRESENT_MODE_FIFO_KHR;
    uint32_t min_image_count_ = 2;
    bool copyable_ = false;
    bool writable_ = false;
    std::vector<VkPresentModeKHR> modes_;
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    // Kept across recreation and only grown: a semaphore a presentation may still wait on is never destroyed early.
    std::vector<VkSemaphore> rendering_done_;
    gpu::Image depth_;

    std::unique_ptr<X11SharedMemory> shared_memory_;
    std::vector<gpu::Image> shared_images_;
    uint32_t next_shared_ = 0;
    VkFence shared_shown_ = VK_NULL_HANDLE;  // the frame to show is finished
    bool vsync_ = true;
    std::chrono::steady_clock::duration refresh_interval_{};
    std::chrono::steady_clock::time_point last_shown_{};
};

}  // namespace stipple::app
