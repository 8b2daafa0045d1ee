#include "app/overlay.hpp"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <string>

#include <imgui.h>
#include <imgui_internal.h>  // ClosePopupsExceptModals
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/panel_layer.hpp"
#include "app/swapchain.hpp"
#include "core/error.hpp"
#include "gpu/context.hpp"
#include "gpu/resources.hpp"
#include "gpu/vk_check.hpp"

namespace stipple::app {

namespace {

// The overlay whose window's key events on_key latches (one window, one overlay), and the callback it chains to
// (the backend's, which chains to the window's own).
Overlay* g_key_overlay = nullptr;
GLFWkeyfun g_backend_key_callback = nullptr;

// The backend reports its VkResults here; a failure ends the viewer like any other Vulkan failure.
void check_imgui_result(VkResult result) {
    if (result < 0) stipple::gpu::vk_check(result, "Dear ImGui Vulkan backend", __FILE__, __LINE__);
}

}  // namespace

void Overlay::on_key(GLFWwindow* window, int key, int scancode, int action, int mods) {
    if (g_backend_key_callback) g_backend_key_callback(window, key, scancode, action, mods);
    if (g_key_overlay && action == GLFW_PRESS) g_key_overlay->key_latch_.pressed(key);
}

Overlay::Overlay(const gpu::Context& context, GLFWwindow* window, const Swapchain& swapchain)
    : context_(context), window_(window) {
    render_pass_ = create_panel_pass(context.device, swapchain.format(), PanelTarget::Frame, swapchain.present_layout());
    layer_ = std::make_unique<PanelLayer>(context, swapchain.format());
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
    // Ahead of the backend's key callback: presses to latch (app/key_latch.hpp). Last, so that a constructor
    // that throws leaves no callback pointing at it; the backend's shutdown puts the window's own back.
    g_key_overlay = this;
    g_backend_key_callback = glfwSetKeyCallback(window, on_key);
}

Overlay::~Overlay() {
    vkDeviceWaitIdle(context_.device);
    layer_.reset();
    if (in_frame_) ImGui::EndFrame();
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    g_key_overlay = nullptr;
    g_backend_key_callback = nullptr;
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
    present_layout_ = swapchain.present_layout();
    images_.clear();
    if (layer_enabled()) layer_->rebuild(swapchain);  // without images where the swapchain has none
    if (!swapchain.valid()) return;
    for (uint32_t i = 0; i < swapchain.image_count(); ++i) {
        images_.push_back(swapchain.image(i));
        framebuffers_.push_back(create_panel_framebuffer(context_.device, render_pass_, swapchain.view(i), extent_));
    }
    ImGui_ImplVulkan_SetMinImageCount(std::max(swapchain.min_image_count(), 2u));
}

void Overlay::new_frame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGuiIO& io = ImGui::GetIO();
    // A drag that leaves the window keeps its cursor: this backend reads the cursor only over the window or
    // while the window has focus, so a slider dragged past the window's edge in an unfocused window (no window
    // manager to focus it) read no cursor and jumped to its least value. The pointer is grabbed while a
    // button is held, so GLFW's cursor stays true outside.
    if (!ImGui::IsMousePosValid(&io.MousePos) &&
        std::any_of(std::begin(io.MouseDown), std::end(io.MouseDown), [](bool down) { return down; })) {
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window_, &x, &y);
        io.MousePos = ImVec2(float(x), float(y));
    }
    key_latch_.apply(io.KeysDown, IM_ARRAYSIZE(io.KeysDown), [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS; });
    KeyLatch::set_modifiers(io.KeysDown, io.KeyCtrl, io.KeyShift, io.KeyAlt, io.KeySuper);
    // The panel is drawn into the frame, which a window larger than the device can draw is clamped to
    // (swapchain.cpp): its viewport must not be the window's.
    if (extent_.width > 0 && extent_.height > 0 && io.DisplayFramebufferScale.x > 0.0f && io.DisplayFramebufferScale.y > 0.0f) {
        io.DisplaySize.x = std::min(io.DisplaySize.x, float(extent_.width) / io.DisplayFramebufferScale.x);
        io.DisplaySize.y = std::min(io.DisplaySize.y, float(extent_.height) / io.DisplayFramebufferScale.y);
    }
    ImGui::NewFrame();
    // Escape closes an open list or menu (this Dear ImGui does so only with keyboard navigation on); the
    // viewer leaves Escape to the panel meanwhile (wants_keys) rather than quitting.
    if (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopup) && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false))
        ImGui::ClosePopupsExceptModals();
    in_frame_ = true;
}

void Overlay::record(VkCommandBuffer cb, uint32_t image_index) {
    STIPPLE_CHECK(in_frame_, "Overlay::record without new_frame");
    ImGui::Render();
    in_frame_ = false;
    ImDrawData* data = ImGui::GetDrawData();
    if (layer_->active()) {  // the window's copy lays the layer over the frame (panel_pixels)
        const PanelPlan plan = layer_->plan(*data);
        if (plan.draw_layer) {
            layer_->begin_layer(cb);
            ImGui_ImplVulkan_RenderDrawData(plan.layer, cb);
            layer_->end_layer(cb);
        }
        data = plan.direct;  // windows that change every frame: into the frame, under the layer
        if (data->CmdListsCount == 0) {
            gpu::image_barrier(cb, images_.at(image_index), VK_IMAGE_ASPECT_COLOR_BIT,
                               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, present_layout_,
                               VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
            return;
        }
    }
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = render_pass_;
    begin.framebuffer = framebuffers_.at(image_index);
    begin.renderArea = {{0, 0}, extent_};
    vkCmdBeginRenderPass(cb, &begin, VK_SUBPASS_CONTENTS_INLINE);
    ImGui_ImplVulkan_RenderDrawData(data, cb);
    vkCmdEndRenderPass(cb);
}

uint64_t Overlay::panel_draws() const { return layer_->draws(); }
uint64_t Overlay::panel_direct_frames() const { return layer_->direct_frames(); }

PixelsOver Overlay::panel_pixels() const { return layer_->pixels(); }

bool Overlay::layer_enabled() {
    // STIPPLE_PANEL_LAYER=off draws the panel straight into every frame, as on a swapchain's own images
    // (a check of the layer: tests/test_cli_view_output.cpp compares the two).
    const char* setting = std::getenv("STIPPLE_PANEL_LAYER");
    return !(setting && std::string(setting) == "off");
}

bool Overlay::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
// Not WantCaptureKeyboard: that also holds while a window is dragged, and a key pressed just after the
// release (before the next frame updates it) would be lost. Only text fields use keys in this panel.
bool Overlay::wants_text() const { return ImGui::GetIO().WantTextInput; }
bool Overlay::wants_keys() const { return wants_text() || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopup); }

}  // namespace stipple::app
