#pragma once
// Screenshots of the current frame at window resolution: the swapchain image, copied right after
// the stipple passes (so the panel is not in the picture) and written as PNG once the frame is done.
#include <filesystem>
#include <string>

#include <vulkan/vulkan.h>

#include "gpu/resources.hpp"

namespace stipple::gpu {
class Context;
}

namespace stipple::app {

// The first "stipple-NNNN<extension>" in `dir` that does not exist yet (NNNN from 0001); the viewer's
// exports (".svg", ".pdf") are numbered like its screenshots.
std::filesystem::path next_screenshot_path(const std::filesystem::path& dir, const std::string& extension = ".png");

class ScreenshotCapture {
public:
    explicit ScreenshotCapture(const gpu::Context& context) : context_(context) {}

    // The next frame, to the next free name in the screenshot folder, or to `exact` when given.
    void request(std::filesystem::path exact = {}) {
        requested_ = true;
        exact_ = std::move(exact);
    }
    void cancel() { requested_ = false; }
    bool requested() const { return requested_; }
    // Requested, or copied and not yet written.
    bool pending() const { return requested_ || copied_; }

    // Records the copy of `image` (in COLOR_ATTACHMENT_OPTIMAL, left so) into a host-visible buffer.
    void record_copy(VkCommandBuffer cb, VkImage image, VkFormat format, VkExtent2D extent);
    // After the frame's fence: writes the PNG to the next free name in `dir`; returns its path, or ""
    // when no copy was recorded this frame. Throws stipple::Error when it cannot be written.
    std::string write_pending(const std::filesystem::path& dir);

private:
    const gpu::Context& context_;
    gpu::Buffer readback_;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
    std::filesystem::path exact_;
    bool requested_ = false;
    bool copied_ = false;
};

}  // namespace stipple::app
