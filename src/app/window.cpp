#include "app/window.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>

#include "app/x11_errors.hpp"
#include "core/error.hpp"
#include "gpu/vk_check.hpp"

namespace stipple::app {

namespace {

std::string g_last_glfw_error;

void on_glfw_error(int code, const char* description) {
    g_last_glfw_error = description ? description : ("GLFW error " + std::to_string(code));
}

Window* self(GLFWwindow* w) { return static_cast<Window*>(glfwGetWindowUserPointer(w)); }

}  // namespace

Window::Window(int width, int height, const std::string& title) {
    glfwSetErrorCallback(on_glfw_error);
    if (!glfwInit()) fail("cannot open a window: " + (g_last_glfw_error.empty() ? "glfwInit failed" : g_last_glfw_error));
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        fail("cannot open a window: GLFW found no Vulkan loader or no surface support");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan, not OpenGL
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        std::string reason = g_last_glfw_error;
        glfwTerminate();
        fail("cannot open a window: " + (reason.empty() ? "glfwCreateWindow failed" : reason));
    }
    report_x11_failures_in_one_line();
    glfwSetWindowUserPointer(window_, this);
    // Installed before Dear ImGui's backend, which chains to them: both see every event.
    glfwSetCursorPosCallback(window_, on_cursor);
    glfwSetMouseButtonCallback(window_, on_button);
    glfwSetScrollCallback(window_, on_scroll);
    glfwSetKeyCallback(window_, on_key);
    glfwSetCharCallback(window_, on_char);
    glfwSetDropCallback(window_, on_drop);
    // The rest only wake the viewer (Dear ImGui's backend chains to the focus and enter ones).
    glfwSetWindowRefreshCallback(window_, on_other);
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { on_other(w); });
    glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int) { on_other(w); });
    glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int) { on_other(w); });
    glfwSetWindowIconifyCallback(window_, [](GLFWwindow* w, int) { on_other(w); });
    glfwGetCursorPos(window_, &cursor_.x, &cursor_.y);
}

Window::~Window() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<const char*> Window::required_instance_extensions() {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) fail("cannot open a window: Vulkan cannot present to this display (" + g_last_glfw_error + ")");
    return std::vector<const char*>(names, names + count);
}

VkSurfaceKHR Window::create_surface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    VK_CHECK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
    return surface;
}

VkExtent2D Window::framebuffer_size() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

double Window::refresh_rate() const {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    return mode && mode->refreshRate > 0 ? double(mode->refreshRate) : 60.0;
}

bool Window::hidden() const {
    VkExtent2D size = framebuffer_size();
    // On X11 a minimized window keeps its size: a window manager iconifies it (WM_STATE) and unmaps it.
    return size.width == 0 || size.height == 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED) ||
           !glfwGetWindowAttrib(window_, GLFW_VISIBLE);
}

bool Window::should_close() const { return glfwWindowShouldClose(window_); }
void Window::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }
void Window::poll_events() { glfwPollEvents(); }
void Window::wait_events(double timeout_seconds) { glfwWaitEventsTimeout(timeout_seconds); }

Input Window::take_input() {
    Input input = std::move(pending_);
    pending_ = Input{};
    return input;
}

void Window::set_capture_queries(std::function<bool(glm::dvec2)> wants_mouse, std::function<bool()> wants_keyboard) {
    wants_mouse_ = std::move(wants_mouse);
    wants_keyboard_ = std::move(wants_keyboard);
}

void Window::on_cursor(GLFWwindow* w, double x, double y) {
    Window* me = self(w);
    ++me->activity_;
    glm::dvec2 now(x, y), delta = now - me->cursor_;
    me->cursor_ = now;
    if (me->orbiting_) me->pending_.orbit_drag += delta;
    if (me->panning_) me->pending_.pan_drag += delta;
}

void Window::on_button(GLFWwindow* w, int button, int action, int) {
    Window* me = self(w);
    ++me->activity_;
    // A drag belongs to whoever got its press: one starting over the panel is the panel's.
    bool press = action == GLFW_PRESS;
    if (press) glfwGetCursorPos(w, &me->cursor_.x, &me->cursor_.y);
    if (press && me->wants_mouse_(me->cursor_)) return;
    if (button == GLFW_MOUSE_BUTTON_LEFT) me->orbiting_ = press;
    if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE) me->panning_ = press;
}

void Window::on_scroll(GLFWwindow* w, double, double dy) {
    Window* me = self(w);
    ++me->activity_;
    if (!me->wants_mouse_(me->cursor_)) me->pending_.scroll += dy;
}

void Window::on_key(GLFWwindow* w, int key, int, int action, int mods) {
    Window* me = self(w);
    ++me->activity_;
    if (action == GLFW_RELEASE || me->wants_keyboard_()) return;
    auto& out = me->pending_.commands;
    switch (key) {
        case GLFW_KEY_ESCAPE:  // a press, not its repeat: Escape held to close a list would quit once it closed
            if (action == GLFW_PRESS) out.push_back(KeyCommand::Quit);
            break;
        case GLFW_KEY_LEFT: out.push_back(KeyCommand::OrbitLeft); break;
        case GLFW_KEY_RIGHT: out.push_back(KeyCommand::OrbitRight); break;
        case GLFW_KEY_UP: out.push_back(KeyCommand::OrbitUp); break;
        case GLFW_KEY_DOWN: out.push_back(KeyCommand::OrbitDown); break;
        case GLFW_KEY_S:
            // Ctrl+S gives no character event, so it is taken here; a plain S comes through on_char.
            if (mods & GLFW_MOD_CONTROL) out.push_back(KeyCommand::SaveScene);
            break;
        default: break;
    }
}

void Window::on_char(GLFWwindow* w, unsigned int c) {
    Window* me = self(w);
    ++me->activity_;
    if (me->wants_keyboard_()) return;
    auto& out = me->pending_.commands;
    switch (c) {
        case '+': case '=': out.push_back(KeyCommand::ZoomIn); break;
        case '-': case '_': out.push_back(KeyCommand::ZoomOut); break;
        case 'f': case 'F': out.push_back(KeyCommand::FrameAll); break;
        case 'h': case 'H': out.push_back(KeyCommand::TogglePanel); break;
        case 's': case 'S': out.push_back(KeyCommand::Screenshot); break;
        case 'v': case 'V': out.push_back(KeyCommand::ToggleVsync); break;
        case 'q': case 'Q': out.push_back(KeyCommand::Quit); break;
        case ' ': out.push_back(KeyCommand::TogglePlay); break;
        case 'o': case 'O': out.push_back(KeyCommand::ToggleProjection); break;
        default: break;
    }
}

void Window::on_drop(GLFWwindow* w, int count, const char** paths) {
    Window* me = self(w);
    ++me->activity_;
    for (int i = 0; i < count; ++i)
        if (paths[i]) me->pending_.dropped.emplace_back(paths[i]);
}

void Window::on_other(GLFWwindow* w) { ++self(w)->activity_; }

}  // namespace stipple::app
