#include "geometry/Annulus.hpp"

#include "core/Error.hpp"
#include "geometry/SolidName.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {

template <int D>
Annulus<D>::Annulus(const Vec<D>& centre, Real innerRadius, Real outerRadius, const std::string& name)
    : centre_(centre), inner_(innerRadius), outer_(outerRadius), name_(checkedSolidName(name, "annulus")) {
  if (!centre.allFinite()) throw InputError(solidKey(name_, "annulus", "centre"), "must be finite");
  if (!(innerRadius > 0) || !std::isfinite(outerRadius) || !(outerRadius > innerRadius))
    throw InputError(solidKey(name_, "annulus", "inner_radius"),
                     "needs 0 < inner_radius < outer_radius (finite), got " + std::to_string(innerRadius) + " and " +
                         std::to_string(outerRadius));
}

template <int D>
Real Annulus<D>::signedDistance(const Vec<D>& x) const {
  const Real r = (x - centre_).norm();
  return std::max(r - outer_, inner_ - r);
}

template <int D>
bool Annulus<D>::outerNearer(const Vec<D>& x) const {
  const Real r = (x - centre_).norm();
  return r - outer_ >= inner_ - r;
}

template <int D>
Vec<D> Annulus<D>::normal(const Vec<D>& x) const {
  const Vec<D> d = x - centre_;
  const Vec<D> radial = d.norm() > 0 ? Vec<D>(d / d.norm()) : Vec<D>(Vec<D>::Unit(0));
  return outerNearer(x) ? radial : Vec<D>(-radial);
}

template <int D>
Bounds<D> Annulus<D>::bounds() const {
  Bounds<D> b;
  b.lower = centre_.array() - outer_;
  b.upper = centre_.array() + outer_;
  return b;
}

template <int D>
std::string Annulus<D>::surfaceName(const Vec<D>& x) const {
  return qualifiedSurfaceName(name_, outerNearer(x) ? "outer" : "inner");
}

template class Annulus<2>;
template class Annulus<3>;

}  // namespace mfwave
