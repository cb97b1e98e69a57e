#pragma once
// The half-space on the inner side of a plane (a line in 2-D): the points x with
// (x - point) . normal <= 0, the normal pointing out of the solid in any direction. Its bounds are
// infinite; intersect it with a bounded solid (a box) to fill it. Its one surface is "plane".

#include "geometry/Solid.hpp"

#include <string>

namespace mfwave {

template <int D>
class HalfSpace final : public Solid<D> {
 public:
  // The normal need not be unit; throws InputError("<name or half_space>.normal") when it is zero
  // or not finite, ".point" when the point is not finite.
  HalfSpace(const Vec<D>& point, const Vec<D>& outwardNormal, const std::string& name = "");

  Real signedDistance(const Vec<D>& x) const override { return (x - point_).dot(normal_); }
  Vec<D> normal(const Vec<D>&) const override { return normal_; }
  Bounds<D> bounds() const override { return Bounds<D>::everywhere(); }
  std::string surfaceName(const Vec<D>& x) const override;

 private:
  Vec<D> point_;
  Vec<D> normal_;  // unit
  std::string name_;
};

}  // namespace mfwave
