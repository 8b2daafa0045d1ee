#pragma once
// Wall-clock timing for the figures commands print (load, generation, frame times).
#include <chrono>

namespace stipple {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

inline double milliseconds_since(Clock::time_point start) { return 1000.0 * seconds_since(start); }

}  // namespace stipple
