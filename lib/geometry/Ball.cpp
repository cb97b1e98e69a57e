#include "geometry/Ball.hpp"

#include "core/Error.hpp"
#include "geometry/SolidName.hpp"

#include <cmath>
#include <string>

namespace mfwave {

template <int D>
Ball<D>::Ball(const Vec<D>& centre, Real radius, const std::string& name)
    : centre_(centre), radius_(radius), name_(checkedSolidName(name, "ball")) {
  if (!centre.allFinite()) throw InputError(solidKey(name_, "ball", "centre"), "must be finite");
  if (!(radius > 0) || !std::isfinite(radius))
    throw InputError(solidKey(name_, "ball", "radius"), "must be positive and finite, got " + std::to_string(radius));
}

template <int D>
Vec<D> Ball<D>::normal(const Vec<D>& x) const {
  const Vec<D> r = x - centre_;
  const Real length = r.norm();
  if (length > 0) return r / length;
  return Vec<D>::Unit(0);
}

template <int D>
Bounds<D> Ball<D>::bounds() const {
  Bounds<D> b;
  b.lower = centre_.array() - radius_;
  b.upper = centre_.array() + radius_;
  return b;
}

template <int D>
std::string Ball<D>::surfaceName(const Vec<D>&) const {
  return qualifiedSurfaceName(name_, "surface");
}

template class Ball<2>;
template class Ball<3>;

}  // namespace mfwave
