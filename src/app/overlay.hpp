#pragma once
// Dear ImGui on top of the stipple drawing: the GLFW and Vulkan backends of Debian's imgui 1.86, and
// the small render pass they need (it loads the drawing already in the swapchain image, draws the
// panel over it and leaves the image ready to present). Where the host copies the frames to the window
// (X11 shared memory), the panel is drawn into a layer only when it changes, and the copy lays it over
// each frame (app/panel_layer.hpp).
#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "app/key_latch.hpp"
#include "app/pixel_over.hpp"

struct GLFWwindow;

namespace stipple::gpu {
class Context;
}

namespace stipple::app {

class PanelLayer;
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
    // A frame without the panel: the keys pressed since the last one are not the panel's.
    void skip_frame() { key_latch_.forget(); }
    // Ends the ImGui frame and records the panel into `image_index` (or into the layer), which must be in
    // COLOR_ATTACHMENT_OPTIMAL; it leaves it in the swapchain's present_layout().
    void record(VkCommandBuffer cb, uint32_t image_index);

    // Whether the last frame's panel wants the mouse (a widget is being dragged, a popup is open, the
    // cursor was over it) / is editing text (then single-letter shortcuts are typing, not commands).
    bool wants_mouse() const;
    bool wants_text() const;
    // Keys belong to the panel: a text field is typed in, or a list or menu is open (Escape closes it
    // rather than quitting the viewer).
    bool wants_keys() const;

    // The panel's layer, for the window's copy to lay over the frame (Swapchain::present); no pixels
    // where the panel is drawn straight into every frame.
    PixelsOver panel_pixels() const;
    // How many frames drew the panel's triangles into the layer (the others reused it), and how many drew
    // windows that change every frame (the timeline while an animation plays) into the frame instead.
    uint64_t panel_draws() const;
    uint64_t panel_direct_frames() const;

private:
    void destroy_framebuffers();
    static bool layer_enabled();

    static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);

    const gpu::Context& context_;
    GLFWwindow* window_ = nullptr;
    KeyLatch key_latch_;
    VkRenderPass render_pass_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    std::vector<VkFramebuffer> framebuffers_;
    std::vector<VkImage> images_;
    VkImageLayout present_layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
    std::unique_ptr<PanelLayer> layer_;
    VkExtent2D extent_{};
    bool in_frame_ = false;
};

}  // namespace stipple::app
