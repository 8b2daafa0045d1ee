#include "app/swapchain.hpp"

#include <algorithm>

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

Swapchain::Swapchain(const gpu::Context& context, VkSurfaceKHR surface) : context_(context), surface_(surface) {
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
}

bool Swapchain::can_disable_vsync() const {
    return std::find(modes_.begin(), modes_.end(), VK_PRESENT_MODE_MAILBOX_KHR) != modes_.end() ||
           std::find(modes_.begin(), modes_.end(), VK_PRESENT_MODE_IMMEDIATE_KHR) != modes_.end();
}

void Swapchain::destroy_views() {
    for (VkImageView v : views_) vkDestroyImageView(context_.device, v, nullptr);
    views_.clear();
    images_.clear();
    depth_.reset();
}

bool Swapchain::recreate(VkExtent2D window_size, bool vsync) {
    // Queried right before creation: the window may be resized at any moment, and the extent must be
    // the one the surface reports now.
    VkSurfaceCapabilitiesKHR caps{};
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physical_device, surface_, &caps));
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == UINT32_MAX) {  // the surface lets the swapchain decide
        extent.width = std::clamp(window_size.width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent.height = std::clamp(window_size.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    destroy_views();
    if (extent.width == 0 || extent.height == 0) {
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
    while (rendering_done_.size() < images_.size()) {
        VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        VkSemaphore s = VK_NULL_HANDLE;
        VK_CHECK(vkCreateSemaphore(context_.device, &semaphore, nullptr, &s));
        rendering_done_.push_back(s);
    }
    depth_ = gpu::Image(context_, extent, context_.depth_format,
                        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, gpu::kDepthStencilAspect);
    return true;
}

VkResult Swapchain::acquire(VkSemaphore signal, uint32_t* image_index) {
    // A bounded wait: a stalled presentation engine skips a frame instead of hanging the viewer.
    VkResult result = vkAcquireNextImageKHR(context_.device, swapchain_, 1'000'000'000ull, signal, VK_NULL_HANDLE,
                                            image_index);
    if (result == VK_SUCCESS || result == VK_SUBOPTIMAL_KHR || result == VK_ERROR_OUT_OF_DATE_KHR ||
        result == VK_TIMEOUT || result == VK_NOT_READY)
        return result;
    VK_CHECK(result);
    return result;
}

VkResult Swapchain::present(VkQueue queue, uint32_t image_index) {
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
