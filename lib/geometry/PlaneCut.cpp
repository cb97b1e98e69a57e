#include "geometry/PlaneCut.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace mfwave {
namespace {

// Normal components below this are treated as zero (see the header).
constexpr Real kDroppedComponent = 1e-6;

// (x)_+^power, with 0^0 = 0 for the derivative's step when power is 0.
Real cutPositivePower(Real x, int power) {
  if (x <= 0) return 0;
  Real r = 1;
  for (int k = 0; k < power; ++k) r *= x;
  return r;
}

// sum over subsets S of the m components of (-1)^|S| (t - sum_S a)_+^power.
Real cutCornerSum(const std::array<Real, 3>& a, int m, Real t, int power) {
  Real total = 0;
  for (unsigned subset = 0; subset < (1u << m); ++subset) {
    Real shift = 0;
    int size = 0;
    for (int i = 0; i < m; ++i)
      if (subset & (1u << i)) {
        shift += a[static_cast<std::size_t>(i)];
        ++size;
      }
    const Real term = cutPositivePower(t - shift, power);
    total += (size % 2 == 0) ? term : -term;
  }
  return total;
}

}  // namespace

template <int D>
PlaneCut planeCutOfUnitCube(const Vec<D>& unitNormal, Real offset) {
  std::array<Real, 3> a{};
  int m = 0;
  Real kept = 0;
  for (int i = 0; i < D; ++i) {
    const Real c = std::abs(unitNormal[i]);
    if (c > kDroppedComponent) {
      a[static_cast<std::size_t>(m++)] = c;
      kept += c * c;
    }
  }
  const Real length = std::sqrt(kept);
  Real sum = 0, product = 1, factorial = 1;
  for (int i = 0; i < m; ++i) {
    sum += a[static_cast<std::size_t>(i)];
    product *= a[static_cast<std::size_t>(i)];
    factorial *= i + 1;
  }
  if (m == 0) return {offset >= 0 ? 1.0 : 0.0, 0.0};  // no normal: all or nothing
  const Real t = offset + 0.5 * sum;

  if (m == 1) {
    // A plane parallel to two faces (or to one, in 2-D): a slab; the face at the top counts.
    const Real tolerance = 1e-9 * sum;
    const Real volume = std::clamp(t / sum, 0.0, 1.0);
    const Real area = (t > tolerance && t <= sum + tolerance) ? 1.0 : 0.0;
    return {volume, area};
  }
  if (t <= 0) return {0.0, 0.0};
  if (t >= sum) return {1.0, 0.0};
  // Evaluate on the nearer half, where fewer terms are non-zero and they cancel less.
  const bool lower = t <= 0.5 * sum;
  const Real u = lower ? t : sum - t;
  const Real part = cutCornerSum(a, m, u, m) / (factorial * product);
  const Real slope = cutCornerSum(a, m, u, m - 1) / (factorial / m * product);
  return {std::clamp(lower ? part : 1 - part, 0.0, 1.0), std::max(slope, 0.0) * length};
}

template PlaneCut planeCutOfUnitCube<2>(const Vec2&, Real);
template PlaneCut planeCutOfUnitCube<3>(const Vec3&, Real);

}  // namespace mfwave
