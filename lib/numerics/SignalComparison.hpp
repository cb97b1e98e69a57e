#pragma once
// How far a computed time series is from an exact one, in the three numbers wave studies report:
// the relative L2 error over a time window, the error of the peak value and the error of the
// arrival time. Both series are sampled at the same times (the run's output times).

#include "core/Types.hpp"

#include <vector>

namespace mfwave {

struct SignalErrors {
  // sqrt( int (s - e)^2 dt / int e^2 dt ) over times <= windowEnd (trapezoidal rule).
  Real relativeL2 = 0;
  // The exact series' extreme value (largest |e|, with its sign), and the computed series'
  // extreme in the same direction (max of s * sign(peak)); relative error of its magnitude,
  // (|s| - |e|) / |e| (negative when the computed peak is too small).
  Real peakExact = 0, peakComputed = 0, peakError = 0;
  // First time |series| reaches arrivalFraction * |peakExact| (linear between samples; NaN when
  // never reached in the window), and computed minus exact.
  Real arrivalExact = 0, arrivalComputed = 0, arrivalError = 0;
};

// Throws InputError("times") for fewer than 2 samples, times that do not increase, or series of
// different lengths, InputError("exact") when the exact series is zero over the window.
SignalErrors compareSignals(const std::vector<Real>& times, const std::vector<Real>& computed,
                            const std::vector<Real>& exact, Real windowEnd, Real arrivalFraction = 0.1);

}  // namespace mfwave
