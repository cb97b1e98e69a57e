// The total-Lagrangian SPH (lib/methods/total_lagrangian_sph): what holds by construction is
// checked to round-off: affine fields (the penalty is zero, the strain energy exact), rigid
// rotations (no force), forces as minus the gradient of the energy (finite differences, large
// strain), momentum, thread independence, and the central difference keeping the total energy.

#include "integrators/CentralDifference.hpp"
#include "methods/total_lagrangian_sph/TotalLagrangianSph.hpp"
#include "particles/Lattice.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <random>

using namespace mfwave;

namespace {

TotalLagrangianSphOptions plateLike() {
  TotalLagrangianSphOptions o;
  o.material = Material::fromYoung(2e6, 0.3975, 1000);
  o.hourglassFactor = 1;
  return o;
}

ParticleSet<2> block(Index nx, Index ny, Real dp) {
  // cell-centred, as the plate study's particles
  return makeLattice<2>(Vec2(0.5 * dp, 0.5 * dp), Vec2((nx - 0.5) * dp, (ny - 0.5) * dp), dp);
}

Vector randomField(Index size, Real scale, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> d(-1, 1);
  Vector u(size);
  for (Index k = 0; k < size; ++k) u[k] = scale * d(rng);
  return u;
}

Vector affine(const TotalLagrangianSph<2>& system, const Mat2& G, const Vec2& shift) {
  const auto& X = system.pairs().X;
  Vector u(system.size());
  for (Index i = 0; i < system.particleCount(); ++i)
    u.segment<2>(2 * i) = G * Vec2(X[static_cast<std::size_t>(2 * i)], X[static_cast<std::size_t>(2 * i + 1)]) + shift;
  return u;
}

}  // namespace

TEST(TotalLagrangianSph, AffineFieldsHaveTheExactStrainEnergyAndNoPenaltyAtEverySurface) {
  const Real dp = 0.01;
  TotalLagrangianSph<2> system(block(9, 6, dp), plateLike());
  Mat2 G;
  G << 0.02, -0.01, 0.03, -0.015;
  const Vector u = affine(system, G, Vec2(0.3, -0.2));
  const TotalLagrangianSphEnergy e = system.energy(u, Vector::Zero(system.size()));
  const Material& m = system.options().material;
  const Mat2 F = Mat2::Identity() + G;
  const Mat2 green = 0.5 * (F.transpose() * F - Mat2::Identity());
  const Real psi = 0.5 * m.lambda() * green.trace() * green.trace() + m.mu() * green.squaredNorm();
  EXPECT_NEAR(e.strain, psi * 54 * dp * dp, 1e-10 * e.strain);
  EXPECT_LT(e.hourglass, 1e-12 * e.strain);
}

TEST(TotalLagrangianSph, RigidRotationsAndTranslationsExertNoForce) {
  TotalLagrangianSph<2> system(block(10, 5, 0.02), plateLike());
  const Real angle = 0.6;
  Mat2 R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  const Vector u = affine(system, R - Mat2::Identity(), Vec2(1.5, -0.7));
  Vector a(system.size());
  system.acceleration(0, u, Vector::Zero(system.size()), a);
  // the scale of a unit strain: E / (rho dp)
  EXPECT_LT(a.cwiseAbs().maxCoeff(), 1e-9 * 2e6 / (1000 * 0.02));
}

TEST(TotalLagrangianSph, ForcesAreMinusTheGradientOfTheEnergyAtLargeStrain) {
  const Real dp = 0.02;
  TotalLagrangianSph<2> system(block(7, 5, dp), plateLike());
  const Index n = system.particleCount();
  const Vector u = randomField(system.size(), 0.15 * dp, 3);  // strains of order 0.3
  Vector a(system.size());
  system.acceleration(0, u, Vector::Zero(system.size()), a);
  const Vector zero = Vector::Zero(system.size());
  auto potential = [&](const Vector& w) {
    const TotalLagrangianSphEnergy e = system.energy(w, zero);
    return e.strain + e.hourglass;
  };
  const Real step = 1e-6 * dp;
  Real largest = 0, worst = 0;
  for (Index k = 0; k < system.size(); k += 3) {
    Vector plus = u, minus = u;
    plus[k] += step;
    minus[k] -= step;
    const Real force = -(potential(plus) - potential(minus)) / (2 * step);
    const Real mass = 1000 * system.pairs().volume[static_cast<std::size_t>(k / 2)];
    largest = std::max(largest, std::abs(force));
    worst = std::max(worst, std::abs(force - mass * a[k]));
  }
  ASSERT_GT(largest, 0);
  EXPECT_LT(worst, 1e-5 * largest) << n << " particles";
}

TEST(TotalLagrangianSph, MomentumIsConservedPairByPair) {
  const Real dp = 0.02;
  TotalLagrangianSph<2> system(block(8, 6, dp), plateLike());
  const Vector u = randomField(system.size(), 0.1 * dp, 5);
  Vector a(system.size());
  system.acceleration(0, u, Vector::Zero(system.size()), a);
  Vec2 momentumRate = Vec2::Zero(), scale = Vec2::Zero();
  for (Index i = 0; i < system.particleCount(); ++i) {
    const Real m = 1000 * system.pairs().volume[static_cast<std::size_t>(i)];
    momentumRate += m * a.segment<2>(2 * i);
    scale += m * a.segment<2>(2 * i).cwiseAbs();
  }
  EXPECT_LT(momentumRate.norm(), 1e-12 * scale.norm());
}

TEST(TotalLagrangianSph, AccelerationsDoNotDependOnTheThreadCount) {
  TotalLagrangianSph<2> system(block(60, 50, 0.01), plateLike());
  ASSERT_GT(system.particleCount(), 2000);
  const Vector u = randomField(system.size(), 0.001, 7);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  Vector one(system.size()), two(system.size());
  system.acceleration(0, u, u, one);
  omp_set_num_threads(2);
  system.acceleration(0, u, u, two);
  omp_set_num_threads(saved);
  EXPECT_EQ((one - two).cwiseAbs().maxCoeff(), 0.0);
}

TEST(TotalLagrangianSph, CentralDifferenceKeepsTheEnergyOfAClampedStrip) {
  // A strip clamped at its left column, set swinging by a smooth velocity field: no artificial
  // terms, so the total energy (kinetic + strain + penalty) only oscillates at O(dt^2).
  const Real dp = 0.02;
  const ParticleSet<2> set = block(20, 4, dp);
  TotalLagrangianSph<2> system(set, plateLike());
  std::vector<Index> left;
  for (Index i = 0; i < set.physicalCount(); ++i)
    if (set.position(i)[0] < dp) left.push_back(i);
  system.fixParticles(left);
  Vector v(system.size());
  for (Index i = 0; i < set.physicalCount(); ++i) {
    const Real x = set.position(i)[0] / 0.4;
    v.segment<2>(2 * i) = Vec2(0, 0.5 * x * x);
  }
  system.clamp(v);
  const Real dt = 0.5 * 2 / std::sqrt(system.largestFrequencySquared());
  CentralDifference integrator;
  integrator.initialise(system, 0, Vector::Zero(system.size()), v, dt);
  const Real initial = system.energy(Vector::Zero(system.size()), v).total();
  Real worst = 0;
  for (int s = 0; s < 4000; ++s) {
    integrator.step();
    const auto state = integrator.state();
    worst = std::max(worst, std::abs(system.energy(state.displacement, state.velocity).total() / initial - 1));
  }
  EXPECT_LT(worst, 2e-3);
  EXPECT_GT(worst, 0);
}
