#include "bench/limit_probe.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "gpu/gpu_timer.hpp"
#include "gpu/pipelines.hpp"
#include "gpu/vk_check.hpp"
#include "render/offscreen.hpp"

namespace stipple::bench {

namespace {

struct ProbeConstants {  // shaders/limit_probe.vert's push constants
    uint32_t total, drawn;
    float side, width, height, point_size;
};

}  // namespace

LimitProbe::LimitProbe(const gpu::Context& context, VkExtent2D extent)
    : context_(context), extent_(extent), depth_format_(context.depth_format) {
    try {
        color_ = gpu::Image(context, extent, kColorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
        depth_ = gpu::Image(context, extent, depth_format_, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, depth_aspect());
        VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(ProbeConstants)};
        VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layout_info.pushConstantRangeCount = 1;
        layout_info.pPushConstantRanges = &range;
        VK_CHECK(vkCreatePipelineLayout(context.device, &layout_info, nullptr, &layout_));
        gpu::GraphicsPipelineDesc desc;
        desc.vertex_shader = "limit_probe.vert";
        desc.fragment_shader = "limit_probe.frag";
        desc.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
        desc.depth_test = false;
        desc.depth_write = false;
        desc.color_format = kColorFormat;
        pipeline_ = gpu::create_graphics_pipeline(context, desc, layout_);
        // The stipple pass's state (render/stipple_renderer.cpp): the depth test without writes, the
        // coverage stencil, blending.
        desc.depth_test = true;
        desc.depth_compare = VK_COMPARE_OP_LESS_OR_EQUAL;
        desc.stencil = gpu::CoverageStencil::Test;
        desc.blend = true;
        desc.depth_format = depth_format_;
        state_pipeline_ = gpu::create_graphics_pipeline(context, desc, layout_);
    } catch (...) {
        release();
        throw;
    }
}

VkImageAspectFlags LimitProbe::depth_aspect() const {
    return gpu::format_has_stencil(depth_format_) ? VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT
                                                  : VK_IMAGE_ASPECT_DEPTH_BIT;
}

LimitProbe::~LimitProbe() { release(); }

void LimitProbe::release() {
    if (pipeline_) vkDestroyPipeline(context_.device, pipeline_, nullptr);
    if (state_pipeline_) vkDestroyPipeline(context_.device, state_pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(context_.device, layout_, nullptr);
}

double LimitProbe::frame_ms(uint32_t total, uint32_t drawn, float side, float point_size, bool with_state) {
    gpu::GpuTimer timer(context_, 4);
    auto start = std::chrono::steady_clock::now();
    VkCommandBuffer cb = context_.begin_one_shot();
    timer.begin_frame(cb);  // resets its queries: outside the rendering
    gpu::image_barrier(cb, color_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = color_.view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = {{1.0f, 1.0f, 1.0f, 1.0f}};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, extent_};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    // With the state: a depth buffer the drawn points pass (cleared to the far plane) and a stencil of
    // ones (as if a surface covered every pixel).
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    if (with_state) {
        const bool stencil = gpu::format_has_stencil(depth_format_);
        const VkImageLayout attachment =
            stencil ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        gpu::image_barrier(cb, depth_.handle(), depth_aspect(), VK_IMAGE_LAYOUT_UNDEFINED, attachment,
                           VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                           VK_ACCESS_2_NONE,
                           VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                           VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
        depth.imageView = depth_.view();
        depth.imageLayout = attachment;
        depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        depth.clearValue.depthStencil = {1.0f, 1};
        rendering.pDepthAttachment = &depth;
        rendering.pStencilAttachment = stencil ? &depth : nullptr;
    }
    // The clear gets a mark of its own: only the points are timed, as the stipple pass is.
    vkCmdBeginRendering(cb, &rendering);
    timer.mark(cb, "clear");
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, with_state ? state_pipeline_ : pipeline_);
    VkViewport viewport{0.0f, 0.0f, float(extent_.width), float(extent_.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, extent_};
    vkCmdSetViewport(cb, 0, 1, &viewport);
    vkCmdSetScissor(cb, 0, 1, &scissor);
    const ProbeConstants constants{total, drawn, side, float(extent_.width), float(extent_.height), point_size};
    vkCmdPushConstants(cb, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof constants, &constants);
    vkCmdDraw(cb, total, 1, 0, 0);
    timer.mark(cb, "probe");
    vkCmdEndRendering(cb);
    context_.submit_and_wait(cb);
    const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const auto passes = timer.read();
    return passes.size() == 2 ? passes[1].second : wall_ms;
}

double LimitProbe::frame(uint64_t culled, uint64_t drawn, uint64_t footprint_pixels, float point_size, bool with_state) {
    const uint64_t total = culled + drawn;
    if (total == 0 || total > UINT32_MAX) fail("limit probe: " + std::to_string(total) + " points is out of range");
    const float side = std::min(std::sqrt(float(std::max<uint64_t>(footprint_pixels, 1))),
                                float(std::min(extent_.width, extent_.height)));
    return frame_ms(uint32_t(total), uint32_t(drawn), side, point_size, with_state);
}

}  // namespace stipple::bench
