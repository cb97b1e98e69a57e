// Central difference's two hooks: the velocity filter (conservative smoothing, Ding-Long-Wu
// eq. 33) and prescribed displacements (Ding-Long-Wu eq. 30).

#include "TestSystems.hpp"
#include "core/Error.hpp"
#include "integrators/ArkodeSecondOrder.hpp"
#include "integrators/CentralDifference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace mfwave;

namespace {

using Damping = CentralDifference::Damping;

std::unique_ptr<LinearSecondOrderSystem> freeParticle() {
  return std::make_unique<LinearSecondOrderSystem>(test::scalarMatrix(1), SparseMatrix(), SparseMatrix(1, 1));
}

// ---- velocity filter ----

TEST(CentralDifferenceVelocityFilter, ZeroingTheVelocityFreezesTheState) {
  for (Real zeta : {0.0, 0.3}) {  // plain and implicit-damping paths
    auto system = test::oscillator(2.0, zeta);
    CentralDifference integrator;
    integrator.setVelocityFilter([](Real, Vector& v) { v.setZero(); });
    const Real dt = 0.05;
    integrator.initialise(*system, 0, Vector::Constant(1, 0.8), Vector::Constant(1, 1.5), dt);
    integrator.step();
    // u never moves; the synchronous velocity is the filtered v_{n-1/2} = 0 plus the half kick
    // dt/2 a_n of the frozen u, the same at every step.
    const Real frozenVelocity = integrator.state().velocity[0];
    for (int i = 0; i < 100; ++i) {
      integrator.step();
      ASSERT_EQ(integrator.state().displacement[0], 0.8);
      ASSERT_EQ(integrator.state().velocity[0], frozenVelocity);
      ASSERT_EQ(integrator.staggeredVelocity()[0], 0.0);
    }
    // v_n = dt/2 a_n with M a_n + C v_n = -K u: a = -w^2 u / (1 + zeta w dt)
    const Real w = 2.0, a = -w * w * 0.8 / (1 + zeta * w * dt);
    EXPECT_NEAR(frozenVelocity, 0.5 * dt * a, 1e-15);
  }
}

TEST(CentralDifferenceVelocityFilter, GeometricDecayOfAFreeParticle) {
  // v <- (1 - g dt) v on a = 0: v_n = v0 q^n and u_n = u0 + dt v0 (q + ... + q^n), q = 1 - g dt.
  auto system = freeParticle();
  const Real g = 3, dt = 0.01, u0 = 0.25, v0 = 2, q = 1 - g * dt;
  CentralDifference integrator;
  integrator.setVelocityFilter([g](Real step, Vector& v) { v *= 1 - g * step; });
  integrator.initialise(*system, 0, Vector::Constant(1, u0), Vector::Constant(1, v0), dt);
  for (int n = 1; n <= 300; ++n) {
    integrator.step();
    const Real qn = std::pow(q, n);
    ASSERT_NEAR(integrator.state().velocity[0], v0 * qn, 1e-13 * v0) << "step " << n;
    ASSERT_NEAR(integrator.state().displacement[0], u0 + dt * v0 * q * (1 - qn) / (1 - q), 1e-13) << "step " << n;
  }
}

TEST(CentralDifferenceVelocityFilter, MustKeepTheSize) {
  auto system = freeParticle();
  CentralDifference integrator;
  integrator.setVelocityFilter([](Real, Vector& v) { v.resize(2); });
  integrator.initialise(*system, 0, Vector::Zero(1), Vector::Zero(1), 0.1);
  try {
    integrator.step();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "velocity_filter");
  }
}

// ---- prescribed displacements ----

constexpr Real kDrive = 1.3;  // between the 5th and 6th modes (1.22, 1.41) of the 11 free masses: no resonance
constexpr Real kAmplitude = 0.2;

// A chain of unit masses and unit springs between a wall and mass 0, mass 0 driven with
// g(t) = A sin(w t), optionally with Rayleigh-type dashpots C = c K (coupling each mass to its
// neighbours, the driven one included).
std::unique_ptr<LinearSecondOrderSystem> drivenChain(int n, Real c) {
  auto chain = test::springChain(n);
  const SparseMatrix damping = c > 0 ? SparseMatrix(c * chain->stiffness()) : SparseMatrix();
  return std::make_unique<LinearSecondOrderSystem>(chain->mass(), damping, chain->stiffness());
}

void drive(Real t, Vector& values) { values[0] = kAmplitude * std::sin(kDrive * t); }

// The reference: the free masses 1..n-1 alone, loaded by the driven one through the spring and
// the dashpot, u_f'' + C_ff u_f' + K_ff u_f = -K_f0 g(t) - C_f0 g'(t), integrated by ARKODE's RK4
// with a step small enough (1e-3, error ~1e-12) to be exact here.
Vector referenceAt(int n, Real c, Real endTime) {
  const auto full = drivenChain(n, c);
  const SparseMatrix k = full->stiffness().bottomRightCorner(n - 1, n - 1);
  const SparseMatrix damping = c > 0 ? SparseMatrix(c * k) : SparseMatrix();
  SparseMatrix mass(n - 1, n - 1);
  mass.setIdentity();
  // only mass 1 touches mass 0: K_10 = -1, C_10 = -c
  LinearSecondOrderSystem reduced(mass, damping, k, [c](Real t, Vector& f) {
    f[0] = kAmplitude * (std::sin(kDrive * t) + c * kDrive * std::cos(kDrive * t));
  });
  ArkodeOptions options;
  options.fixedStep = 1e-3;
  ArkodeSecondOrder rk4(options);
  rk4.initialise(reduced, 0, Vector::Zero(n - 1), Vector::Zero(n - 1), options.fixedStep);
  rk4.advanceTo(endTime);
  Vector both(2 * (n - 1));
  both << rk4.state().displacement, rk4.state().velocity;
  return both;
}

struct DrivenRun {
  Real errorU, errorV;
};

DrivenRun drivenRunError(int n, Real c, Real endTime, int steps, const Vector& reference) {
  auto system = drivenChain(n, c);
  CentralDifference integrator;
  integrator.setPrescribedDisplacement({0}, drive);
  Vector v0 = Vector::Zero(n);
  v0[0] = kAmplitude * kDrive;  // g'(0)
  const Real dt = endTime / steps;
  integrator.initialise(*system, 0, Vector::Zero(n), v0, dt);
  EXPECT_EQ(integrator.implicitDamping(), c > 0);
  Vector g(1);
  for (int i = 1; i <= steps; ++i) {
    integrator.step();
    drive(integrator.time(), g);
    EXPECT_EQ(integrator.state().displacement[0], g[0]);  // follows g exactly
  }
  // the reported velocity of the driven mass: second order in dt
  EXPECT_NEAR(integrator.state().velocity[0], kAmplitude * kDrive * std::cos(kDrive * endTime), 0.2 * dt * dt);
  const auto s = integrator.state();
  return {(s.displacement.tail(n - 1) - reference.head(n - 1)).lpNorm<Eigen::Infinity>(),
          (s.velocity.tail(n - 1) - reference.tail(n - 1)).lpNorm<Eigen::Infinity>()};
}

void expectSecondOrderDrivenChain(Real c, const char* label) {
  const int n = 12;
  const Real endTime = 8;
  const Vector reference = referenceAt(n, c, endTime);
  std::vector<DrivenRun> runs;
  for (int steps : {400, 800, 1600, 3200}) runs.push_back(drivenRunError(n, c, endTime, steps, reference));
  const auto& coarse = runs[runs.size() - 2];
  const auto& fine = runs.back();
  const Real orderU = std::log2(coarse.errorU / fine.errorU), orderV = std::log2(coarse.errorV / fine.errorV);
  std::printf("%s: errors u %.3e -> %.3e, v %.3e -> %.3e; orders u %.4f v %.4f\n", label, coarse.errorU, fine.errorU,
              coarse.errorV, fine.errorV, orderU, orderV);
  EXPECT_NEAR(orderU, 2.0, 0.05);
  EXPECT_NEAR(orderV, 2.0, 0.05);
}

TEST(CentralDifferencePrescribedDisplacement, DrivenChainIsSecondOrder) {
  expectSecondOrderDrivenChain(0, "driven chain");
}

TEST(CentralDifferencePrescribedDisplacement, DrivenChainWithImplicitCoupledDashpotsIsSecondOrder) {
  // C = 0.5 K couples the driven mass to its neighbour: its known acceleration enters the
  // neighbour's row of (M + dt/2 C) a = ... (eliminated, not just overwritten).
  expectSecondOrderDrivenChain(0.5, "driven chain, implicit dashpots C = 0.5 K");
}

TEST(CentralDifferencePrescribedDisplacement, ReportedVelocityAndAccelerationAreCentralDifferencesOfG) {
  auto system = drivenChain(5, 0.3);
  CentralDifference integrator;
  integrator.setPrescribedDisplacement({0, 4}, [](Real t, Vector& values) {
    values[0] = t * t * t;
    values[1] = 0;
  });
  const Real dt = 0.1;
  integrator.initialise(*system, 1, Vector::Unit(5, 0), Vector::Zero(5), dt);  // g(1) = 1
  for (int i = 0; i < 20; ++i) {
    integrator.step();
    const Real t = integrator.time();
    const Real gPrevious = std::pow(t - dt, 3), g = t * t * t, gNext = std::pow(t + dt, 3);
    EXPECT_NEAR(integrator.state().displacement[0], g, 0);
    EXPECT_NEAR(integrator.state().velocity[0], (gNext - gPrevious) / (2 * dt), 1e-12 * g);  // 3 t^2 + dt^2
    EXPECT_NEAR(integrator.acceleration()[0], (gNext - 2 * g + gPrevious) / (dt * dt), 1e-9 * g);  // 6 t
    EXPECT_EQ(integrator.state().displacement[4], 0.0);
    EXPECT_EQ(integrator.state().velocity[4], 0.0);
    EXPECT_EQ(integrator.acceleration()[4], 0.0);
  }
}

TEST(CentralDifferencePrescribedDisplacement, MisuseNamesTheKey) {
  auto system = drivenChain(4, 0);
  auto expectKey = [&](std::vector<Index> dofs, std::function<void(Real, Vector&)> g, const Vector& u0,
                       const std::string& key) {
    try {
      CentralDifference integrator;
      integrator.setPrescribedDisplacement(std::move(dofs), std::move(g));
      integrator.initialise(*system, 0, u0, Vector::Zero(4), 0.1);
      FAIL() << "expected " << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key) << e.what();
    }
  };
  auto zero = [](Real, Vector& values) { values.setZero(); };
  expectKey({4}, zero, Vector::Zero(4), "prescribed_displacement");       // out of range
  expectKey({-1}, zero, Vector::Zero(4), "prescribed_displacement");      // negative
  expectKey({1, 1}, zero, Vector::Zero(4), "prescribed_displacement");    // repeated
  expectKey({1}, {}, Vector::Zero(4), "prescribed_displacement");         // no g
  expectKey({1}, [](Real, Vector& values) { values.resize(3); }, Vector::Zero(4), "prescribed_displacement");
  expectKey({1}, zero, Vector::Unit(4, 1), "initial_displacement");       // u0 != g(t0)
  CentralDifference integrator;
  integrator.initialise(*system, 0, Vector::Zero(4), Vector::Zero(4), 0.1);
  try {
    integrator.setPrescribedDisplacement({0}, zero);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "prescribed_displacement");
  }
}

}  // namespace
