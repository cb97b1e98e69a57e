#include "systems/SecondOrderAsFirstOrder.hpp"

#include "core/Error.hpp"

namespace mfwave {

SecondOrderAsFirstOrder::SecondOrderAsFirstOrder(SecondOrderSystem& system) : system_(system) {
  const Index n = system_.size();
  u_.resize(n);
  v_.resize(n);
  a_.resize(n);
}

void SecondOrderAsFirstOrder::rhs(Real t, const Vector& y, Vector& ydot) {
  ydot.resize(2 * system_.size());
  rhsView(t, y, ydot);
}

void SecondOrderAsFirstOrder::rhsView(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) {
  const Index n = system_.size();
  // The copies keep the SecondOrderSystem interface on whole vectors; they cost two streams of
  // memory per evaluation, small beside any spatial operator.
  u_ = y.head(n);
  v_ = y.tail(n);
  system_.acceleration(t, u_, v_, a_);
  ydot.head(n) = v_;
  ydot.tail(n) = a_;
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
