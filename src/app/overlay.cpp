#include "app/overlay.hpp"

#include <algorithm>

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include "app/swapchain.hpp"
#include "core/error.hpp"
#include "gpu/context.hpp"
#include "gpu/vk_check.hpp"

namespace stipple::app {

namespace {

// The backend reports its VkResults here; a failure ends the viewer like any other Vulkan failure.
void check_imgui_result(VkResult result) {
    if (result < 0) stipple::gpu::vk_check(result, "Dear ImGui Vulkan backend", __FILE__, __LINE__);
}

VkRenderPass create_overlay_pass(VkDevice device, VkFormat format, VkImageLayout final_layout) {
    VkAttachmentDescription color{};
    color.format = format;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // the stipple drawing is already there
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.finalLayout = final_layout;  // presented by the swapchain, or read by the host (Swapchain::present_layout)
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    // The stipple pass (or a screenshot copy) wrote the image before; the panel blends over it.
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

}  // namespace

Overlay::Overlay(const gpu::Context& context, GLFWwindow* window, const Swapchain& swapchain) : context_(context) {
    render_pass_ = create_overlay_pass(context.device, swapchain.format(), swapchain.present_layout());
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pool.maxSets = 4;
    pool.poolSizeCount = 1;
    pool.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(context.device, &pool, nullptr, &pool_));

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini dropped into whatever folder the viewer runs in
    ImGui::StyleColorsDark();
    ImGui::GetStyle().Alpha = 0.94f;
    ImGui_ImplGlfw_InitForVulkan(window, true);  // chains to the window's own callbacks

    ImGui_ImplVulkan_InitInfo init{};
    init.Instance = context.instance;
    init.PhysicalDevice = context.physical_device;
    init.Device = context.device;
    init.QueueFamily = context.queue_family;
    init.Queue = context.queue;
    init.DescriptorPool = pool_;
    init.Subpass = 0;
    init.MinImageCount = std::max(swapchain.min_image_count(), 2u);
    init.ImageCount = std::max(swapchain.image_count(), init.MinImageCount);
    init.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    init.CheckVkResultFn = check_imgui_result;
    if (!ImGui_ImplVulkan_Init(&init, render_pass_)) fail("Dear ImGui's Vulkan backend failed to initialise");

    VkCommandBuffer cb = context.begin_one_shot();
    ImGui_ImplVulkan_CreateFontsTexture(cb);
    context.submit_and_wait(cb);
    ImGui_ImplVulkan_DestroyFontUploadObjects();
    rebuild(swapchain);
}

Overlay::~Overlay() {
    vkDeviceWaitIdle(context_.device);
    if (in_frame_) ImGui::EndFrame();
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    destroy_framebuffers();
    vkDestroyDescriptorPool(context_.device, pool_, nullptr);
    vkDestroyRenderPass(context_.device, render_pass_, nullptr);
}

void Overlay::destroy_framebuffers() {
    for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(context_.device, f, nullptr);
    framebuffers_.clear();
}

void Overlay::rebuild(const Swapchain& swapchain) {
    destroy_framebuffers();
    extent_ = swapchain.extent();
    if (!swapchain.valid()) return;
    for (uint32_t i = 0; i < swapchain.image_count(); ++i) {
        VkImageView view = swapchain.view(i);
        VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        info.renderPass = render_pass_;
        info.attachmentCount = 1;
        info.pAttachments = &view;
        info.width = extent_.width;
        info.height = extent_.height;
        info.layers = 1;
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        VK_CHECK(vkCreateFramebuffer(context_.device, &info, nullptr, &framebuffer));
        framebuffers_.push_back(framebuffer);
    }
    ImGui_ImplVulkan_SetMinImageCount(std::max(swapchain.min_image_count(), 2u));
}

void Overlay::new_frame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    in_frame_ = true;
}

void Overlay::record(VkCommandBuffer cb, uint32_t image_index) {
    STIPPLE_CHECK(in_frame_, "Overlay::record without new_frame");
    ImGui::Render();
    in_frame_ = false;
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = render_pass_;
    begin.framebuffer = framebuffers_.at(image_index);
    begin.renderArea = {{0, 0}, extent_};
    vkCmdBeginRenderPass(cb, &begin, VK_SUBPASS_CONTENTS_INLINE);
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cb);
    vkCmdEndRenderPass(cb);
}

bool Overlay::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
// Not WantCaptureKeyboard: that also holds while a window is dragged, and a key pressed just after the
// release (before the next frame updates it) would be lost. Only text fields use keys in this panel.
bool Overlay::wants_text() const { return ImGui::GetIO().WantTextInput; }

}  // namespace stipple::app
