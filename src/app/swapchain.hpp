#pragma once
// The window's swapchain, its image views, a depth image of the same size, and one "rendering done"
// semaphore per image. Recreated whenever the window's size changes or presentation reports it out
// of date; vsync chooses FIFO, otherwise MAILBOX or IMMEDIATE where the surface offers them.
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/resources.hpp"

namespace stipple::gpu {
class Context;
}

namespace stipple::app {

class Swapchain {
public:
    // Chooses the colour format once (the renderer's pipelines are built for it). Throws when the
    // device's queue cannot present to `surface`.
    Swapchain(const gpu::Context& context, VkSurfaceKHR surface);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // (Re)creates for the surface's current size (`window_size` where the surface leaves it to us).
    // The GPU must be idle. Returns false, with no swapchain, when the surface has no area (minimized).
    bool recreate(VkExtent2D window_size, bool vsync);
    bool valid() const { return swapchain_ != VK_NULL_HANDLE; }

    VkSwapchainKHR handle() const { return swapchain_; }
    VkFormat format() const { return format_.format; }
    VkExtent2D extent() const { return extent_; }
    VkPresentModeKHR present_mode() const { return present_mode_; }
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
    // to recreate, every other failure throws.
    VkResult acquire(VkSemaphore signal, uint32_t* image_index);
    VkResult present(VkQueue queue, uint32_t image_index);

private:
    void destroy_views();

    const gpu::Context& context_;
    VkSurfaceKHR surface_;
    VkSurfaceFormatKHR format_{};
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkExtent2D extent_{};
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
};

}  // namespace stipple::app
