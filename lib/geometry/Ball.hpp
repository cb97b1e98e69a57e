#pragma once
// A ball (a disc in 2-D) of a centre and a radius. Its one surface is "surface".

#include "geometry/Solid.hpp"

#include <string>

namespace mfwave {

template <int D>
class Ball final : public Solid<D> {
 public:
  // Throws InputError("<name or ball>.radius") unless the radius is positive and finite,
  // ".centre" when the centre is not finite.
  Ball(const Vec<D>& centre, Real radius, const std::string& name = "");

  Real signedDistance(const Vec<D>& x) const override { return (x - centre_).norm() - radius_; }
  // Radial; at the centre, where every direction is as near, +x.
  Vec<D> normal(const Vec<D>& x) const override;
  Bounds<D> bounds() const override;
  std::string surfaceName(const Vec<D>& x) const override;

 private:
  Vec<D> centre_;
  Real radius_;
  std::string name_;
};

}  // namespace mfwave
