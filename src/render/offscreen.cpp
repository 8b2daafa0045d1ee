#include "render/offscreen.hpp"

#include <chrono>
#include <cstring>

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "gpu/vk_check.hpp"

namespace stipple {

Image RenderedFrame::coverage_mask() const {
    Image mask;
    mask.width = color.width;
    mask.height = color.height;
    mask.channels = 1;
    mask.pixels.resize(depth.size());
    for (size_t i = 0; i < depth.size(); ++i) mask.pixels[i] = depth[i] < 1.0f ? 255 : 0;
    return mask;
}

OffscreenTarget::OffscreenTarget(const gpu::Context& context, VkExtent2D extent, bool color_words)
    : context_(context), extent_(extent) {
    if (extent.width == 0 || extent.height == 0 || extent.width > context.properties.limits.maxImageDimension2D ||
        extent.height > context.properties.limits.maxImageDimension2D)
        fail("image size " + std::to_string(extent.width) + "x" + std::to_string(extent.height) +
             " is out of range: 1.." + std::to_string(context.properties.limits.maxImageDimension2D) + " per side");
    // Linear, with its pixels as words for the splat to draw in (no copy back), where the device allows.
    const VkImageUsageFlags usage =
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    color_ = color_words ? gpu::Image::linear_with_words(context, extent, kColorFormat, usage)
                         : gpu::Image(context, extent, kColorFormat, usage, VK_IMAGE_ASPECT_COLOR_BIT);
    depth_ = gpu::Image(context, extent, context.depth_format,
                        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                            VK_IMAGE_USAGE_TRANSFER_DST_BIT, gpu::kDepthStencilAspect);
    VkDeviceSize pixels = VkDeviceSize(extent.width) * extent.height;
    color_readback_ = gpu::Buffer(context, pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback);
    depth_readback_ = gpu::Buffer(context, pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback);
}

RenderTargets OffscreenTarget::targets() const {
    return {color_.handle(), color_.view(), depth_.handle(), depth_.view(), extent_, true, color_.words(), color_.words_serial()};
}

double OffscreenTarget::draw(StippleRenderer& renderer, const FrameView& view) { return draw_queued(renderer, view, 1); }

int OffscreenTarget::default_queued_frames(const gpu::Context& context) {
    return context.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 1 : kQueuedFramesOnGpus;
}

double OffscreenTarget::draw_queued(StippleRenderer& renderer, const FrameView& view, int frames) {
    STIPPLE_CHECK(frames >= 1, "draw_queued needs at least one frame");
    auto start = std::chrono::steady_clock::now();
    FrameView sized = view;
    sized.extent = extent_;
    VkCommandBuffer cb = context_.begin_one_shot();
    for (int i = 0; i < frames; ++i) {
        // Nothing runs before the submission, so preparing (uniforms, CPU densities) over the last
        // frame's data races with nothing. Host-written data is read when the GPU runs, so every queued
        // frame reads what the last preparation wrote: the same, since they all draw `view` (a timing,
        // not an animation). The GPU finishes each frame before the next one's first pass.
        renderer.prepare(sized);
        if (i > 0)
            gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                                VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
        renderer.record(cb, targets());
    }
    context_.submit_and_wait(cb);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    renderer.collect();  // the last frame's GPU times
    return ms / frames;
}

RenderedFrame OffscreenTarget::render(StippleRenderer& renderer, const FrameView& view) {
    FrameView sized = view;
    sized.extent = extent_;
    renderer.prepare(sized);
    VkCommandBuffer cb = context_.begin_one_shot();
    renderer.record(cb, targets());

    gpu::image_barrier(cb, color_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_TRANSFER_READ_BIT);
    gpu::image_barrier(cb, depth_.handle(), gpu::kDepthStencilAspect, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent_.width, extent_.height, 1};
    vkCmdCopyImageToBuffer(cb, color_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, color_readback_.handle(), 1,
                           &region);
    if (const gpu::Buffer* words = renderer.depth_words()) {  // the depth pass ran as compute
        const VkBufferCopy whole{0, 0, depth_readback_.size()};
        vkCmdCopyBuffer(cb, words->handle(), depth_readback_.handle(), 1, &whole);
    } else {
        region.imageSubresource.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
        vkCmdCopyImageToBuffer(cb, depth_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, depth_readback_.handle(), 1,
                               &region);
    }
    gpu::buffer_barrier(cb, color_readback_.handle(), VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    gpu::buffer_barrier(cb, depth_readback_.handle(), VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    context_.submit_and_wait(cb);
    renderer.collect();

    color_readback_.invalidate();
    depth_readback_.invalidate();
    RenderedFrame frame;
    size_t pixels = size_t(extent_.width) * extent_.height;
    frame.color.width = int(extent_.width);
    frame.color.height = int(extent_.height);
    frame.color.channels = 4;
    frame.color.pixels.resize(pixels * 4);
    std::memcpy(frame.color.pixels.data(), color_readback_.mapped(), pixels * 4);
    // The splat leaves 1 - ink coverage in alpha (shaders/splat.comp); a drawing is opaque.
    for (size_t i = 0; i < pixels; ++i) frame.color.pixels[4 * i + 3] = 255;
    frame.depth.resize(pixels);
    const auto* words = static_cast<const uint32_t*>(depth_readback_.mapped());
    for (size_t i = 0; i < pixels; ++i) frame.depth[i] = gpu::depth_to_float(context_.depth_format, words[i]);
    return frame;
}

}  // namespace stipple
