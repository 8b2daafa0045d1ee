#pragma once
// Dear ImGui on top of the stipple drawing: the GLFW and Vulkan backends of Debian's imgui 1.86, and
// the small render pass they need (it loads the drawing already in the swapchain image, draws the
// panel over it and leaves the image ready to present).
#include <vector>

#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace stipple::gpu {
class Context;
}

namespace stipple::app {

class Swapchain;

class Overlay {
public:
    Overlay(const gpu::Context& context, GLFWwindow* window, const Swapchain& swapchain);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    // Framebuffers for the swapchain's current images (after every recreation).
    void rebuild(const Swapchain& swapchain);

    // Starts an ImGui frame; widgets may be issued until record().
    void new_frame();
    // Ends the ImGui frame and records the panel into `image_index`, which must be in
    // COLOR_ATTACHMENT_OPTIMAL; it leaves it in PRESENT_SRC_KHR.
    void record(VkCommandBuffer cb, uint32_t image_index);

    // Whether the last frame's panel wants the mouse (a widget is being dragged, a popup is open, the
    // cursor was over it) / is editing text (then single-letter shortcuts are typing, not commands).
    bool wants_mouse() const;
    bool wants_text() const;

private:
    void destroy_framebuffers();

    const gpu::Context& context_;
    VkRenderPass render_pass_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    std::vector<VkFramebuffer> framebuffers_;
    VkExtent2D extent_{};
    bool in_frame_ = false;
};

}  // namespace stipple::app
