// Clamped particles, prescribed velocities and tractions: their rates and their entries in the
// energy ledger (load work = traction power + body-force power + constraint-reaction power).

#include "UlsphTestSupport.hpp"

#include "methods/updated_lagrangian_sph/HistoryRate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace mfwave;

namespace {

struct Block {
  ParticleSet<2> set = makeLattice<2>(Vec2::Zero(), Vec2::Ones(), 0.1);
  UpdatedLagrangianSphOptions options() const {
    UpdatedLagrangianSphOptions o;
    o.bodyForce = {0.3, -1.0, 0.0};
    o.viscosity.alpha = 0.5;
    return o;
  }
  UpdatedLagrangianSph<2> system{set, options()};
};

}  // namespace

TEST(UlsphConstraints, RatesOfClampedPrescribedAndLoadedParticles) {
  Block block;
  UpdatedLagrangianSph<2>& system = block.system;
  const Index n = system.particleCount();  // 121
  const TimeFunction ramp = TimeFunction::ramp(0, 2.0, 3.0);  // slope 1.5
  system.fixParticles({0, 1});
  system.prescribeVelocity({5, 6}, Vec2(0.2, -0.1), ramp);
  system.addTraction({120, 119}, Vec2(0.0, 4.0), TimeFunction::constant(0.5), 0.1);  // force (0, 0.2)
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(-1, 1);
  Vector v(2 * n);
  for (Index k = 0; k < 2 * n; ++k) v[k] = 0.05 * u(rng);
  Vector y = system.initialState(v);
  const auto& layout = system.layout();
  const Real t = 0.5;
  // The integrated prescribed velocity at t: velocity * history(t).
  for (Index i : {5, 6}) {
    y[layout.velocity(i, 0)] = 0.2 * ramp(t);
    y[layout.velocity(i, 1)] = -0.1 * ramp(t);
  }
  Vector ydot(system.size());
  system.rhs(t, y, ydot);

  for (Index i : {0, 1}) {
    for (int a = 0; a < 2; ++a) {
      EXPECT_EQ(y[layout.velocity(i, a)], 0.0);
      EXPECT_EQ(ydot[layout.position(i, a)], 0.0);
      EXPECT_EQ(ydot[layout.velocity(i, a)], 0.0);
    }
  }
  for (Index i : {5, 6}) {
    EXPECT_NEAR(ydot[layout.velocity(i, 0)], 0.2 * 1.5, 1e-15);
    EXPECT_NEAR(ydot[layout.velocity(i, 1)], -0.1 * 1.5, 1e-15);
    EXPECT_EQ(ydot[layout.position(i, 0)], y[layout.velocity(i, 0)]);
  }

  // A traction adds force / m to the acceleration of its particles: compare with the same state
  // without the traction.
  Block plain;
  plain.system.fixParticles({0, 1});
  plain.system.prescribeVelocity({5, 6}, Vec2(0.2, -0.1), ramp);
  Vector plainRate(system.size());
  plain.system.rhs(t, y, plainRate);
  const Real m = system.masses()[120];
  EXPECT_NEAR(ydot[layout.velocity(120, 1)] - plainRate[layout.velocity(120, 1)], 0.2 / m, 1e-12);
  EXPECT_NEAR(ydot[layout.velocity(120, 0)] - plainRate[layout.velocity(120, 0)], 0.0, 1e-12);

  // Load work rate: traction power + body-force power + reaction power m (a_prescribed - a_free).v.
  Real expected = 0.2 * (y[layout.velocity(120, 1)] + y[layout.velocity(119, 1)]);
  const Vec2 g(0.3, -1.0);
  for (Index i = 0; i < n; ++i) {
    const Real mi = system.masses()[static_cast<std::size_t>(i)];
    expected += mi * g.dot(Vec2(y[layout.velocity(i, 0)], y[layout.velocity(i, 1)]));
  }
  // The free accelerations of the constrained particles, from a system without constraints.
  Block free;
  free.system.addTraction({120, 119}, Vec2(0.0, 4.0), TimeFunction::constant(0.5), 0.1);
  Vector freeRate(system.size());
  free.system.rhs(t, y, freeRate);
  for (Index i : {0, 1, 5, 6}) {
    const Real mi = system.masses()[static_cast<std::size_t>(i)];
    for (int a = 0; a < 2; ++a)
      expected += mi * (ydot[layout.velocity(i, a)] - freeRate[layout.velocity(i, a)]) * y[layout.velocity(i, a)];
  }
  const auto loadWork = layout.ledger(UpdatedLagrangianSphLayout<2>::LoadWork);
  EXPECT_NEAR(ydot[loadWork], expected, 1e-12 * std::abs(expected) + 1e-15);
  EXPECT_GT(std::abs(expected), 1e-3);
}

TEST(UlsphConstraints, HistoryRateIsTheRightHandSlope) {
  const TimeFunction ramp = TimeFunction::ramp(1.0, 2.0, 4.0);
  EXPECT_EQ(historyRate(ramp, 0.5), 0.0);
  EXPECT_EQ(historyRate(ramp, 1.0), 2.0);  // the piece that starts at t
  EXPECT_EQ(historyRate(ramp, 2.0), 2.0);
  EXPECT_EQ(historyRate(ramp, 3.0), 0.0);
  EXPECT_EQ(historyRate(TimeFunction::constant(3), 1.0), 0.0);
  const TimeFunction ricker = TimeFunction::ricker(2.0, 0.5, 1.0);
  // d/dt (1 - 2a) exp(-a), a = (pi f (t - d))^2: exp(-a) a' (2a - 3), a' = 2 (pi f)^2 (t - d).
  const Real t = 0.6, pf = M_PI * 2.0, a = std::pow(pf * (t - 0.5), 2);
  const Real exact = std::exp(-a) * 2 * pf * pf * (t - 0.5) * (2 * a - 3);
  EXPECT_NEAR(historyRate(ricker, t), exact, 1e-7 * std::abs(exact));
}

TEST(UlsphConstraints, ClampedBarEndHoldsAndPrescribedEndMoves) {
  // A 1-D bar, left end clamped, right end pulled at 1e-3: after a short run the clamped particle
  // has not moved and the prescribed one has moved by exactly v t.
  ParticleSet<1> set = makeLine(0, 1, 0.02);
  UpdatedLagrangianSph<1> system(set, {});
  const Index last = system.particleCount() - 1;
  system.fixParticles({0});
  system.prescribeVelocity({last}, Vec1(1e-3), TimeFunction::constant(1));
  test::LocalLeapfrog stepper(system, system.initialState());
  const Real dt = system.stableStep(stepper.state());
  for (int k = 0; k < 100; ++k) stepper.step(dt);
  const auto& layout = system.layout();
  EXPECT_EQ(stepper.state()[layout.position(0, 0)], 0.0);
  EXPECT_NEAR(stepper.state()[layout.position(last, 0)], 1.0 + 1e-3 * stepper.time(), 1e-14);
  EXPECT_GT(system.stress(stepper.state(), last - 1)(0, 0), 0.0);  // pulled: tension near the end
}
