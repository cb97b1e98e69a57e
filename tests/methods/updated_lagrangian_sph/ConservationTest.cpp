// What the pair forms of Li eq. (29)-(30) conserve, on a free body (no constraints, no loads) with
// a disordered lattice, random velocities, stresses, densities and energies, and every artificial
// term on:
//  - linear momentum: every pair term is antisymmetric, so sum_i m_i dv_i/dt = 0 to round-off;
//  - energy: the energy equation is the exact counterpart of the momentum equation, so
//    d/dt (kinetic + internal) = sum m v.a + sum m de/dt = 0 to round-off;
//  - angular momentum: a pair force m_i m_j M_ij grad W_ij is central (parallel to x_ij) only when
//    M_ij is isotropic (pressure, Pi_ij). With the deviatoric stress or R_ij it is not, and
//    sum m x cross a is not zero: it vanishes only to the consistency error of the SPH sum
//    (exactly for uniform stress on a full lattice stencil). Measured below.

#include "UlsphTestSupport.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <random>
#include <tuple>
#include <utility>

using namespace mfwave;

namespace {

// Angular momentum rate |sum m x cross a| (z in 2-D, the vector in 3-D) and its scale
// sum m |x| |a|, with x measured from the centre of mass (the torque itself does not depend on the
// point when sum m a = 0).
template <int D>
std::pair<Real, Real> torque(const Vector& x, const Vector& a, const std::vector<Real>& m) {
  Vec3 centre = Vec3::Zero();
  Real mass = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    for (int d = 0; d < D; ++d) centre[d] += m[i] * x[static_cast<Index>(i) * D + d];
    mass += m[i];
  }
  centre /= mass;
  Vec3 total = Vec3::Zero();
  Real scale = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    Vec3 xi = Vec3::Zero(), ai = Vec3::Zero();
    for (int d = 0; d < D; ++d) {
      xi[d] = x[static_cast<Index>(i) * D + d] - centre[d];
      ai[d] = a[static_cast<Index>(i) * D + d];
    }
    total += m[i] * xi.cross(ai);
    scale += m[i] * xi.norm() * ai.norm();
  }
  return {total.norm(), scale};
}

template <int D>
struct RandomBody {
  ParticleSet<D> particles;
  UpdatedLagrangianSph<D> system;
  Vector y;

  static ParticleSet<D> jittered(Real dp, std::mt19937& rng) {
    ParticleSet<D> set = makeLattice<D>(Vec<D>::Zero(), Vec<D>::Ones(), dp);
    std::uniform_real_distribution<Real> u(-0.15 * dp, 0.15 * dp);
    for (Index i = 0; i < set.size(); ++i) {
      Vec<D> x = set.position(i);
      for (int a = 0; a < D; ++a) x[a] += u(rng);
      set.setPosition(i, x);
    }
    return set;
  }

  static UpdatedLagrangianSphOptions options(bool artificialStress, bool corrected) {
    UpdatedLagrangianSphOptions o;
    o.kernelGradientCorrection = corrected;
    o.material = Material::fromLame(2.0, 1.0, 1.5);
    o.gamma = 1.4;
    o.viscosity.alpha = 1.0;
    o.viscosity.beta = 2.0;
    o.artificialStress.enabled = artificialStress;
    return o;
  }

  RandomBody(Real dp, bool deviatoric, bool artificialStress, unsigned seed, bool corrected = false)
      : particles([&] {
          std::mt19937 rng(seed);
          return jittered(dp, rng);
        }()),
        system(particles, options(artificialStress, corrected)) {
    std::mt19937 rng(seed + 1);
    std::uniform_real_distribution<Real> u(-1, 1);
    const Index n = system.particleCount();
    Vector v(n * D);
    for (Index k = 0; k < v.size(); ++k) v[k] = 0.1 * u(rng);
    y = system.initialState(v);
    const auto& layout = system.layout();
    for (Index i = 0; i < n; ++i) {
      y[layout.density(i)] *= 1 + 0.02 * u(rng);
      y[layout.energy(i)] = 0.05 * (1 + u(rng));
      if (deviatoric)
        for (int c = 0; c < Layout::stressComponents; ++c) y[layout.stress(i, c)] = 0.5 * u(rng);
    }
  }
  using Layout = UpdatedLagrangianSphLayout<D>;
};

struct Balance {
  Real momentum;      // |sum m a| / sum m |a|
  Real energy;        // |sum m v.a + sum m de/dt| / (sum m |v.a| + sum m |de/dt|)
  Real angular;       // |sum m x cross a| / sum m |x| |a|
  Real dissipation;   // ledger rate of the viscous dissipation
};

template <int D>
Balance balance(RandomBody<D>& body) {
  UpdatedLagrangianSph<D>& system = body.system;
  const auto& layout = system.layout();
  const Index n = system.particleCount();
  Vector ydot(system.size());
  system.rhs(0, body.y, ydot);
  Vector a(n * D), x(n * D);
  Vec<D> momentum = Vec<D>::Zero();
  Real momentumScale = 0, power = 0, powerScale = 0;
  for (Index i = 0; i < n; ++i) {
    const Real m = system.masses()[static_cast<std::size_t>(i)];
    Vec<D> ai, vi;
    for (int d = 0; d < D; ++d) {
      ai[d] = a[i * D + d] = ydot[layout.velocity(i, d)];
      x[i * D + d] = body.y[layout.position(i, d)];
      vi[d] = body.y[layout.velocity(i, d)];
    }
    momentum += m * ai;
    momentumScale += m * ai.norm();
    const Real de = ydot[layout.energy(i)];
    power += m * vi.dot(ai) + m * de;
    powerScale += m * std::abs(vi.dot(ai)) + m * std::abs(de);
  }
  const auto [t, tScale] = torque<D>(x, a, system.masses());
  return {momentum.norm() / momentumScale, std::abs(power) / powerScale, t / tScale,
          ydot[layout.ledger(UpdatedLagrangianSphLayout<D>::ViscousDissipation)]};
}

}  // namespace

TEST(UlsphConservation, PressureAndViscosityConserveMomentumAngularMomentumAndEnergy2d) {
  RandomBody<2> body(0.05, false, false, 11);
  const Balance b = balance(body);
  std::printf("2-D pressure only: momentum %.2e energy %.2e angular %.2e\n", b.momentum, b.energy, b.angular);
  EXPECT_LT(b.momentum, 1e-13);
  EXPECT_LT(b.energy, 1e-13);
  EXPECT_LT(b.angular, 1e-13);  // isotropic pair terms are central
  EXPECT_GT(b.dissipation, 0);
}

TEST(UlsphConservation, StressAndArtificialStressConserveMomentumAndEnergy2d) {
  RandomBody<2> body(0.05, true, true, 12);
  const Balance b = balance(body);
  std::printf("2-D random stress: momentum %.2e energy %.2e angular %.2e\n", b.momentum, b.energy, b.angular);
  EXPECT_LT(b.momentum, 1e-13);
  EXPECT_LT(b.energy, 1e-13);
  EXPECT_GT(b.dissipation, 0);
  // Non-central pair forces: a torque well above round-off (measured below), small against the forces.
  EXPECT_GT(b.angular, 1e-8);
  EXPECT_LT(b.angular, 1e-2);
}

TEST(UlsphConservation, StressAndArtificialStressConserveMomentumAndEnergy3d) {
  RandomBody<3> body(0.125, true, true, 13);
  const Balance b = balance(body);
  std::printf("3-D random stress: momentum %.2e energy %.2e angular %.2e\n", b.momentum, b.energy, b.angular);
  EXPECT_LT(b.momentum, 1e-13);
  EXPECT_LT(b.energy, 1e-13);
  EXPECT_GT(b.dissipation, 0);
  EXPECT_GT(b.angular, 1e-8);
  EXPECT_LT(b.angular, 1e-2);
}

// With the kernel-gradient correction the stress pair term A_i C_i grad W + A_j C_j grad W is still
// antisymmetric and the energy equation uses the same corrected gradient, so momentum and energy
// balance to round-off as before (angular momentum to the order of the correction).
TEST(UlsphConservation, KernelGradientCorrectionKeepsMomentumAndEnergyBalance) {
  RandomBody<2> body2(0.05, true, true, 14, true);
  const Balance b2 = balance(body2);
  RandomBody<3> body3(0.125, true, true, 15, true);
  const Balance b3 = balance(body3);
  std::printf("corrected: 2-D momentum %.2e energy %.2e angular %.2e; 3-D momentum %.2e energy %.2e angular %.2e\n",
              b2.momentum, b2.energy, b2.angular, b3.momentum, b3.energy, b3.angular);
  EXPECT_LT(b2.momentum, 1e-13);
  EXPECT_LT(b2.energy, 1e-13);
  EXPECT_LT(b3.momentum, 1e-13);
  EXPECT_LT(b3.energy, 1e-13);
  EXPECT_GT(b2.dissipation, 0);
  EXPECT_LT(b2.angular, 1e-1);
  EXPECT_LT(b3.angular, 1e-1);
}

TEST(UlsphConservation, UniformStressOnRegularLatticeExertsNoTorque) {
  // With a uniform stress the pair forces cancel in the interior and the free surface carries the
  // net traction sigma . n, whose torque about the centre vanishes for a symmetric body.
  const ParticleSet<2> set = makeLattice<2>(Vec2::Constant(-0.5), Vec2::Constant(0.5), 0.05);
  UpdatedLagrangianSph<2> system(set, UpdatedLagrangianSphOptions{});
  Vector y = system.initialState();
  const auto& layout = system.layout();
  for (Index i = 0; i < system.particleCount(); ++i) {
    y[layout.stress(i, 0)] = 0.3;
    y[layout.stress(i, 1)] = -0.1;
    y[layout.stress(i, 2)] = 0.2;
  }
  Vector ydot(system.size());
  system.rhs(0, y, ydot);
  Vector a(system.particleCount() * 2), x(a.size());
  for (Index i = 0; i < system.particleCount(); ++i)
    for (int d = 0; d < 2; ++d) {
      a[i * 2 + d] = ydot[layout.velocity(i, d)];
      x[i * 2 + d] = y[layout.position(i, d)];
    }
  const auto [t, scale] = torque<2>(x, a, system.masses());
  EXPECT_LT(t / scale, 1e-13);
}

TEST(UlsphConservation, ShortRunKeepsMomentumToRoundOffAndAngularMomentumClose) {
  // 40 leapfrog steps of the random 2-D body: sum m v stays at its initial value to round-off;
  // sum m x cross v drifts by the non-central torque (measured below).
  RandomBody<2> body(0.05, true, false, 21);
  UpdatedLagrangianSph<2>& system = body.system;
  const auto& layout = system.layout();
  auto totals = [&](const Vector& y) {
    Vec2 p = Vec2::Zero();
    Real l = 0, scale = 0;
    for (Index i = 0; i < system.particleCount(); ++i) {
      const Real m = system.masses()[static_cast<std::size_t>(i)];
      const Vec2 x(y[layout.position(i, 0)], y[layout.position(i, 1)]);
      const Vec2 v(y[layout.velocity(i, 0)], y[layout.velocity(i, 1)]);
      p += m * v;
      l += m * (x[0] * v[1] - x[1] * v[0]);
      scale += m * x.norm() * v.norm();
    }
    return std::make_tuple(p, l, scale);
  };
  const auto [p0, l0, scale0] = totals(body.y);
  test::LocalLeapfrog stepper(system, body.y);
  const Real dt = 0.5 * system.stableStep(body.y);
  for (int k = 0; k < 40; ++k) stepper.step(dt);
  const auto [p1, l1, scale1] = totals(stepper.state());
  (void)scale1;
  Real mass = 0;
  for (Real m : system.masses()) mass += m;
  std::printf("short run: momentum drift %.2e, angular momentum drift %.2e (relative to sum m |x||v|)\n",
              (p1 - p0).norm() / (mass * 0.1), std::abs(l1 - l0) / scale0);
  EXPECT_LT((p1 - p0).norm() / (mass * 0.1), 1e-13);
  EXPECT_LT(std::abs(l1 - l0) / scale0, 0.05);
}
