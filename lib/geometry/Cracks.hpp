#pragma once
// The cracks of a body, asked together: two particles see each other unless the segment between
// them crosses any crack. Each crack's box rejects the far pairs before the exact test.

#include "geometry/Crack.hpp"

#include <vector>

namespace mfwave {

template <int D>
class Cracks {
 public:
  void add(const Crack<D>& crack) { cracks_.push_back(crack); }
  std::size_t size() const { return cracks_.size(); }
  bool empty() const { return cracks_.empty(); }
  const Crack<D>& operator[](std::size_t i) const { return cracks_[i]; }

  // No crack separates a from b.
  bool visible(const Vec<D>& a, const Vec<D>& b) const {
    const Vec<D> low = a.cwiseMin(b), high = a.cwiseMax(b);
    for (const Crack<D>& crack : cracks_) {
      const Bounds<D>& box = crack.bounds();
      if ((high.array() < box.lower.array()).any() || (low.array() > box.upper.array()).any()) continue;
      if (crack.crosses(a, b)) return false;
    }
    return true;
  }

 private:
  std::vector<Crack<D>> cracks_;
};

}  // namespace mfwave
