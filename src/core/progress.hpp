#pragma once
// A one-line terminal progress bar on stderr for long CPU stages (stipple generation of big models).
// It prints only when enabled and stderr is a terminal, so logs and tests stay clean.
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace stipple {

class ProgressBar {
public:
    // `enabled` is the caller's wish (e.g. GenerationParams::progress); the bar is shown only if
    // it is set and stderr is a terminal.
    ProgressBar(std::string label, bool enabled);
    ~ProgressBar();  // finishes the line if it was left open
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    bool active() const { return active_; }
    // Overall fraction done in [0, 1]; thread-safe and cheap when nothing changes on screen
    // (it redraws at most once per percent and ~20 times per second).
    void update(double fraction);
    // Draws 100 % with the elapsed time and ends the line.
    void finish();

private:
    void draw(int permille);

    std::string label_;
    bool active_ = false;
    bool finished_ = false;
    std::atomic<int> shown_{-1};  // permille last drawn
    std::mutex mutex_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace stipple
