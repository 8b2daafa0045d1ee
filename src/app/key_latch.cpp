#include "app/key_latch.hpp"

#include <algorithm>

namespace stipple::app {

void KeyLatch::pressed(int key) {
    if (std::find(pressed_.begin(), pressed_.end(), key) == pressed_.end()) pressed_.push_back(key);
}

void KeyLatch::apply(bool* keys_down, int count, const std::function<bool(int)>& down_now) {
    for (int key : held_)
        if (key >= 0 && key < count) keys_down[key] = down_now(key);
    held_.clear();
    for (int key : pressed_) {
        if (key < 0 || key >= count || keys_down[key]) continue;  // still down: ImGui sees it as it is
        keys_down[key] = true;
        held_.push_back(key);
    }
    pressed_.clear();
}

}  // namespace stipple::app
