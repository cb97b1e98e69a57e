#include "geometry/LatticeWindow.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <string>

namespace mfwave {

template <int D>
LatticeWindow<D> latticeWindow(const Bounds<D>& bounds, Real dx, const Vec<D>& origin, Real reach) {
  if (!(dx > 0) || !std::isfinite(dx)) throw InputError("spacing", "must be positive and finite, got " + std::to_string(dx));
  if (!origin.allFinite()) throw InputError("origin", "must be finite");
  if (!bounds.finite())
    throw InputError("solid", "is unbounded (a half-space?): intersect it with a bounded solid, e.g. a box, to fill it");
  LatticeWindow<D> window;
  Real total = 1;
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    const Real margin = reach + 1e-9 * dx;
    const Real low = std::ceil((bounds.lower[a] - margin - origin[a]) / dx);
    const Real high = std::floor((bounds.upper[a] + margin - origin[a]) / dx);
    const Real extent = std::max(high - low + 1, 0.0);
    total *= extent;
    if (!(total < 2147483648.0))
      throw InputError("spacing", std::to_string(dx) + " gives more than 2^31 lattice nodes over the solid's bounds");
    window.first[s] = static_cast<Index>(low);
    window.extent[s] = static_cast<Index>(extent);
  }
  return window;
}

template LatticeWindow<2> latticeWindow<2>(const Bounds<2>&, Real, const Vec2&, Real);
template LatticeWindow<3> latticeWindow<3>(const Bounds<3>&, Real, const Vec3&, Real);

}  // namespace mfwave
