#pragma once
// The viewer's window (GLFW, no client API: Vulkan draws into it) and the input it gathers between
// frames. Callbacks only record what happened; the viewer acts on it once per frame, after asking
// Dear ImGui whether the panel wants the mouse or the keyboard.
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace stipple::app {

// Commands the keyboard gives (layout-aware where a character is involved: '+' is '+' anywhere).
enum class KeyCommand { OrbitLeft, OrbitRight, OrbitUp, OrbitDown, ZoomIn, ZoomOut, FrameAll, TogglePanel,
                        Screenshot, ToggleVsync, SaveScene, Quit, TogglePlay,
                        ToggleProjection };

struct Input {
    glm::dvec2 orbit_drag{0.0};  // pixels dragged with the left button since the last frame
    glm::dvec2 pan_drag{0.0};    // pixels dragged with the right or middle button
    double scroll = 0.0;         // wheel steps, positive away from the user (zoom in)
    std::vector<KeyCommand> commands;
    std::vector<std::string> dropped;  // files dropped onto the window
};

class Window {
public:
    // Throws stipple::Error with GLFW's reason (no display, no Vulkan loader, ...).
    Window(int width, int height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    // The instance extensions Vulkan needs to present into this window (VK_KHR_surface + platform).
    static std::vector<const char*> required_instance_extensions();
    VkSurfaceKHR create_surface(VkInstance instance) const;

    VkExtent2D framebuffer_size() const;
    // The primary monitor's refresh rate in Hz (60 where it reports none, as Xvfb's may).
    double refresh_rate() const;
    // Nothing can be seen: zero-sized, iconified by a window manager, or unmapped.
    bool hidden() const;
    bool should_close() const;
    void request_close();
    void set_title(const std::string& title);

    void poll_events();
    void wait_events(double timeout_seconds);  // sleeps until something happens (hidden, or nothing to draw)
    // Counts every event that may change what the window should show: input (also input the panel takes),
    // a resize, an expose (the server asks for the contents again), focus, the cursor entering or leaving.
    uint64_t activity() const { return activity_; }

    // Input since the last take_input(); the queues are emptied.
    Input take_input();
    // Whether the panel has the mouse (asked with the cursor position of a press or wheel step) or the
    // keyboard: input it has is not the viewer's.
    void set_capture_queries(std::function<bool(glm::dvec2)> wants_mouse, std::function<bool()> wants_keyboard);

private:
    static void on_cursor(GLFWwindow* w, double x, double y);
    static void on_button(GLFWwindow* w, int button, int action, int mods);
    static void on_scroll(GLFWwindow* w, double dx, double dy);
    static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);
    static void on_char(GLFWwindow* w, unsigned int codepoint);
    static void on_drop(GLFWwindow* w, int count, const char** paths);
    static void on_other(GLFWwindow* w);

    GLFWwindow* window_ = nullptr;
    Input pending_;
    glm::dvec2 cursor_{0.0};
    bool orbiting_ = false;
    bool panning_ = false;
    uint64_t activity_ = 0;
    std::function<bool(glm::dvec2)> wants_mouse_ = [](glm::dvec2) { return false; };
    std::function<bool()> wants_keyboard_ = [] { return false; };
};

}  // namespace stipple::app
