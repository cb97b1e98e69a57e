// lib/methods/spectral_element/SpectralElementElasticity<2> in motion: central difference (leapfrog
// form) on free and fixed faces keeps its discrete energy to rounding over many periods; absorbing
// faces only remove energy; the lowest P mode of a 1-D-like box converges to its exact frequency
// at order 2N, i.e. at least N.

#include "methods/spectral_element/SpectralElementElasticity.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

namespace mfwave {
namespace {

// The central-difference step limit 2 / omega_max of M^-1 K, by power iteration.
Real criticalStep(SpectralElementElasticity<2>& system) {
  const Vector m = system.lumpedMass();
  Vector x = Vector::Ones(system.size()), kx;
  for (Index i = 0; i < x.size(); ++i) x[i] = std::sin(0.37 * static_cast<Real>(i) + 0.1);
  Real lambda = 0;
  for (int k = 0; k < 3000; ++k) {
    system.applyStiffness(x, kx);
    const Vector y = kx.cwiseQuotient(m);
    lambda = y.norm() / x.norm();
    x = y / y.norm();
  }
  return 2 / std::sqrt(lambda);
}

// Free and fixed faces, no damping, an initial smooth displacement: the central difference's
// conserved energy 1/2 v_{n+1/2}^T M v_{n+1/2} + 1/2 u_n^T K u_{n+1} stays constant, and the
// plain kinetic + strain energy at whole steps stays within O((omega dt)^2) of it.
TEST(SpectralElementDynamics, CentralDifferenceConservesEnergyOnFreeAndFixedFaces) {
  SpectralElementSettings<2> s;
  s.lower = Vec2(0, 0);
  s.upper = Vec2(2, 1);
  s.elementSize = 0.5;
  s.order = 4;
  s.material = Material::fromLame(1, 1, 1);
  s.faces = {SpectralElementFace::Fixed, SpectralElementFace::Free, SpectralElementFace::Free,
             SpectralElementFace::Fixed};
  SpectralElementElasticity<2> system(s);
  const Real dt = 0.5 * criticalStep(system);
  const Index n = system.nodeCount();
  Vector u(system.size()), v = Vector::Zero(system.size()), a(system.size());
  for (Index p = 0; p < n; ++p) {
    const Vec2 x = system.nodePosition(p);
    u[2 * p] = 0.01 * std::sin(1.3 * x[0]) * std::cos(2.1 * x[1]);
    u[2 * p + 1] = 0.02 * std::cos(0.7 * x[0] + 0.4) * x[1];
  }
  for (Index dof = 0; dof < system.size(); ++dof)
    if (system.fixedDofs()[static_cast<std::size_t>(dof)]) u[dof] = 0;
  // 20 periods of the slowest wave across the box (2 L / c_s = 4)
  const long steps = static_cast<long>(std::ceil(80.0 / dt));
  system.acceleration(0, u, v, a);
  Vector vHalf = v + 0.5 * dt * a;
  Vector ku;
  system.applyStiffness(u, ku);
  Real reference = -1, largestDrift = 0, largestWholeStepDrift = 0;
  for (long k = 0; k < steps; ++k) {
    const Vector uNext = u + dt * vHalf;
    Vector kuNext;
    system.applyStiffness(uNext, kuNext);
    const Real conserved = 0.5 * vHalf.dot(system.lumpedMass().cwiseProduct(vHalf)) + 0.5 * u.dot(kuNext);
    if (reference < 0) reference = conserved;
    largestDrift = std::max(largestDrift, std::abs(conserved - reference) / reference);
    system.acceleration(0, uNext, vHalf, a);
    const Vector vNext = vHalf + dt * a;
    const Vector vWhole = 0.5 * (vHalf + (vHalf + dt * a));
    largestWholeStepDrift = std::max(
        largestWholeStepDrift,
        std::abs(system.kineticEnergy(vWhole) + system.strainEnergy(uNext) - reference) / reference);
    u = uNext;
    vHalf = vNext;
  }
  EXPECT_GT(steps, 1000);
  EXPECT_LT(largestDrift, 1e-6);  // measured ~1e-13
  // the high modes the masked corner excites have omega dt near 1: a few per cent (measured 0.025)
  EXPECT_LT(largestWholeStepDrift, 5e-2);
}

// Absorbing faces on three sides: the energy never grows and the dashpots remove most of it.
TEST(SpectralElementDynamics, AbsorbingFacesOnlyRemoveEnergy) {
  SpectralElementSettings<2> s;
  s.lower = Vec2(-2, -2);
  s.upper = Vec2(2, 0);
  s.elementSize = 0.5;
  s.order = 4;
  s.material = Material::fromLame(1, 1, 1);
  s.faces = {SpectralElementFace::Absorbing, SpectralElementFace::Absorbing, SpectralElementFace::Absorbing,
             SpectralElementFace::Free};
  SpectralElementElasticity<2> system(s);
  const Real dt = 0.5 * criticalStep(system);
  Vector u(system.size()), v = Vector::Zero(system.size());
  for (Index p = 0; p < system.nodeCount(); ++p) {
    const Vec2 x = system.nodePosition(p);
    const Real bump = std::exp(-4 * (x[0] * x[0] + (x[1] + 1) * (x[1] + 1)));
    u[2 * p] = 0.01 * bump;
    u[2 * p + 1] = -0.01 * bump;
  }
  // central difference with the centred dashpot solve; its energy E_{n+1/2} = 1/2 v_{n+1/2}^T M
  // v_{n+1/2} + 1/2 u_n^T K u_{n+1} falls by dt vbar^T C vbar each step (vbar the mean of the two
  // half-step velocities), so it never rises
  const std::unique_ptr<CentredDampingSolve> solve = system.centredDamping(dt, {});
  Vector a(system.size());
  system.acceleration(0, u, v, a);
  Vector vHalf = v + 0.5 * dt * a;
  const auto halfStepEnergy = [&](const Vector& uNow, const Vector& uAhead, const Vector& vh) {
    Vector kuNext;
    system.applyStiffness(uAhead, kuNext);
    return system.kineticEnergy(vh) + 0.5 * uNow.dot(kuNext);
  };
  Vector uNext = u + dt * vHalf;
  const Real initial = halfStepEnergy(u, uNext, vHalf);
  Real previous = initial;
  const long steps = static_cast<long>(std::ceil(20.0 / dt));
  int rises = 0;
  for (long k = 0; k < steps; ++k) {
    u = uNext;
    solve->acceleration(0, u, vHalf, Vector(), a);
    vHalf += dt * a;
    uNext = u + dt * vHalf;
    const Real e = halfStepEnergy(u, uNext, vHalf);
    if (e > previous * (1 + 1e-12)) ++rises;
    previous = e;
  }
  EXPECT_EQ(rises, 0);
  EXPECT_LT(previous, 0.05 * initial);  // most of the bump has left through the dashpots
}

// The lowest axial mode of a box [0, 4] x [0, 1] with lambda = 0, the x faces fixed and the y
// faces free: u = (sin(pi x / 4), 0) is exact (sigma_yy = lambda u_x,x = 0 leaves the y faces
// free), omega = pi c_p / 4, c_p = sqrt(2 mu / rho). Its discrete frequency from the dense
// eigenproblem at two element sizes.
Real axialModeError(int order, Real elementSize) {
  SpectralElementSettings<2> s;
  s.lower = Vec2(0, 0);
  s.upper = Vec2(4, 1);
  s.elementSize = elementSize;
  s.order = order;
  s.material = Material::fromLame(0, 1, 1);
  s.faces = {SpectralElementFace::Fixed, SpectralElementFace::Fixed, SpectralElementFace::Free,
             SpectralElementFace::Free};
  const SpectralElementElasticity<2> system(s);
  std::vector<Index> free;
  for (Index dof = 0; dof < system.size(); ++dof)
    if (!system.fixedDofs()[static_cast<std::size_t>(dof)]) free.push_back(dof);
  const auto count = static_cast<Index>(free.size());
  const Vector m = system.lumpedMass();
  Eigen::MatrixXd a(count, count);
  Vector unit = Vector::Zero(system.size()), column;
  for (Index j = 0; j < count; ++j) {
    unit.setZero();
    unit[free[static_cast<std::size_t>(j)]] = 1;
    system.applyStiffness(unit, column);
    for (Index i = 0; i < count; ++i)
      a(i, j) = column[free[static_cast<std::size_t>(i)]] /
                std::sqrt(m[free[static_cast<std::size_t>(i)]] * m[free[static_cast<std::size_t>(j)]]);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(0.5 * (a + a.transpose()), Eigen::EigenvaluesOnly);
  const Real pi = std::acos(-1.0);
  const Real exact = pi * std::sqrt(2.0) / 4;
  Real closest = std::numeric_limits<Real>::infinity();
  for (Index i = 0; i < count; ++i) {
    const Real omega = std::sqrt(std::max<Real>(eigen.eigenvalues()[i], 0));
    if (std::abs(omega - exact) < std::abs(closest - exact)) closest = omega;
  }
  return std::abs(closest - exact) / exact;
}

TEST(SpectralElementDynamics, AxialModeFrequencyConvergesAtLeastAtOrderN) {
  for (int order : {1, 2, 3, 4}) {
    const Real coarse = axialModeError(order, 1.0), fine = axialModeError(order, 0.5);
    const Real measured = std::log2(coarse / fine);
    EXPECT_GE(measured, order) << "order " << order << ": errors " << coarse << ", " << fine;
    RecordProperty("order_" + std::to_string(order), std::to_string(measured));
    std::printf("N = %d: relative frequency errors %.3e (h = 1), %.3e (h = 0.5), order %.2f\n", order, coarse, fine,
                measured);
  }
}

}  // namespace
}  // namespace mfwave
