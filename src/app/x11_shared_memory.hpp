#pragma once
// A window's frames handed to the X server through shared memory (MIT-SHM), for CPU devices.
//
// Why: Mesa's software presentation (lavapipe's swapchain) sends every frame through the X connection's
// socket as PutImage requests unless the server also has DRI3, which Xvfb, Xvnc and X servers on
// machines without a GPU driver lack. At 1280x1024 that is 5 MB a frame written into the socket, read
// and copied again by the server: about 15 ms of the two cores' time per frame on the project's
// machine (perf, 2026-12-01), a third of the viewer's frame. Through shared memory the server copies
// the frame once from a segment it shares with us.
#include <cstdint>
#include <memory>
#include <string>

#include <vulkan/vulkan.h>

#include "app/pixel_over.hpp"

struct GLFWwindow;

namespace stipple::app {

class X11SharedMemory {
public:
    // The window's X11 display and window, or null with the reason in `why`: not an X11 window, a server
    // without MIT-SHM or on another machine (a segment cannot be attached), or a visual whose pixels are
    // not 24-bit true colour in 32-bit little-endian words (B8G8R8A8 in Vulkan's terms).
    static std::unique_ptr<X11SharedMemory> open(GLFWwindow* window, std::string* why);
    ~X11SharedMemory();
    X11SharedMemory(const X11SharedMemory&) = delete;
    X11SharedMemory& operator=(const X11SharedMemory&) = delete;

    // `count` segments of `extent` (the old ones detached); throws when the server refuses them.
    void resize(VkExtent2D extent, uint32_t count);
    // Copies `pixels` (extent.height rows of extent.width B8G8R8A8 words, `row_pitch` bytes apart) into
    // segment `index`, with `over` laid over them (the viewer's panel: app/pixel_over.hpp), and asks the
    // server to show it in the window. Waits first, if need be, until the server has finished with the
    // segment's previous frame.
    void show(uint32_t index, const void* pixels, size_t row_pitch, const PixelsOver& over = {});

private:
    struct State;
    explicit X11SharedMemory(std::unique_ptr<State> state);
    void release_segments();
    std::unique_ptr<State> state_;
};

}  // namespace stipple::app
