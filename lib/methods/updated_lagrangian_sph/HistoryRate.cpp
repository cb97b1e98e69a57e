#include "methods/updated_lagrangian_sph/HistoryRate.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mfwave {

Real historyRate(const TimeFunction& history, Real t) {
  if (history.kind() == TimeFunction::Kind::Constant) return 0;
  std::vector<Real> times, values;
  if (history.piecewiseLinear(times, values)) {
    // First breakpoint strictly after t: the piece [times[k-1], times[k]) contains t.
    const auto after = std::upper_bound(times.begin(), times.end(), t);
    if (after == times.begin() || after == times.end()) return 0;  // held constant outside
    const auto k = static_cast<std::size_t>(after - times.begin());
    return (values[k] - values[k - 1]) / (times[k] - times[k - 1]);
  }
  const Real step = 1e-6 * std::max<Real>(1, std::abs(t));
  return (history(t + step) - history(t - step)) / (2 * step);
}

}  // namespace mfwave
