#pragma once
// The axis-aligned box a solid fits in. A particle fill walks the lattice cells inside it, so it
// must be finite by then; a half-space alone has infinite bounds and becomes finite by CSG with a
// bounded solid (an intersection takes the smaller box).

#include "core/Types.hpp"

#include <limits>

namespace mfwave {

template <int D>
struct Bounds {
  Vec<D> lower = Vec<D>::Constant(std::numeric_limits<Real>::infinity());
  Vec<D> upper = Vec<D>::Constant(-std::numeric_limits<Real>::infinity());

  // Every point of space (what a half-space reports).
  static Bounds everywhere() {
    Bounds b;
    b.lower = Vec<D>::Constant(-std::numeric_limits<Real>::infinity());
    b.upper = Vec<D>::Constant(std::numeric_limits<Real>::infinity());
    return b;
  }
  bool finite() const { return lower.allFinite() && upper.allFinite(); }
  bool empty() const { return (upper.array() < lower.array()).any(); }
  bool contains(const Vec<D>& x) const {
    return (x.array() >= lower.array()).all() && (x.array() <= upper.array()).all();
  }
};

// The smallest box holding both.
template <int D>
Bounds<D> hull(const Bounds<D>& a, const Bounds<D>& b) {
  Bounds<D> h;
  h.lower = a.lower.cwiseMin(b.lower);
  h.upper = a.upper.cwiseMax(b.upper);
  return h;
}

// The part both share (empty() when they do not meet).
template <int D>
Bounds<D> overlap(const Bounds<D>& a, const Bounds<D>& b) {
  Bounds<D> h;
  h.lower = a.lower.cwiseMax(b.lower);
  h.upper = a.upper.cwiseMin(b.upper);
  return h;
}

}  // namespace mfwave
