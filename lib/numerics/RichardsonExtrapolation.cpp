#include "numerics/RichardsonExtrapolation.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>

namespace mfwave {
namespace {

void requireSpacing(const ConvergenceSample& s) {
  if (!(s.spacing > 0) || !std::isfinite(s.spacing))
    throw InputError("spacing", "convergence samples need positive finite spacings");
}

}  // namespace

std::optional<Real> observedOrder(const ConvergenceSample& coarse, const ConvergenceSample& middle,
                                  const ConvergenceSample& fine, Real minOrder, Real maxOrder) {
  requireSpacing(coarse);
  requireSpacing(middle);
  requireSpacing(fine);
  if (!(coarse.spacing > middle.spacing && middle.spacing > fine.spacing))
    throw InputError("spacing", "samples must be ordered coarse > middle > fine");
  const Real d1 = coarse.value - middle.value;
  const Real d2 = middle.value - fine.value;
  if (d1 == 0 || d2 == 0 || (d1 > 0) != (d2 > 0)) return std::nullopt;
  const Real ratio = d1 / d2;
  // (h1^p - h2^p) / (h2^p - h3^p) grows monotonically with p for h1 > h2 > h3.
  const auto model = [&](Real p) {
    const Real a = std::pow(coarse.spacing, p), b = std::pow(middle.spacing, p), c = std::pow(fine.spacing, p);
    return (a - b) / (b - c) - ratio;
  };
  Real lo = minOrder, hi = maxOrder;
  if (model(lo) > 0 || model(hi) < 0) return std::nullopt;
  for (int k = 0; k < 200 && hi - lo > 1e-12; ++k) {
    const Real mid = 0.5 * (lo + hi);
    (model(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Real richardsonLimit(const ConvergenceSample& coarse, const ConvergenceSample& fine, Real order) {
  requireSpacing(coarse);
  requireSpacing(fine);
  const Real factor = std::pow(coarse.spacing / fine.spacing, order) - 1;
  if (!(factor != 0) || !std::isfinite(factor)) throw InputError("spacing", "the two spacings must differ");
  return fine.value + (fine.value - coarse.value) / factor;
}

std::optional<RichardsonSeries> richardsonSeries(std::vector<ConvergenceSample> samples, Real assumedOrder) {
  std::sort(samples.begin(), samples.end(),
            [](const ConvergenceSample& a, const ConvergenceSample& b) { return a.spacing > b.spacing; });
  if (samples.size() < 2) return std::nullopt;
  RichardsonSeries series;
  const std::size_t n = samples.size();
  series.resolutions = n;
  if (n >= 3) series.observedOrder = observedOrder(samples[n - 3], samples[n - 2], samples[n - 1]);
  series.orderUsed = series.observedOrder.value_or(assumedOrder);
  series.limit = richardsonLimit(samples[n - 2], samples[n - 1], series.orderUsed);
  return series;
}

}  // namespace mfwave
