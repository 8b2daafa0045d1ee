#include "core/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stipple {

namespace {
constexpr int kBarWidth = 30;
thread_local ProgressObserver* current_observer = nullptr;
}  // namespace

ScopedProgressObserver::ScopedProgressObserver(ProgressObserver* observer) : previous_(current_observer) {
    current_observer = observer;
}

ScopedProgressObserver::~ScopedProgressObserver() { current_observer = previous_; }

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)),
      observer_(current_observer),
      active_(enabled && isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() {
    if (active_ && !finished_ && shown_.load() >= 0) std::fputc('\n', stderr);
}

void ProgressBar::update(double fraction) {
    if (!(fraction >= 0.0)) fraction = 0.0;  // also catches NaN
    if (observer_) {
        if (observer_->cancelled()) throw Cancelled();
        observer_->report(std::min(fraction, 1.0));
    }
    if (!active_) return;
    const int permille = static_cast<int>(std::min(fraction, 1.0) * 1000.0);
    // Whole percents only: the cheap atomic check keeps hot loops from taking the lock.
    if (permille / 10 == shown_.load(std::memory_order_relaxed) / 10) return;
    std::lock_guard<std::mutex> lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    if (finished_ || permille <= shown_.load() || now - last_draw_ < std::chrono::milliseconds(50)) return;
    last_draw_ = now;
    draw(permille);
}

void ProgressBar::finish() {
    if (!active_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    if (finished_) return;
    draw(1000);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, " %.1f s\n", seconds);
    finished_ = true;
}

void ProgressBar::draw(int permille) {
    shown_.store(permille);
    const int filled = permille * kBarWidth / 1000;
    char bar[kBarWidth + 1];
    for (int i = 0; i < kBarWidth; ++i) bar[i] = i < filled ? '#' : '.';
    bar[kBarWidth] = '\0';
    std::fprintf(stderr, "\r%s [%s] %3d%%", label_.c_str(), bar, permille / 10);
    std::fflush(stderr);
}

}  // namespace stipple
