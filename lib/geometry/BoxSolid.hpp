#pragma once
// An axis-aligned box [lower, upper] (a rectangle in 2-D). Its faces are named by the axis and the
// side their outward normal points to: "-x", "+x", "-y", "+y" and, in 3-D, "-z", "+z".

#include "geometry/Solid.hpp"

#include <string>

namespace mfwave {

template <int D>
class BoxSolid final : public Solid<D> {
 public:
  // Throws InputError("<name or box>.upper") unless lower < upper on every axis and both are finite.
  BoxSolid(const Vec<D>& lower, const Vec<D>& upper, const std::string& name = "");

  Real signedDistance(const Vec<D>& x) const override;
  Vec<D> normal(const Vec<D>& x) const override;
  Bounds<D> bounds() const override;
  std::string surfaceName(const Vec<D>& x) const override;

  const std::string& name() const { return name_; }

 private:
  // The face whose plane is farthest out from x (nearest from inside): 2 * axis + (0 low, 1 high).
  int activeFace(const Vec<D>& x) const;

  Vec<D> centre_;
  Vec<D> half_;
  std::string name_;
};

}  // namespace mfwave
