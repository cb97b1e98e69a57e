#include "systems/SecondOrderAsFirstOrder.hpp"

#include "core/Error.hpp"

namespace mfwave {

SecondOrderAsFirstOrder::SecondOrderAsFirstOrder(SecondOrderSystem& system) : system_(system) {}

void SecondOrderAsFirstOrder::rhs(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) {
  const Index n = system_.size();
  // u, v and a are views into y and ydot: no copies.
  system_.acceleration(t, y.head(n), y.tail(n), ydot.tail(n));
  ydot.head(n) = y.tail(n);
}

std::optional<VectorDistribution> SecondOrderAsFirstOrder::distribution() const {
  std::optional<VectorDistribution> d = system_.distribution();
  if (!d) return d;
  d->globalSize *= 2;
  // y = (u, v), each in the system's layout: the u part's sum, then the v part's.
  if (auto half = d->orderedSumOfSquares)
    d->orderedSumOfSquares = [half](const Real* z, Index count) { return half(z, count / 2) + half(z + count / 2, count / 2); };
  return d;
}

Vector SecondOrderAsFirstOrder::pack(const Vector& u, const Vector& v) const {
  const Index n = system_.size();
  if (u.size() != n || v.size() != n) throw InputError("state", "u and v must both have the system's size");
  Vector y(2 * n);
  y << u, v;
  return y;
}

void SecondOrderAsFirstOrder::unpack(const Vector& y, Vector& u, Vector& v) const {
  const Index n = system_.size();
  u = y.head(n);
  v = y.tail(n);
}

}  // namespace mfwave
