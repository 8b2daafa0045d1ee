#include "app/panel_layer.hpp"

#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "app/swapchain.hpp"
#include "gpu/context.hpp"
#include "gpu/vk_check.hpp"

namespace stipple::app {

namespace {

template <typename T>
void append(std::vector<std::byte>& out, const T* data, size_t count) {
    const auto* bytes = reinterpret_cast<const std::byte*>(data);
    out.insert(out.end(), bytes, bytes + sizeof(T) * count);
}

}  // namespace

VkRenderPass create_panel_pass(VkDevice device, VkFormat format, PanelTarget target, VkImageLayout final_layout) {
    VkAttachmentDescription color{};
    color.format = format;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    // Into the frame: the stipple drawing is already there. Into the layer: nothing under the panel.
    color.loadOp = target == PanelTarget::Frame ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout =
        target == PanelTarget::Frame ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
    color.finalLayout = final_layout;  // presented, read by the host (Swapchain::present_layout), or composed
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    // The stipple pass (or a screenshot copy) wrote the image before; the panel blends over it. The same
    // dependency for the layer: render passes are compatible only if they depend alike.
    VkSubpassDependency before{};
    before.srcSubpass = VK_SUBPASS_EXTERNAL;
    before.dstSubpass = 0;
    before.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    before.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT;
    before.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    before.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 1;
    info.pAttachments = &color;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 1;
    info.pDependencies = &before;
    VkRenderPass pass = VK_NULL_HANDLE;
    VK_CHECK(vkCreateRenderPass(device, &info, nullptr, &pass));
    return pass;
}

VkFramebuffer create_panel_framebuffer(VkDevice device, VkRenderPass pass, VkImageView view, VkExtent2D extent) {
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = pass;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFramebuffer(device, &info, nullptr, &framebuffer));
    return framebuffer;
}

PanelLayer::PanelLayer(const gpu::Context& context, VkFormat format) : context_(context), format_(format) {
    pass_ = create_panel_pass(context.device, format, PanelTarget::Layer, VK_IMAGE_LAYOUT_GENERAL);
}

PanelLayer::~PanelLayer() {
    release_images();
    vkDestroyRenderPass(context_.device, pass_, nullptr);
}

void PanelLayer::release_images() {
    if (framebuffer_) vkDestroyFramebuffer(context_.device, framebuffer_, nullptr);
    framebuffer_ = VK_NULL_HANDLE;
    layer_.reset();
    held_.clear();
    extent_ = {};
}

void PanelLayer::rebuild(const Swapchain& swapchain) {
    release_images();
    if (!swapchain.valid() || !swapchain.host_reads() || swapchain.format() != format_) return;
    const VkExtent2D extent = swapchain.extent();
    layer_ = gpu::Image::linear_with_words(context_, extent, format_, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, true);
    if (!layer_.mapped()) return;  // no host-visible linear image: the panel is drawn into each frame
    framebuffer_ = create_panel_framebuffer(context_.device, pass_, layer_.view(), extent);
    extent_ = extent;
}

PixelsOver PanelLayer::pixels() const {
    if (!active()) return {};
    return {layer_.mapped(), size_t(layer_.row_pitch()), box_[0], box_[1], box_[2], box_[3]};
}

namespace {

// Everything ImGui_ImplVulkan_RenderDrawData draws from a window's list: its vertices, indices, and each
// command's clip rectangle, texture and ranges; and the box its commands may touch: their vertices' box
// within their clip rectangles (the main viewport's clip rectangle is the whole window).
void describe(const ImDrawList& list, std::vector<std::byte>& bytes, float box[4]) {
    bytes.clear();
    append(bytes, list.VtxBuffer.Data, size_t(list.VtxBuffer.Size));
    append(bytes, list.IdxBuffer.Data, size_t(list.IdxBuffer.Size));
    box[0] = box[1] = 1e30f;
    box[2] = box[3] = -1e30f;
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
        append(bytes, &cmd.ClipRect, 1);
        append(bytes, &cmd.TextureId, 1);
        append(bytes, &cmd.VtxOffset, 1);
        append(bytes, &cmd.IdxOffset, 1);
        append(bytes, &cmd.ElemCount, 1);
        append(bytes, &cmd.UserCallback, 1);
        float drawn[4] = {1e30f, 1e30f, -1e30f, -1e30f};
        for (uint32_t e = 0; e < cmd.ElemCount && cmd.IdxOffset + e < uint32_t(list.IdxBuffer.Size); ++e) {
            const uint32_t v = cmd.VtxOffset + list.IdxBuffer[int(cmd.IdxOffset + e)];
            if (v >= uint32_t(list.VtxBuffer.Size)) continue;
            const ImVec2 p = list.VtxBuffer[int(v)].pos;
            drawn[0] = std::min(drawn[0], p.x);
            drawn[1] = std::min(drawn[1], p.y);
            drawn[2] = std::max(drawn[2], p.x);
            drawn[3] = std::max(drawn[3], p.y);
        }
        box[0] = std::min(box[0], std::max(drawn[0], cmd.ClipRect.x));
        box[1] = std::min(box[1], std::max(drawn[1], cmd.ClipRect.y));
        box[2] = std::max(box[2], std::min(drawn[2], cmd.ClipRect.z));
        box[3] = std::max(box[3], std::min(drawn[3], cmd.ClipRect.w));
    }
}

ImDrawData subset(const ImDrawData& all, std::vector<ImDrawList*>& lists) {
    ImDrawData part = all;  // the placement: position, size, scale
    part.CmdLists = lists.data();
    part.CmdListsCount = int(lists.size());
    part.TotalVtxCount = part.TotalIdxCount = 0;
    for (const ImDrawList* list : lists) {
        part.TotalVtxCount += list->VtxBuffer.Size;
        part.TotalIdxCount += list->IdxBuffer.Size;
    }
    return part;
}

}  // namespace

PanelPlan PanelLayer::plan(const ImDrawData& data) {
    std::vector<Window> now(size_t(std::max(data.CmdListsCount, 0)));
    for (size_t i = 0; i < now.size(); ++i) {
        Window& window = now[i];
        window.list = data.CmdLists[i];
        describe(*window.list, window.bytes, window.box);
        const auto before = std::find_if(seen_.begin(), seen_.end(), [&](const Window& w) { return w.list == window.list; });
        const bool changed = before == seen_.end() || before->bytes != window.bytes;
        window.changed_frames = changed ? (before == seen_.end() ? 1 : before->changed_frames + 1) : 0;
    }
    const std::vector<bool> direct = windows_drawn_into_frame(std::vector<PanelWindow>(now.begin(), now.end()));
    layer_lists_.clear();
    direct_lists_.clear();
    std::vector<std::byte> held;
    const float placement[6] = {data.DisplayPos.x,  data.DisplayPos.y,        data.DisplaySize.x,
                                data.DisplaySize.y, data.FramebufferScale.x, data.FramebufferScale.y};
    append(held, placement, 6);
    float box[4] = {1e30f, 1e30f, -1e30f, -1e30f};
    for (size_t i = 0; i < now.size(); ++i) {
        if (direct[i]) {
            direct_lists_.push_back(data.CmdLists[i]);
            continue;
        }
        layer_lists_.push_back(data.CmdLists[i]);
        append(held, &now[i].list, 1);
        append(held, now[i].bytes.data(), now[i].bytes.size());
        box[0] = std::min(box[0], now[i].box[0]);
        box[1] = std::min(box[1], now[i].box[1]);
        box[2] = std::max(box[2], now[i].box[2]);
        box[3] = std::max(box[3], now[i].box[3]);
    }
    seen_ = std::move(now);
    layer_data_ = subset(data, layer_lists_);
    direct_data_ = subset(data, direct_lists_);
    PanelPlan plan{held != held_, &layer_data_, &direct_data_};
    if (!direct_lists_.empty()) ++direct_frames_;
    if (!plan.draw_layer) return plan;
    held_ = std::move(held);
    // In the layer's pixels: those whose centres the box holds, and their neighbours.
    auto to_pixel = [&](float v, float origin, float scale, uint32_t size, bool up) {
        const float at = (v - origin) * scale;
        return uint32_t(std::clamp(up ? std::ceil(at) : std::floor(at), 0.0f, float(size)));
    };
    const uint32_t x0 = to_pixel(box[0], data.DisplayPos.x, data.FramebufferScale.x, extent_.width, false);
    const uint32_t y0 = to_pixel(box[1], data.DisplayPos.y, data.FramebufferScale.y, extent_.height, false);
    const uint32_t x1 = to_pixel(box[2], data.DisplayPos.x, data.FramebufferScale.x, extent_.width, true);
    const uint32_t y1 = to_pixel(box[3], data.DisplayPos.y, data.FramebufferScale.y, extent_.height, true);
    box_[0] = x0;
    box_[1] = y0;
    box_[2] = x1 > x0 ? x1 - x0 : 0;
    box_[3] = y1 > y0 ? y1 - y0 : 0;
    return plan;
}

void PanelLayer::begin_layer(VkCommandBuffer cb) {
    // The host read the layer for the last frame's window before this frame was recorded (one frame in
    // flight, shown before the next is drawn); the whole layer is cleared, so what lies outside the box
    // stays transparent.
    VkClearValue transparent{};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = pass_;
    begin.framebuffer = framebuffer_;
    begin.renderArea = {{0, 0}, extent_};
    begin.clearValueCount = 1;
    begin.pClearValues = &transparent;
    vkCmdBeginRenderPass(cb, &begin, VK_SUBPASS_CONTENTS_INLINE);
}

void PanelLayer::end_layer(VkCommandBuffer cb) {
    vkCmdEndRenderPass(cb);  // in GENERAL: the mapped memory holds the pixels as laid out
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    ++draws_;
}

}  // namespace stipple::app
