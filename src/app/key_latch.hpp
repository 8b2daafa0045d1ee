#pragma once
// Keys pressed and released between two frames, held down for one frame so that Dear ImGui sees them.
//
// Debian's Dear ImGui 1.86 reads the keyboard as states (io.KeysDown), once a frame, and its GLFW backend
// sets them from the key callback. A key pressed and released between two frames is never seen down:
// a typed value's Enter (xdotool's key, a quick typist, any frame slower than a keystroke: a heavy scene
// draws at a few frames a second) did not commit it, and D_max stayed as it was. (1.87 queues the events
// instead; this is that queue's effect for the keys that need it.)
#include <functional>
#include <vector>

namespace stipple::app {

class KeyLatch {
public:
    // From the key callback, on a press (after the backend has set the key's state).
    void pressed(int key);
    // Once a frame, before ImGui::NewFrame: `keys_down` is io.KeysDown (`count` of them), `down_now` the
    // key's real state. A key latched last frame gets its real state back; a key pressed since then and no
    // longer down is held down for this frame (one latched last frame and pressed again: up for this frame,
    // down for the next, so that the second press is a press of its own).
    void apply(bool* keys_down, int count, const std::function<bool(int)>& down_now);
    // After apply: Ctrl, Shift, Alt and Super as the keys' states now say (`keys_down`, GLFW's key codes), as the
    // backend sets them on each key event. A quick Ctrl+A (both pressed and released between two frames) had
    // both keys held by apply but the backend's Ctrl already released: Dear ImGui saw a bare A, did not select
    // the field's text, and what was typed next was added to it (a tester's 2.5 read 2).
    static void set_modifiers(const bool* keys_down, bool& ctrl, bool& shift, bool& alt, bool& super);
    // Forgets the presses since the last apply: frames without the panel (hidden), whose keys are not its.
    void forget() { pressed_.clear(); }

private:
    std::vector<int> pressed_;  // since the last apply
    std::vector<int> held_;     // held down by the last apply
};

}  // namespace stipple::app
