#pragma once
// A one-line terminal progress bar on stderr for long CPU stages (stipple generation of big models).
// It prints only when enabled and stderr is a terminal, so logs and tests stay clean.
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <string>

namespace stipple {

// Watches long work from another thread (the viewer's background generation): every ProgressBar made
// on a thread that has an observer installed reports its fraction to it, and throws Cancelled from
// update() once the observer is cancelled, so the work stops at its next progress report.
class ProgressObserver {
public:
    double fraction() const { return fraction_.load(std::memory_order_relaxed); }
    void cancel() { cancelled_.store(true); }
    bool cancelled() const { return cancelled_.load(); }
    void report(double fraction) { fraction_.store(fraction, std::memory_order_relaxed); }

private:
    std::atomic<double> fraction_{0.0};
    std::atomic<bool> cancelled_{false};
};

// Thrown by ProgressBar::update when its observer was cancelled.
struct Cancelled : std::exception {
    const char* what() const noexcept override { return "cancelled"; }
};

// Installs `observer` for the ProgressBars this thread makes while it lives.
class ScopedProgressObserver {
public:
    explicit ScopedProgressObserver(ProgressObserver* observer);
    ~ScopedProgressObserver();
    ScopedProgressObserver(const ScopedProgressObserver&) = delete;
    ScopedProgressObserver& operator=(const ScopedProgressObserver&) = delete;

private:
    ProgressObserver* previous_;
};

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
    // (it redraws at most once per percent and ~20 times per second). Throws Cancelled when the
    // observer installed where the bar was made has been cancelled.
    void update(double fraction);
    // Draws 100 % with the elapsed time and ends the line.
    void finish();

private:
    void draw(int permille);

    std::string label_;
    ProgressObserver* observer_ = nullptr;
    bool active_ = false;
    bool finished_ = false;
    std::atomic<int> shown_{-1};  // permille last drawn
    std::mutex mutex_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace stipple
