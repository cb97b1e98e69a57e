#include "geometry/Csg.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <string>
#include <utility>

namespace mfwave {
namespace {

template <int D>
void checkCsgOperands(const std::vector<SolidPtr<D>>& operands, const char* key) {
  if (operands.empty()) throw InputError(key, "needs at least one solid");
  for (std::size_t i = 0; i < operands.size(); ++i)
    if (!operands[i]) throw InputError(key, "solid " + std::to_string(i) + " is missing (null)");
}

// The operand whose signed distance at x is the smallest (a union's) or the largest (an
// intersection's), and that distance: the combination's distance and its active surface at once.
template <int D>
std::pair<const Solid<D>*, Real> extremeOperand(const std::vector<SolidPtr<D>>& operands, const Vec<D>& x,
                                                bool largest) {
  const Solid<D>* best = operands.front().get();
  Real bestDistance = best->signedDistance(x);
  for (std::size_t i = 1; i < operands.size(); ++i) {
    const Real d = operands[i]->signedDistance(x);
    if (largest ? d > bestDistance : d < bestDistance) {
      bestDistance = d;
      best = operands[i].get();
    }
  }
  return {best, bestDistance};
}

}  // namespace

template <int D>
SolidUnion<D>::SolidUnion(std::vector<SolidPtr<D>> operands) : operands_(std::move(operands)) {
  checkCsgOperands(operands_, "union");
}

template <int D>
const Solid<D>& SolidUnion<D>::active(const Vec<D>& x) const {
  return *extremeOperand<D>(operands_, x, false).first;
}

template <int D>
Real SolidUnion<D>::signedDistance(const Vec<D>& x) const {
  return extremeOperand<D>(operands_, x, false).second;
}

template <int D>
Vec<D> SolidUnion<D>::normal(const Vec<D>& x) const {
  return active(x).normal(x);
}

template <int D>
Bounds<D> SolidUnion<D>::bounds() const {
  Bounds<D> b = operands_.front()->bounds();
  for (std::size_t i = 1; i < operands_.size(); ++i) b = hull(b, operands_[i]->bounds());
  return b;
}

template <int D>
std::string SolidUnion<D>::surfaceName(const Vec<D>& x) const {
  return active(x).surfaceName(x);
}

template <int D>
SolidIntersection<D>::SolidIntersection(std::vector<SolidPtr<D>> operands) : operands_(std::move(operands)) {
  checkCsgOperands(operands_, "intersection");
}

template <int D>
const Solid<D>& SolidIntersection<D>::active(const Vec<D>& x) const {
  return *extremeOperand<D>(operands_, x, true).first;
}

template <int D>
Real SolidIntersection<D>::signedDistance(const Vec<D>& x) const {
  return extremeOperand<D>(operands_, x, true).second;
}

template <int D>
Vec<D> SolidIntersection<D>::normal(const Vec<D>& x) const {
  return active(x).normal(x);
}

template <int D>
Bounds<D> SolidIntersection<D>::bounds() const {
  Bounds<D> b = operands_.front()->bounds();
  for (std::size_t i = 1; i < operands_.size(); ++i) b = overlap(b, operands_[i]->bounds());
  return b;
}

template <int D>
std::string SolidIntersection<D>::surfaceName(const Vec<D>& x) const {
  return active(x).surfaceName(x);
}

template <int D>
SolidDifference<D>::SolidDifference(SolidPtr<D> kept, SolidPtr<D> removed)
    : kept_(std::move(kept)), removed_(std::move(removed)) {
  if (!kept_) throw InputError("difference", "the solid to keep is missing (null)");
  if (!removed_) throw InputError("difference", "the solid to remove is missing (null)");
}

template <int D>
bool SolidDifference<D>::removedActive(const Vec<D>& x) const {
  return -removed_->signedDistance(x) > kept_->signedDistance(x);
}

template <int D>
Real SolidDifference<D>::signedDistance(const Vec<D>& x) const {
  return std::max(kept_->signedDistance(x), -removed_->signedDistance(x));
}

template <int D>
Vec<D> SolidDifference<D>::normal(const Vec<D>& x) const {
  if (removedActive(x)) return -removed_->normal(x);
  return kept_->normal(x);
}

template <int D>
std::string SolidDifference<D>::surfaceName(const Vec<D>& x) const {
  if (removedActive(x)) return removed_->surfaceName(x);
  return kept_->surfaceName(x);
}

template class SolidUnion<2>;
template class SolidUnion<3>;
template class SolidIntersection<2>;
template class SolidIntersection<3>;
template class SolidDifference<2>;
template class SolidDifference<3>;

}  // namespace mfwave
