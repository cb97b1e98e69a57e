#include "analytic/RayleighWave.hpp"

#include <cmath>

namespace mfwave {

Real rayleighWaveSpeed(Real pWaveSpeed, Real shearWaveSpeed) {
  const Real gamma = shearWaveSpeed * shearWaveSpeed / (pWaveSpeed * pWaveSpeed);
  auto g = [gamma](Real xi) {
    return ((2 - xi) * (2 - xi) - 4 * std::sqrt(1 - gamma * xi) * std::sqrt(1 - xi)) / xi;
  };
  Real lo = 1e-9, hi = 1;
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const Real mid = 0.5 * (lo + hi);
    (g(mid) < 0 ? lo : hi) = mid;
  }
  return shearWaveSpeed * std::sqrt(0.5 * (lo + hi));
}

}  // namespace mfwave
