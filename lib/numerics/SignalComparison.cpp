#include "numerics/SignalComparison.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <limits>

namespace mfwave {
namespace {

// First time |s| >= level, interpolated linearly between the samples; NaN if never.
Real firstCrossing(const std::vector<Real>& t, const std::vector<Real>& s, std::size_t count, Real level) {
  for (std::size_t i = 0; i < count; ++i) {
    if (std::abs(s[i]) < level) continue;
    if (i == 0) return t[0];
    const Real a = std::abs(s[i - 1]), b = std::abs(s[i]);
    return t[i - 1] + (t[i] - t[i - 1]) * (level - a) / (b - a);
  }
  return std::numeric_limits<Real>::quiet_NaN();
}

}  // namespace

SignalErrors compareSignals(const std::vector<Real>& times, const std::vector<Real>& computed,
                            const std::vector<Real>& exact, Real windowEnd, Real arrivalFraction) {
  if (times.size() < 2) throw InputError("times", "need at least 2 samples to compare signals");
  if (computed.size() != times.size() || exact.size() != times.size())
    throw InputError("times", "computed and exact series need one value per time");
  std::size_t count = 0;
  while (count < times.size() && times[count] <= windowEnd) {
    if (count > 0 && !(times[count] > times[count - 1])) throw InputError("times", "times must increase strictly");
    ++count;
  }
  if (count < 2) throw InputError("times", "fewer than 2 samples inside the window");

  SignalErrors e;
  Real error2 = 0, norm2 = 0;
  std::size_t peakAt = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (std::abs(exact[i]) > std::abs(exact[peakAt])) peakAt = i;
    if (i == 0) continue;
    const Real dt = times[i] - times[i - 1];
    const Real d0 = computed[i - 1] - exact[i - 1], d1 = computed[i] - exact[i];
    error2 += 0.5 * dt * (d0 * d0 + d1 * d1);
    norm2 += 0.5 * dt * (exact[i - 1] * exact[i - 1] + exact[i] * exact[i]);
  }
  if (!(norm2 > 0)) throw InputError("exact", "the exact series is zero over the window");
  e.relativeL2 = std::sqrt(error2 / norm2);

  e.peakExact = exact[peakAt];
  const Real sign = e.peakExact >= 0 ? 1 : -1;
  e.peakComputed = computed[0];
  for (std::size_t i = 0; i < count; ++i)
    if (sign * computed[i] > sign * e.peakComputed) e.peakComputed = computed[i];
  e.peakError = sign * (e.peakComputed - e.peakExact) / std::abs(e.peakExact);  // < 0: peak too small

  const Real level = arrivalFraction * std::abs(e.peakExact);
  e.arrivalExact = firstCrossing(times, exact, count, level);
  e.arrivalComputed = firstCrossing(times, computed, count, level);
  e.arrivalError = e.arrivalComputed - e.arrivalExact;
  return e;
}

}  // namespace mfwave
