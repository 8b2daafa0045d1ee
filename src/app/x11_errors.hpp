#pragma once
// What the viewer says when its X server fails it: a window destroyed from outside (`xdotool windowkill`,
// a crashed window manager) or a server that went away. Xlib's own handlers print several lines of
// protocol detail and exit; ours print one line and exit with 1, as every other failure does.

namespace stipple::app {

// Installs the handlers when the windows are on X11 (GLFW's display); elsewhere it does nothing.
void report_x11_failures_in_one_line();

}  // namespace stipple::app
