#pragma once
// Wall-clock seconds since a start, for the set-up, loop and case times every study reports.

#include <chrono>

namespace mfwave {

class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  void restart() { start_ = Clock::now(); }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  using Clock = std::chrono::steady_clock;  // monotonic: a clock change cannot make a time negative
  Clock::time_point start_;
};

// Particles times steps over seconds: the cost figure every study prints (0 for no time).
inline double particleStepsPerSecond(double particles, double steps, double seconds) {
  return seconds > 0 ? particles * steps / seconds : 0;
}

}  // namespace mfwave
