#pragma once
// Small first-order systems for the tests of the first-order integrators. All are split
// (SplitFirstOrderSystem, y = [q; p]) so every integrator, the leapfrog included, runs on them;
// each counts its configuration and momentum evaluations.

#include "core/Types.hpp"
#include "systems/SplitFirstOrderSystem.hpp"

#include <cmath>

namespace mfwave::test {

class CountingSplitSystem : public SplitFirstOrderSystem {
 public:
  long configurationCalls = 0;
  long momentumCalls = 0;
};

// x'' + 2 zeta w x' + w^2 x = 0 as q = x, p = v: Q = p, P = -w^2 q - 2 zeta w p.
class SplitOscillator : public CountingSplitSystem {
 public:
  SplitOscillator(Real w, Real zeta) : w_(w), zeta_(zeta) {}
  Index size() const override { return 2; }
  Index configurationSize() const override { return 1; }
  void configurationRate(Real, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> qdot) override {
    ++configurationCalls;
    qdot[0] = y[1];
  }
  void momentumRate(Real, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> pdot) override {
    ++momentumCalls;
    pdot[0] = -w_ * w_ * y[0] - 2 * zeta_ * w_ * y[1];
  }
  // Exact [x; v] at t from x(0) = 1, v(0) = 0 (0 <= zeta < 1).
  Vector exact(Real t) const {
    const Real wd = w_ * std::sqrt(1 - zeta_ * zeta_);
    const Real decay = std::exp(-zeta_ * w_ * t);
    Vector y(2);
    y << decay * (std::cos(wd * t) + zeta_ * w_ / wd * std::sin(wd * t)), -decay * (w_ * w_ / wd) * std::sin(wd * t);
    return y;
  }
  // (1/2) v^2 + (1/2) w^2 x^2.
  Real energy(const Vector& y) const { return 0.5 * y[1] * y[1] + 0.5 * w_ * w_ * y[0] * y[0]; }

 private:
  Real w_, zeta_;
};

// A forced pendulum with a time-dependent drift, nonlinear and explicitly time-dependent in both
// parts: q' = p + a cos(2t), p' = -sin q + b cos(1.3 t).
class ForcedPendulum : public CountingSplitSystem {
 public:
  ForcedPendulum(Real a, Real b) : a_(a), b_(b) {}
  Index size() const override { return 2; }
  Index configurationSize() const override { return 1; }
  void configurationRate(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> qdot) override {
    ++configurationCalls;
    qdot[0] = y[1] + a_ * std::cos(2 * t);
  }
  void momentumRate(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> pdot) override {
    ++momentumCalls;
    pdot[0] = -std::sin(y[0]) + b_ * std::cos(1.3 * t);
  }

 private:
  Real a_, b_;
};

// A configuration rate that depends on the configuration itself (as the density rate -rho div v
// and the Jaumann terms of a stress rate do): q' = p - c q^2, p' = -q.
class SelfCoupledDrift : public CountingSplitSystem {
 public:
  explicit SelfCoupledDrift(Real c) : c_(c) {}
  Index size() const override { return 2; }
  Index configurationSize() const override { return 1; }
  void configurationRate(Real, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> qdot) override {
    ++configurationCalls;
    qdot[0] = y[1] - c_ * y[0] * y[0];
  }
  void momentumRate(Real, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> pdot) override {
    ++momentumCalls;
    pdot[0] = -y[0];
  }

 private:
  Real c_;
};

// The undamped oscillator as a plain (unsplit) FirstOrderSystem.
class PlainOscillator : public FirstOrderSystem {
 public:
  explicit PlainOscillator(Real w) : w_(w) {}
  Index size() const override { return 2; }
  void rhs(Real, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) override {
    ydot[0] = y[1];
    ydot[1] = -w_ * w_ * y[0];
  }

 private:
  Real w_;
};

inline Vector vector2(Real a, Real b) {
  Vector y(2);
  y << a, b;
  return y;
}

}  // namespace mfwave::test
