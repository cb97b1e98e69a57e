#pragma once
// An annulus (a spherical shell in 3-D): the points between an inner and an outer radius about a
// centre. Its surfaces are "outer" and "inner". The colliding rings are two of them.

#include "geometry/Solid.hpp"

#include <string>

namespace mfwave {

template <int D>
class Annulus final : public Solid<D> {
 public:
  // Throws InputError("<name or annulus>.inner_radius") unless 0 < inner < outer (finite),
  // ".centre" when the centre is not finite.
  Annulus(const Vec<D>& centre, Real innerRadius, Real outerRadius, const std::string& name = "");

  Real signedDistance(const Vec<D>& x) const override;
  // Radial, outward through the outer surface and inward (towards the centre) through the inner.
  Vec<D> normal(const Vec<D>& x) const override;
  Bounds<D> bounds() const override;
  std::string surfaceName(const Vec<D>& x) const override;

  const Vec<D>& centre() const { return centre_; }
  Real innerRadius() const { return inner_; }
  Real outerRadius() const { return outer_; }

 private:
  // Whether the outer surface is the nearer.
  bool outerNearer(const Vec<D>& x) const;
  Vec<D> centre_;
  Real inner_, outer_;
  std::string name_;
};

}  // namespace mfwave
