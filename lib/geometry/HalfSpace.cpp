#include "geometry/HalfSpace.hpp"

#include "core/Error.hpp"
#include "geometry/SolidName.hpp"

namespace mfwave {

template <int D>
HalfSpace<D>::HalfSpace(const Vec<D>& point, const Vec<D>& outwardNormal, const std::string& name)
    : point_(point), name_(checkedSolidName(name, "half_space")) {
  if (!point.allFinite()) throw InputError(solidKey(name_, "half_space", "point"), "must be finite");
  const Real length = outwardNormal.norm();
  if (!outwardNormal.allFinite() || !(length > 0))
    throw InputError(solidKey(name_, "half_space", "normal"), "must be a finite, non-zero vector");
  normal_ = outwardNormal / length;
}

template <int D>
std::string HalfSpace<D>::surfaceName(const Vec<D>&) const {
  return qualifiedSurfaceName(name_, "plane");
}

template class HalfSpace<2>;
template class HalfSpace<3>;

}  // namespace mfwave
