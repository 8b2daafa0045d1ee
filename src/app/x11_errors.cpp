#include "app/x11_errors.hpp"

#include <GLFW/glfw3.h>
#include <X11/Xlib.h>

#include <cstdio>
#include <cstdlib>

extern "C" {
GLFWAPI Display* glfwGetX11Display(void);  // as in x11_shared_memory.cpp
}

namespace stipple::app {

namespace {

// Neither returns into Xlib after a fatal failure: std::_Exit, no atexit handlers (the viewer's teardown
// would talk to the server again).
[[noreturn]] void end_viewer(const char* line) {
    std::fflush(stdout);
    std::fprintf(stderr, "stipple: %s\n", line);
    std::fflush(stderr);
    std::_Exit(1);
}

int on_x_error(Display* display, XErrorEvent* event) {
    char text[160] = {};
    XGetErrorText(display, event->error_code, text, sizeof text);  // local: no request to the server
    const bool window_gone = event->error_code == BadWindow || event->error_code == BadDrawable;
    char line[400];
    std::snprintf(line, sizeof line, "the X server refused a request of the viewer's (%s, request %d.%d, resource 0x%lx)%s", text,
                  int(event->request_code), int(event->minor_code), static_cast<unsigned long>(event->resourceid),
                  window_gone ? ": was its window destroyed from outside?" : "");
    end_viewer(line);
}

int on_x_connection_lost(Display*) { end_viewer("the connection to the X server was lost (the window was killed, or the server ended)"); }

}  // namespace

void report_x11_failures_in_one_line() {
    if (glfwGetX11Display() == nullptr) return;
    XSetErrorHandler(on_x_error);
    XSetIOErrorHandler(on_x_connection_lost);
}

}  // namespace stipple::app
