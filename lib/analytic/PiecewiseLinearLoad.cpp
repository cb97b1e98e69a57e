#include "analytic/PiecewiseLinearLoad.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mfwave {

PiecewiseLinearLoad::PiecewiseLinearLoad(std::vector<Real> times, std::vector<Real> values)
    : times_(std::move(times)), values_(std::move(values)) {
  if (times_.size() < 2 || times_.size() != values_.size())
    throw InputError("times", "need at least 2 breakpoints and as many values as times");
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (!std::isfinite(times_[i]) || !std::isfinite(values_[i]))
      throw InputError("times", "breakpoints must be finite");
    if (i > 0 && !(times_[i] > times_[i - 1]))
      throw InputError("times", "must be strictly increasing");
  }
  if (values_.front() != 0)
    throw InputError("values", "the load must start from 0 (a jump would give infinite velocity)");
  // Slope 0 before the first breakpoint and after the last.
  Real previous = 0;
  for (std::size_t i = 0; i < times_.size(); ++i) {
    const Real slope = i + 1 < times_.size()
                           ? (values_[i + 1] - values_[i]) / (times_[i + 1] - times_[i])
                           : 0;
    slopeJumps_.push_back(slope - previous);
    previous = slope;
  }
}

Real PiecewiseLinearLoad::value(Real t) const {
  if (t <= times_.front()) return values_.front();
  if (t >= times_.back()) return values_.back();
  const auto i = static_cast<std::size_t>(
      std::upper_bound(times_.begin(), times_.end(), t) - times_.begin() - 1);
  const Real s = (t - times_[i]) / (times_[i + 1] - times_[i]);
  return values_[i] + s * (values_[i + 1] - values_[i]);
}

}  // namespace mfwave
