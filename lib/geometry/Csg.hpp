#pragma once
// Constructive solid geometry: the union, intersection and difference of any solids, themselves
// solids, so they nest. The signed distance is the min (union) or max (intersection; difference
// as A intersected with the complement of B) of the operands': exact on the surface, of the right
// sign, and never larger in magnitude than the true distance, which is what a fill needs (Solid.hpp).
// Normals and surface names come from the operand whose distance is the one taken (the active
// surface); a subtracted operand's normal is reversed, its names kept ("hole.surface").

#include "geometry/Solid.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfwave {

template <int D>
using SolidPtr = std::shared_ptr<const Solid<D>>;

// Points in any of the operands.
template <int D>
class SolidUnion final : public Solid<D> {
 public:
  // Throws InputError("union") for no operands or a null one.
  explicit SolidUnion(std::vector<SolidPtr<D>> operands);
  Real signedDistance(const Vec<D>& x) const override;
  Vec<D> normal(const Vec<D>& x) const override;
  Bounds<D> bounds() const override;
  std::string surfaceName(const Vec<D>& x) const override;

 private:
  const Solid<D>& active(const Vec<D>& x) const;
  std::vector<SolidPtr<D>> operands_;
};

// Points in every operand.
template <int D>
class SolidIntersection final : public Solid<D> {
 public:
  // Throws InputError("intersection") for no operands or a null one.
  explicit SolidIntersection(std::vector<SolidPtr<D>> operands);
  Real signedDistance(const Vec<D>& x) const override;
  Vec<D> normal(const Vec<D>& x) const override;
  Bounds<D> bounds() const override;
  std::string surfaceName(const Vec<D>& x) const override;

 private:
  const Solid<D>& active(const Vec<D>& x) const;
  std::vector<SolidPtr<D>> operands_;
};

// Points of `kept` not in `removed`.
template <int D>
class SolidDifference final : public Solid<D> {
 public:
  // Throws InputError("difference") for a null operand.
  SolidDifference(SolidPtr<D> kept, SolidPtr<D> removed);
  Real signedDistance(const Vec<D>& x) const override;
  Vec<D> normal(const Vec<D>& x) const override;
  Bounds<D> bounds() const override { return kept_->bounds(); }
  std::string surfaceName(const Vec<D>& x) const override;

 private:
  // The removed operand's surface is the active one at x.
  bool removedActive(const Vec<D>& x) const;
  SolidPtr<D> kept_;
  SolidPtr<D> removed_;
};

// Shorthands for two operands.
template <int D>
SolidPtr<D> unite(SolidPtr<D> a, SolidPtr<D> b) {
  return std::make_shared<SolidUnion<D>>(std::vector<SolidPtr<D>>{std::move(a), std::move(b)});
}
template <int D>
SolidPtr<D> intersect(SolidPtr<D> a, SolidPtr<D> b) {
  return std::make_shared<SolidIntersection<D>>(std::vector<SolidPtr<D>>{std::move(a), std::move(b)});
}
template <int D>
SolidPtr<D> subtract(SolidPtr<D> kept, SolidPtr<D> removed) {
  return std::make_shared<SolidDifference<D>>(std::move(kept), std::move(removed));
}

}  // namespace mfwave
