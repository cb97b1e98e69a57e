#pragma once
// The period and amplitude of an oscillation from its samples (the plate study's tip
// displacement; any signal that starts at 0 and swings about it).
//
// Zero crossings are found with hysteresis: a crossing counts only once the signal has reached
// `hysteresis` times its largest |value| on the other side, so particle-scale ripples near zero
// never add spurious crossings. Its time is the linear interpolation of the last sign change before
// that. The signal starts at 0 (the plate starts straight with the mode's velocity): the
// first crossing ends the first half period, so measuring from it ignores the start; the period is
// 2 (t_last - t_first) / (crossings - 1), the mean over the rest of the run.

#include "core/Types.hpp"

#include <limits>
#include <vector>

namespace mfwave {

struct Oscillation {
  Real period = std::numeric_limits<Real>::quiet_NaN();
  int halfPeriods = 0;                    // half periods between the first and the last crossing
  std::vector<Real> crossings;            // times of the zero crossings
  std::vector<Real> halfCycleAmplitudes;  // largest |u| of each half cycle (the first from t = 0)
  Real firstAmplitude() const {
    return halfCycleAmplitudes.empty() ? std::numeric_limits<Real>::quiet_NaN() : halfCycleAmplitudes.front();
  }
  // Mean of the last two half-cycle amplitudes (one full period), NaN if fewer than two.
  Real lastAmplitude() const;
  // The mean period over the first `periods` whole periods after the first crossing (over all the
  // whole periods seen if fewer; NaN if none), and the shortest and longest single periods (from
  // crossings two apart).
  Real earlyPeriod(int periods) const;
  Real shortestPeriod() const;
  Real longestPeriod() const;
};

Oscillation analyseOscillation(const std::vector<Real>& times, const std::vector<Real>& values, Real hysteresis = 0.2);

}  // namespace mfwave
