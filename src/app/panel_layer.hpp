#pragma once
// The panel drawn into a layer of its own only when it changes, and laid over each frame as the frame
// is copied to the X server (app/x11_shared_memory.hpp, app/pixel_over.hpp), where the window's frames
// reach it through shared memory (lavapipe). Dear ImGui's few thousand triangles cost llvmpipe 6-7 ms
// a frame at 1280x1024, a fifth of the bunny's frame with lines: bilinear fetches of the font texture
// and blending over half a million pixels of panel, one to three layers deep. The panel changes when the
// user touches it or its figures refresh (twice a second); the other frames only blend the layer's
// pixels into the copy the window takes anyway.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <imgui.h>
#include <vulkan/vulkan.h>

#include "app/panel_windows.hpp"
#include "app/pixel_over.hpp"
#include "gpu/resources.hpp"

namespace stipple::gpu {
class Context;
}

namespace stipple::app {

class Swapchain;

// The render pass Dear ImGui draws in: into the frame (loading the drawing already there, ending in the
// layout the window takes) or into the layer (cleared to transparent black, ending in GENERAL, where the
// layer's memory holds its pixels as the host reads them). The two are compatible, so ImGui's one
// pipeline draws in both.
enum class PanelTarget { Frame, Layer };
VkRenderPass create_panel_pass(VkDevice device, VkFormat format, PanelTarget target, VkImageLayout final_layout);
// A framebuffer of `pass` for one colour image of `extent`.
VkFramebuffer create_panel_framebuffer(VkDevice device, VkRenderPass pass, VkImageView view, VkExtent2D extent);

// What a frame draws of the panel: into the layer (when what it should hold changed) and straight into
// the frame. ImGui makes a draw list per window, back to front. A window that changed in each of the
// last two frames (the timeline while an animation plays) is drawn into each frame instead, unless it
// lies in front of a window the layer holds and overlaps it (app/panel_windows.hpp).
struct PanelPlan {
    bool draw_layer = false;
    ImDrawData* layer = nullptr;   // the windows the layer holds
    ImDrawData* direct = nullptr;  // the windows drawn into the frame (none: CmdListsCount 0)
};

class PanelLayer {
public:
    PanelLayer(const gpu::Context& context, VkFormat format);
    ~PanelLayer();
    PanelLayer(const PanelLayer&) = delete;
    PanelLayer& operator=(const PanelLayer&) = delete;

    // For the swapchain's current images: active where the host copies them to the window (and the layer
    // can be mapped), else not, and the overlay draws the panel straight into each frame.
    void rebuild(const Swapchain& swapchain);
    bool active() const { return framebuffer_ != VK_NULL_HANDLE; }

    // Splits this frame's windows between the layer and the frame (valid until the next plan).
    PanelPlan plan(const ImDrawData& data);
    // Around ImGui's commands for plan().layer: the layer cleared, drawn, then ready for the host.
    void begin_layer(VkCommandBuffer cb);
    void end_layer(VkCommandBuffer cb);

    // The layer as the window's copy lays it over the frame, once the frame's commands have completed.
    PixelsOver pixels() const;
    // How many frames drew windows into the layer (the others reused it), and how many drew windows
    // that change every frame into the frame.
    uint64_t draws() const { return draws_; }
    uint64_t direct_frames() const { return direct_frames_; }

private:
    struct Window : PanelWindow {  // a window's draw list as last seen (box in ImGui's coordinates)
        const ImDrawList* list = nullptr;
        std::vector<std::byte> bytes;  // what ImGui_ImplVulkan_RenderDrawData draws from
    };
    void release_images();

    const gpu::Context& context_;
    VkFormat format_;
    VkRenderPass pass_ = VK_NULL_HANDLE;
    gpu::Image layer_;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
    VkExtent2D extent_{};

    std::vector<Window> seen_;                 // last frame's windows
    std::vector<std::byte> held_;              // what the layer holds: the frame's placement, its windows' bytes
    std::vector<ImDrawList*> layer_lists_, direct_lists_;
    ImDrawData layer_data_{}, direct_data_{};
    uint32_t box_[4] = {};  // the layer's pixels that may not be transparent: x, y, width, height
    uint64_t draws_ = 0, direct_frames_ = 0;
};

}  // namespace stipple::app
