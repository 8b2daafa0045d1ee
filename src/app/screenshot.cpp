#include "app/screenshot.hpp"

#include <cstdio>
#include <cstring>
#include <utility>

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "io/png_io.hpp"

namespace stipple::app {

std::filesystem::path next_screenshot_path(const std::filesystem::path& dir, const std::string& extension) {
    for (int i = 1; i < 1000000; ++i) {
        char name[32];
        std::snprintf(name, sizeof(name), "stipple-%04d", i);
        std::filesystem::path path = dir / (name + extension);
        if (!std::filesystem::exists(path)) return path;
    }
    fail_file(dir.string(), "no free screenshot name left");
}

void ScreenshotCapture::record_copy(VkCommandBuffer cb, VkImage image, VkFormat format, VkExtent2D extent) {
    VkDeviceSize size = VkDeviceSize(extent.width) * extent.height * 4;
    if (!readback_ || readback_.size() < size)
        readback_ = gpu::Buffer(context_, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback);
    gpu::image_barrier(cb, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cb, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.handle(), 1, &region);
    gpu::buffer_barrier(cb, readback_.handle(), VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    // Back for the panel, which draws over the same image.
    gpu::image_barrier(cb, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    format_ = format;
    extent_ = extent;
    requested_ = false;
    copied_ = true;
}

std::string ScreenshotCapture::write_pending(const std::filesystem::path& dir) {
    if (!copied_) return "";
    copied_ = false;
    readback_.invalidate();
    Image image;
    image.width = int(extent_.width);
    image.height = int(extent_.height);
    image.channels = 4;
    image.pixels.resize(size_t(extent_.width) * extent_.height * 4);
    std::memcpy(image.pixels.data(), readback_.mapped(), image.pixels.size());
    bool bgra = format_ == VK_FORMAT_B8G8R8A8_UNORM || format_ == VK_FORMAT_B8G8R8A8_SRGB;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        if (bgra) std::swap(image.pixels[i], image.pixels[i + 2]);
        image.pixels[i + 3] = 255;  // a window has no transparency; keep the PNG opaque
    }
    const std::filesystem::path path = exact_.empty() ? next_screenshot_path(dir) : std::exchange(exact_, {});
    write_png(path.string(), image);
    return path.string();
}

}  // namespace stipple::app
