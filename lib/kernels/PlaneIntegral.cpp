#include "kernels/PlaneIntegral.hpp"

#include "core/GaussLegendre.hpp"

#include <cmath>

namespace mfwave {

Real planeIntegralThroughCentre(const Kernel& kernel) {
  const int d = kernel.dimension();
  if (d == 1) return kernel.value(0.0);

  // In q = s/h: int_plane W dS = sigma h^{-1} * c_d int_0^kappa q^{d-2} f(q) dq with c_2 = 2,
  // c_3 = 2 pi. 16 points on 8 subintervals per piece: exact for the splines (degree <= 6),
  // converged to rounding for the Gaussian.
  static const QuadratureRule rule = gaussLegendre(16);
  const std::vector<Real> breaks = kernel.pieceBreaks();
  Real radial = 0.0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    radial += integrate(
        rule, breaks[i], breaks[i + 1],
        [&](Real q) { return (d == 3 ? q : 1.0) * kernel.shape(q); }, 8);
  }
  const Real measure = d == 3 ? 2.0 * kPi : 2.0;
  return measure * kernel.normalisation() / kernel.smoothingLength() * radial;
}

}  // namespace mfwave
