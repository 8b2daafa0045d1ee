#include "app/swapchain.hpp"

#include <algorithm>
#include <thread>

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "gpu/vk_check.hpp"
#include "render/offscreen.hpp"

namespace stipple::app {

namespace {

// UNORM, not sRGB: the renderer's colours and blending are then the same as in offscreen PNGs.
VkSurfaceFormatKHR choose_format(const std::vector<VkSurfaceFormatKHR>& formats) {
    for (VkFormat want : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
        for (const VkSurfaceFormatKHR& f : formats)
            if (f.format == want && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    return formats.front();
}

}  // namespace

Swapchain::Swapchain(const gpu::Context& context, VkSurfaceKHR surface, std::unique_ptr<X11SharedMemory> shared_memory,
                     double refresh_hz)
    : context_(context), surface_(surface), shared_memory_(std::move(shared_memory)) {
    if (shared_memory_) {
        // The X server's pixels: 32-bit words, blue in the low byte (X11SharedMemory::open checked).
        format_ = {VK_FORMAT_B8G8R8A8_UNORM, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR};
        refresh_interval_ = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(1.0 / std::clamp(refresh_hz, 1.0, 1000.0)));
        VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(context.device, &fence, nullptr, &shared_shown_));
        return;
    }
    VkBool32 supported = VK_FALSE;
    VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(context.physical_device, context.queue_family, surface, &supported));
    if (!supported) fail("device '" + context.device_name + "' cannot present to this window");
    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(context.physical_device, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(context.physical_device, surface, &count, formats.data()));
    if (formats.empty()) fail("the window's surface offers no colour format");
    format_ = choose_format(formats);
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(context.physical_device, surface, &count, nullptr));
    modes_.resize(count);
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(context.physical_device, surface, &count, modes_.data()));
}

Swapchain::~Swapchain() {
    vkDeviceWaitIdle(context_.device);
    destroy_views();
    if (swapchain_) vkDestroySwapchainKHR(context_.device, swapchain_, nullptr);
    for (VkSemaphore s : rendering_done_) vkDestroySemaphore(context_.device, s, nullptr);
    if (shared_shown_) vkDestroyFence(context_.device, shared_shown_, nullptr);
}

std::string Swapchain::mode_name() const {
    if (shared_memory_) return vsync_ ? "X11 shared memory, vsync" : "X11 shared memory";
    switch (present_mode_) {
        case VK_PRESENT_MODE_FIFO_KHR: return "fifo (vsync)";
        case VK_PRESENT_MODE_MAILBOX_KHR: return "mailbox";
        case VK_PRESENT_MODE_IMMEDIATE_KHR: return "immediate";
        case VK_PRESENT_MODE_FIFO_RELAXED_KHR: return "fifo relaxed";
        default: return "other";
    }
}

VkImageLayout Swapchain::present_layout() const {
    return shared_memory_ ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
}

bool Swapchain::can_disable_vsync() const {
    if (shared_memory_) return true;
    return std::find(modes_.begin(), modes_.end(), VK_PRESENT_MODE_MAILBOX_KHR) != modes_.end() ||
           std::find(modes_.begin(), modes_.end(), VK_PRESENT_MODE_IMMEDIATE_KHR) != modes_.end();
}

void Swapchain::destroy_views() {
    if (shared_images_.empty())
        for (VkImageView v : views_) vkDestroyImageView(context_.device, v, nullptr);
    views_.clear();
    images_.clear();
    shared_images_.clear();  // with their views
    depth_.reset();
}

namespace {

// The largest frame the device can draw: a window dragged larger (17000 px wide) made images, a
// framebuffer and a viewport beyond its limits (validation errors on every frame). The frame is then
// clamped, and the window's edge beyond it stays unpainted.
VkExtent2D clamp_to_device(const gpu::Context& context, VkExtent2D extent) {
    const VkPhysicalDeviceLimits& limits = context.properties.limits;
    const uint32_t width = std::min({limits.maxImageDimension2D, limits.maxFramebufferWidth, limits.maxViewportDimensions[0]});
    const uint32_t height = std::min({limits.maxImageDimension2D, limits.maxFramebufferHeight, limits.maxViewportDimensions[1]});
    return {std::min(extent.width, width), std::min(extent.height, height)};
}

}  // namespace

bool Swapchain::recreate(VkExtent2D window_size, bool vsync) {
    vsync_ = vsync;
    made_for_ = window_size;
    if (shared_memory_) return recreate_shared(window_size);
    // Queried right before creation: the window may be resized at any moment, and the extent must be
    // the one the surface reports now.
    VkSurfaceCapabilitiesKHR caps{};
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physical_device, surface_, &caps));
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == UINT32_MAX) extent = window_size;  // the surface lets the swapchain decide
    const VkExtent2D drawable = clamp_to_device(context_, extent);
    extent.width = std::clamp(drawable.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height = std::clamp(drawable.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    // A surface that fixes the extent (X11: the window's size) beyond what the device can draw: no frames
    // until the window is smaller.
    too_large_ = extent.width > drawable.width || extent.height > drawable.height;
    destroy_views();
    if (extent.width == 0 || extent.height == 0 || too_large_) {
        if (swapchain_) vkDestroySwapchainKHR(context_.device, swapchain_, nullptr);
        swapchain_ = VK_NULL_HANDLE;
        extent_ = {};
        return false;
    }

    present_mode_ = VK_PRESENT_MODE_FIFO_KHR;  // always available, and what vsync means
    if (!vsync)
        for (VkPresentModeKHR want : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
            if (std::find(modes_.begin(), modes_.end(), want) != modes_.end()) {
                present_mode_ = want;
                break;
            }
    min_image_count_ = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) min_image_count_ = std::min(min_image_count_, caps.maxImageCount);
    copyable_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
    // Copies both ways also let the compute splat draw into the window's images (see RenderTargets).
    writable_ = copyable_ && (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT) != 0;

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface_;
    info.minImageCount = min_image_count_;
    info.imageFormat = format_.format;
    info.imageColorSpace = format_.colorSpace;
    info.imageExtent = extent;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                      (copyable_ ? VkImageUsageFlags(VK_IMAGE_USAGE_TRANSFER_SRC_BIT) : 0u) |
                      (writable_ ? VkImageUsageFlags(VK_IMAGE_USAGE_TRANSFER_DST_BIT) : 0u);
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR))
        for (uint32_t bit = 1; bit <= VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR; bit <<= 1)
            if (caps.supportedCompositeAlpha & bit) {
                info.compositeAlpha = VkCompositeAlphaFlagBitsKHR(bit);
                break;
            }
    info.presentMode = present_mode_;
    info.clipped = VK_TRUE;
    info.oldSwapchain = swapchain_;
    VkSwapchainKHR created = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSwapchainKHR(context_.device, &info, nullptr, &created));
    if (swapchain_) vkDestroySwapchainKHR(context_.device, swapchain_, nullptr);
    swapchain_ = created;
    extent_ = extent;

    uint32_t count = 0;
    VK_CHECK(vkGetSwapchainImagesKHR(context_.device, swapchain_, &count, nullptr));
    images_.resize(count);
    VK_CHECK(vkGetSwapchainImagesKHR(context_.device, swapchain_, &count, images_.data()));
    for (VkImage image : images_) {
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format_.format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView handle = VK_NULL_HANDLE;
        VK_CHECK(vkCreateImageView(context_.device, &view, nullptr, &handle));
        views_.push_back(handle);
    }
    add_semaphores_and_depth(extent);
    return true;
}

void Swapchain::add_semaphores_and_depth(VkExtent2D extent) {
    while (rendering_done_.size() < images_.size()) {
        VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        VkSemaphore s = VK_NULL_HANDLE;
        VK_CHECK(vkCreateSemaphore(context_.device, &semaphore, nullptr, &s));
        rendering_done_.push_back(s);
    }
    depth_ = gpu::Image(context_, extent, context_.depth_format,
                        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                            VK_IMAGE_USAGE_TRANSFER_DST_BIT, gpu::kDepthStencilAspect);
}

bool Swapchain::recreate_shared(VkExtent2D window_size) {
    destroy_views();
    extent_ = {};
    too_large_ = false;  // the frame is clamped, the window's edge beyond it left unpainted
    const VkExtent2D extent = clamp_to_device(context_, window_size);
    if (extent.width == 0 || extent.height == 0) return false;
    // Two images: one the X server may still be copying from while the next is drawn.
    constexpr uint32_t kImages = 2;
    const VkImageUsageFlags usage =
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    for (uint32_t i = 0; i < kImages; ++i) {
        gpu::Image image = gpu::Image::linear_with_words(context_, extent, format_.format, usage, true);
        if (!image.mapped())
            fail("cannot show frames through X11 shared memory: the device has no host-visible linear " +
                 std::string("colour image of ") + std::to_string(extent.width) + "x" + std::to_string(extent.height) +
                 " (use --present swapchain)");
        images_.push_back(image.handle());
        views_.push_back(image.view());
        shared_images_.push_back(std::move(image));
    }
    shared_memory_->resize(extent, kImages);
    min_image_count_ = kImages;
    copyable_ = writable_ = true;
    extent_ = extent;
    next_shared_ = 0;
    add_semaphores_and_depth(extent);
    return true;
}

VkResult Swapchain::present_shared(VkQueue queue, uint32_t image_index, const PixelsOver& over) {
    // The frame finished (its semaphore waited on by an empty submission that signals a fence), then
    // copied to the X server. The caller waits for its frame before the next anyway (one in flight).
    VkSemaphore wait = rendering_done_.at(image_index);
    const VkPipelineStageFlags stage = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &wait;
    submit.pWaitDstStageMask = &stage;
    VK_CHECK(vkResetFences(context_.device, 1, &shared_shown_));
    VK_CHECK(vkQueueSubmit(queue, 1, &submit, shared_shown_));
    context_.wait_for_fence(shared_shown_);
    if (vsync_) {  // no faster than the monitor: what FIFO means to a swapchain
        const auto due = last_shown_ + refresh_interval_;
        if (std::chrono::steady_clock::now() < due) std::this_thread::sleep_until(due);
    }
    last_shown_ = std::chrono::steady_clock::now();
    const gpu::Image& image = shared_images_.at(image_index);
    shared_memory_->show(image_index, image.mapped(), size_t(image.row_pitch()), over);
    return VK_SUCCESS;
}

VkResult Swapchain::acquire(VkSemaphore signal, uint32_t* image_index) {
    if (shared_memory_) {
        // Our own images: the next one, free since its frame was shown; the semaphore the frame's
        // submission waits on signalled at once.
        *image_index = next_shared_;
        next_shared_ = (next_shared_ + 1) % uint32_t(shared_images_.size());
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.signalSemaphoreCount = 1;
        submit.pSignalSemaphores = &signal;
        VK_CHECK(vkQueueSubmit(context_.queue, 1, &submit, VK_NULL_HANDLE));
        return VK_SUCCESS;
    }
    // A bounded wait: a stalled presentation engine skips a frame instead of hanging the viewer.
    VkResult result = vkAcquireNextImageKHR(context_.device, swapchain_, 1'000'000'000ull, signal, VK_NULL_HANDLE,
                                            image_index);
    if (result == VK_SUCCESS || result == VK_SUBOPTIMAL_KHR || result == VK_ERROR_OUT_OF_DATE_KHR ||
        result == VK_TIMEOUT || result == VK_NOT_READY)
        return result;
    VK_CHECK(result);
    return result;
}

VkResult Swapchain::present(VkQueue queue, uint32_t image_index, const PixelsOver& over) {
    if (shared_memory_) return present_shared(queue, image_index, over);
    VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    info.waitSemaphoreCount = 1;
    VkSemaphore wait = rendering_done_.at(image_index);
    info.pWaitSemaphores = &wait;
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_;
    info.pImageIndices = &image_index;
    VkResult result = vkQueuePresentKHR(queue, &info);
    if (result == VK_SUCCESS || result == VK_SUBOPTIMAL_KHR || result == VK_ERROR_OUT_OF_DATE_KHR) return result;
    VK_CHECK(result);
    return result;
}

}  // namespace stipple::app
