#pragma once
// Offscreen rendering: a colour and a depth image of a fixed size, and their read-back.
#include <vector>

#include "gpu/resources.hpp"
#include "io/png_io.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple {

inline constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;
inline constexpr int kQueuedFramesOnGpus = 8;
// The depth format is the context's (gpu::Context::depth_format).

struct RenderedFrame {
    Image color;               // RGBA8, top row first
    std::vector<float> depth;  // window depth per pixel, top row first; 1 where no surface
    // White where a surface covers the pixel, black elsewhere (for compositing and tests).
    Image coverage_mask() const;
};

class OffscreenTarget {
public:
    // color_words: a linear colour image the splat draws in directly, where the device allows
    // (RenderTargets::color_words); false: an ordinary image the splat's buffer is copied into, as for a
    // window's swapchain images (tests compare the two).
    OffscreenTarget(const gpu::Context& context, VkExtent2D extent, bool color_words = true);
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;
    VkExtent2D extent() const { return extent_; }
    RenderTargets targets() const;
    // Prepares, records, submits and waits; reads back colour and depth.
    RenderedFrame render(StippleRenderer& renderer, const FrameView& view);
    // The same frame without the read-back (what an interactive frame costs); returns wall milliseconds.
    double draw(StippleRenderer& renderer, const FrameView& view);
    // `frames` such frames queued back to back in one submission, each prepared on the CPU as it is recorded;
    // returns wall milliseconds per frame. A real GPU waited on after every frame spends much of it on the
    // round trip (submission, fence, wake-up); an interactive program keeps frames in flight instead.
    double draw_queued(StippleRenderer& renderer, const FrameView& view, int frames);
    // How many frames to queue when timing on this device: 1 on a CPU device (lavapipe runs the same either
    // way), kQueuedFramesOnGpus on a GPU, which waited on after every small frame idles and lowers its
    // clocks (an H200: 400-1200 MHz of 1980, 2026-11-27).
    static int default_queued_frames(const gpu::Context& context);

private:
    const gpu::Context& context_;
    VkExtent2D extent_;
    gpu::Image color_;
    gpu::Image depth_;
    gpu::Buffer color_readback_;
    gpu::Buffer depth_readback_;
};

}  // namespace stipple
