#include "geometry/BoxSolid.hpp"

#include "core/Error.hpp"
#include "geometry/SolidName.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {

template <int D>
BoxSolid<D>::BoxSolid(const Vec<D>& lower, const Vec<D>& upper, const std::string& name)
    : name_(checkedSolidName(name, "box")) {
  if (!lower.allFinite()) throw InputError(solidKey(name_, "box", "lower"), "must be finite");
  if (!upper.allFinite()) throw InputError(solidKey(name_, "box", "upper"), "must be finite");
  for (int a = 0; a < D; ++a)
    if (!(upper[a] > lower[a]))
      throw InputError(solidKey(name_, "box", "upper"), "must exceed lower on every axis; axis " + std::to_string(a) +
                                                            " has lower " + std::to_string(lower[a]) + ", upper " +
                                                            std::to_string(upper[a]));
  centre_ = 0.5 * (lower + upper);
  half_ = 0.5 * (upper - lower);
}

template <int D>
Real BoxSolid<D>::signedDistance(const Vec<D>& x) const {
  // q: how far x is beyond each pair of face planes (negative inside the slab).
  const Vec<D> q = (x - centre_).cwiseAbs() - half_;
  const Real outside = q.cwiseMax(0.0).norm();
  const Real inside = std::min(q.maxCoeff(), 0.0);
  return outside + inside;
}

template <int D>
int BoxSolid<D>::activeFace(const Vec<D>& x) const {
  const Vec<D> offset = x - centre_;
  int axis = 0;
  Real best = std::abs(offset[0]) - half_[0];
  for (int a = 1; a < D; ++a) {
    const Real q = std::abs(offset[a]) - half_[a];
    if (q > best) {
      best = q;
      axis = a;
    }
  }
  return 2 * axis + (offset[axis] >= 0 ? 1 : 0);
}

template <int D>
Vec<D> BoxSolid<D>::normal(const Vec<D>& x) const {
  const int face = activeFace(x);
  Vec<D> n = Vec<D>::Zero();
  n[face / 2] = face % 2 == 1 ? 1.0 : -1.0;
  return n;
}

template <int D>
Bounds<D> BoxSolid<D>::bounds() const {
  Bounds<D> b;
  b.lower = centre_ - half_;
  b.upper = centre_ + half_;
  return b;
}

template <int D>
std::string BoxSolid<D>::surfaceName(const Vec<D>& x) const {
  const int face = activeFace(x);
  const char axisLetter[] = {'x', 'y', 'z'};
  std::string surface(1, face % 2 == 1 ? '+' : '-');
  surface += axisLetter[face / 2];
  return qualifiedSurfaceName(name_, surface);
}

template class BoxSolid<2>;
template class BoxSolid<3>;

}  // namespace mfwave
