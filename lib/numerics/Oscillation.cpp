#include "numerics/Oscillation.hpp"

#include <algorithm>
#include <cmath>

namespace mfwave {

Real Oscillation::lastAmplitude() const {
  const std::size_t n = halfCycleAmplitudes.size();
  if (n < 2) return std::numeric_limits<Real>::quiet_NaN();
  return 0.5 * (halfCycleAmplitudes[n - 1] + halfCycleAmplitudes[n - 2]);
}

Real Oscillation::earlyPeriod(int periods) const {
  const auto whole = static_cast<int>((crossings.size() > 0 ? crossings.size() - 1 : 0) / 2);
  const int used = std::min(periods, whole);
  if (used < 1) return std::numeric_limits<Real>::quiet_NaN();
  return (crossings[static_cast<std::size_t>(2 * used)] - crossings.front()) / used;
}

Real Oscillation::shortestPeriod() const {
  Real shortest = std::numeric_limits<Real>::quiet_NaN();
  for (std::size_t k = 2; k < crossings.size(); ++k)
    if (!(crossings[k] - crossings[k - 2] >= shortest)) shortest = crossings[k] - crossings[k - 2];
  return shortest;
}

Real Oscillation::longestPeriod() const {
  Real longest = std::numeric_limits<Real>::quiet_NaN();
  for (std::size_t k = 2; k < crossings.size(); ++k)
    if (!(crossings[k] - crossings[k - 2] <= longest)) longest = crossings[k] - crossings[k - 2];
  return longest;
}

Oscillation analyseOscillation(const std::vector<Real>& times, const std::vector<Real>& values, Real hysteresis) {
  Oscillation o;
  const std::size_t n = std::min(times.size(), values.size());
  if (n < 3) return o;
  Real largest = 0;
  for (std::size_t k = 0; k < n; ++k) largest = std::max(largest, std::abs(values[k]));
  if (!(largest > 0) || !std::isfinite(largest)) return o;
  const Real threshold = hysteresis * largest;

  int armed = 0;       // the side the signal last reached beyond the threshold (0: not yet)
  Real lastZero = -1;  // time of the last sign change
  Real peak = 0;       // largest |u| of the current half cycle
  for (std::size_t k = 0; k < n; ++k) {
    const Real u = values[k];
    if (k > 0) {
      const Real before = values[k - 1];
      if ((before < 0 && u >= 0) || (before > 0 && u <= 0)) {
        const Real w = before / (before - u);
        lastZero = times[k - 1] + w * (times[k] - times[k - 1]);
      }
    }
    if (std::abs(u) > threshold) {
      const int side = u > 0 ? 1 : -1;
      if (armed != 0 && side != armed && lastZero >= 0) {
        o.crossings.push_back(lastZero);
        o.halfCycleAmplitudes.push_back(peak);
        peak = 0;
      }
      armed = side;
    }
    peak = std::max(peak, std::abs(u));
  }
  // The unfinished half cycle after the last crossing is not a whole one: its amplitude is dropped.
  if (o.crossings.size() >= 2) {
    o.halfPeriods = static_cast<int>(o.crossings.size()) - 1;
    o.period = 2 * (o.crossings.back() - o.crossings.front()) / o.halfPeriods;
  }
  return o;
}

}  // namespace mfwave
