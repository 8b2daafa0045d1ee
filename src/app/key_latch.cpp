#include "app/key_latch.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace stipple::app {

void KeyLatch::pressed(int key) {
    if (std::find(pressed_.begin(), pressed_.end(), key) == pressed_.end()) pressed_.push_back(key);
}

void KeyLatch::apply(bool* keys_down, int count, const std::function<bool(int)>& down_now) {
    for (int key : held_)
        if (key >= 0 && key < count) keys_down[key] = down_now(key);
    std::vector<int> held, carried;
    for (int key : pressed_) {
        if (key < 0 || key >= count || keys_down[key]) continue;  // still down: ImGui sees it as it is
        if (std::find(held_.begin(), held_.end(), key) != held_.end()) {
            carried.push_back(key);  // down last frame: up now, then down again
            continue;
        }
        keys_down[key] = true;
        held.push_back(key);
    }
    held_ = std::move(held);
    pressed_ = std::move(carried);
}

void KeyLatch::set_modifiers(const bool* keys_down, bool& ctrl, bool& shift, bool& alt, bool& super) {
    ctrl = keys_down[GLFW_KEY_LEFT_CONTROL] || keys_down[GLFW_KEY_RIGHT_CONTROL];
    shift = keys_down[GLFW_KEY_LEFT_SHIFT] || keys_down[GLFW_KEY_RIGHT_SHIFT];
    alt = keys_down[GLFW_KEY_LEFT_ALT] || keys_down[GLFW_KEY_RIGHT_ALT];
    super = keys_down[GLFW_KEY_LEFT_SUPER] || keys_down[GLFW_KEY_RIGHT_SUPER];
}

}  // namespace stipple::app
