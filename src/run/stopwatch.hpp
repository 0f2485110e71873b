// Wall-clock seconds between the laps of a piece of work (where a report's time goes).
#pragma once

#include <chrono>

namespace bb {

class Stopwatch {
 public:
  /// Seconds since the last lap (or since the stopwatch was made); starts the next lap.
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace bb
