#pragma once
// Scalar functions of time that scale loads and prescribed boundary values: constant, ramp,
// triangle pulse, Ricker wavelet and tabulated (piecewise linear, from numbers or a CSV file).

#include "core/Types.hpp"

#include <string>
#include <vector>

namespace mfwave {

class TimeFunction {
 public:
  enum class Kind { Constant, Ramp, Triangle, Ricker, Tabulated };

  // f(t) = value.
  static TimeFunction constant(Real value);
  // 0 before `start`, rising linearly to `amplitude` over `duration` (> 0), then held.
  static TimeFunction ramp(Real start, Real duration, Real amplitude = 1);
  // 0 before `start`, linear up to `amplitude` at start + rise, linear down to 0 at
  // start + rise + fall, 0 after (rise, fall > 0). Ding-Long-Wu eq. (36) is
  // triangle(0, 1, 1, 1): f = t on (0, 1), 2 - t on (1, 2), 0 after.
  static TimeFunction triangle(Real start, Real rise, Real fall, Real amplitude = 1);
  // Ricker wavelet (1 - 2 a) exp(-a), a = (pi f (t - delay))^2, peak `amplitude` at t = delay;
  // peakFrequency f > 0 is the frequency of the spectrum's maximum.
  static TimeFunction ricker(Real peakFrequency, Real delay, Real amplitude = 1);
  // Piecewise linear through (times[i], values[i]); times strictly increasing, at least 2 points;
  // held constant at the end values outside the table.
  static TimeFunction tabulated(std::vector<Real> times, std::vector<Real> values);
  // A CSV file with two numeric columns (time, value); header lines before the data are skipped;
  // '#' starts a comment. Errors name the file and the line. At most kMaxTableBytes
  // (core/BoundedRead.hpp) are read.
  static TimeFunction fromCsv(const std::string& path);
  // The same for the table's text; `source` names it in messages.
  static TimeFunction fromCsvText(const std::string& text, const std::string& source);

  Real operator()(Real t) const;
  Kind kind() const { return kind_; }
  // The factory's arguments, in its order (ricker: peak frequency, delay, amplitude).
  const std::vector<Real>& parameters() const { return p_; }
  // The breakpoints of a piecewise-linear function (ramp, triangle, tabulated; constant held
  // from its first breakpoint on): f is values[0] before times[0], linear between breakpoints and
  // values.back() after the last. False for a constant and a Ricker wavelet (not piecewise linear
  // with a start), when the arguments are left unchanged. Exact references that convolve a step
  // response with the load history (LambSquareLoad) take these.
  bool piecewiseLinear(std::vector<Real>& times, std::vector<Real>& values) const;
  // The time after which f is zero for good (a Ricker wavelet: below 1e-30 of its peak, 3 / f
  // after its delay); +infinity when f never ends (a constant, a ramp, a table ending non-zero).
  // Energy checks use it: after every load is quiet, a passive system's energy cannot grow.
  Real quietAfter() const;
  // One line for logs and run summaries, e.g. "ricker(peak_frequency=5, delay=0.3, amplitude=1)".
  std::string describe() const;

 private:
  TimeFunction(Kind kind, std::vector<Real> parameters) : kind_(kind), p_(std::move(parameters)) {}
  Kind kind_;
  std::vector<Real> p_;  // the parameters, in the order of the factory's arguments
  std::vector<Real> times_, values_;
  std::string source_;  // CSV path, for describe()
};

}  // namespace mfwave
