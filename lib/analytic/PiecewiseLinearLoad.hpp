#pragma once
// A load history f(t) through breakpoints (t_k, f_k): linear between them, held at the last value
// after the last breakpoint, and starting from f = 0 (a jump in a surface load would give an
// infinite velocity in the exact solutions). Written as f(t) = sum_k ds_k (t - t_k)_+ with ds_k the
// slope changes, so the response of a linear system to f is the same sum of its ramp responses,
// and its velocity the sum of its step displacements: how the exact Lamb solutions apply a load.

#include "core/Types.hpp"

#include <vector>

namespace mfwave {

class PiecewiseLinearLoad {
 public:
  // At least 2 breakpoints, times strictly increasing, as many values as times, all finite, the
  // first value 0. Throws InputError naming "times" or "values".
  PiecewiseLinearLoad(std::vector<Real> times, std::vector<Real> values);

  Real value(Real t) const;  // f(t)

  // sum_k ds_k response(t - t_k) over the breakpoints whose slope changes.
  template <class Response>
  Real superpose(Real t, Response&& response) const {
    Real sum = 0;
    for (std::size_t k = 0; k < times_.size(); ++k)
      if (slopeJumps_[k] != 0) sum += slopeJumps_[k] * response(t - times_[k]);
    return sum;
  }

  const std::vector<Real>& times() const { return times_; }
  const std::vector<Real>& slopeJumps() const { return slopeJumps_; }

 private:
  std::vector<Real> times_, values_, slopeJumps_;
};

}  // namespace mfwave
