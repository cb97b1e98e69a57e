// The spectrum of the consistent variant next to the published scheme's, on small blocks (dense
// eigenvalues): the stable central-difference step from the largest |eigenvalue| of M^-1 K_sys, and
// the growth rate (largest real part of the modes) with free faces and with every face
// transmitting (dashpots through the traction matrix), with and without the higher-order filter
// v <- v - gamma dt (I - S)^2 v. The corrected boundary rows are not symmetric, so some modes are
// complex and grow slowly (docs/references.md, reading 3); the filter is meant to remove that growth.
//
// The filter enters the spectrum as what it is in the limit of small steps: per step it removes
// gamma dt (I - S)^2 v from the velocity, i.e. a damping term -gamma (I - S)^2 v in v'. The
// companion matrix of M u'' + C u' + K_sys u = 0 with it is
//   [[0, I], [-M^-1 K_sys, -(M^-1 C + gamma (I - S)^2)]],
// and its eigenvalues s are the modes exp(s t). lambda = mu = rho = 1 (c_p = sqrt 3, c_s = 1),
// h = dx, two ghost layers; gamma = 0.25 c_s / dx (the findings' 0.25 / dx).

#include "BlockFixture.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include "core/Material.hpp"
#include "integrators/CentralDifference.hpp"
#include "methods/very_weak_sph/ConservativeSmoothing.hpp"
#include "methods/very_weak_sph/TransmittingBoundary.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <random>

using namespace mfwave;
using mfwave::test::Block;

namespace {

using Dense = Eigen::MatrixXd;

struct Scheme {
  Dense accelerationFromDisplacement;  // -M^-1 K_sys
  Dense dampingHalfSpace;              // M^-1 C, every face transmitting but the top one (the Lamb setting)
  Dense dampingTransmitting;           // M^-1 C, every face transmitting
  Dense filter;                        // gamma (I - S)^2 on each component
};

// M^-1 A for a diagonal M.
Dense inverseMassTimes(const SparseMatrix& mass, const SparseMatrix& a) {
  return mass.diagonal().cwiseInverse().asDiagonal() * Dense(a);
}

template <int D>
Scheme schemeOf(const Block<D>& block, VeryWeakSphVariant variant) {
  VeryWeakSphOptions options;
  options.variant = variant;
  const VeryWeakSph<D> vw = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, options);
  const Index n = block.particles.physicalCount();
  Scheme s;
  s.accelerationFromDisplacement = -inverseMassTimes(vw.system.mass(), vw.system.stiffness());
  // Published: the paper's particle-lumped dashpots (eq. (32)); consistent: through the corrected T.
  auto damping = [&](std::uint8_t mask) {
    const SparseMatrix c =
        variant == VeryWeakSphVariant::Published
            ? assembleTransmittingDamping(block.particles, block.neighbours, block.kernel, vw.data.facets,
                                          options.material, mask, DashpotLumping::Particle)
            : dashpotsThroughTractionMatrix(vw.data.tractionMatrix, vw.data.facets, options.material, mask);
    return inverseMassTimes(vw.system.mass(), c);
  };
  s.dampingHalfSpace = damping(static_cast<std::uint8_t>(allFaces(D) & ~faceBit(2 * D - 1)));
  s.dampingTransmitting = damping(allFaces(D));
  const Dense smoothing(smoothingMatrix(block.particles, block.neighbours, block.kernel, vw.data.volume));
  const Dense offSmooth = Dense::Identity(n, n) - smoothing;
  const Dense squared = offSmooth * offSmooth;
  const Real gamma = 0.25 * options.material.sWaveSpeed() / block.kernel.smoothingLength();  // h = dx
  s.filter = Dense::Zero(D * n, D * n);
  for (Index a = 0; a < n; ++a)
    for (Index b = 0; b < n; ++b)
      for (int i = 0; i < D; ++i) s.filter(D * a + i, D * b + i) = gamma * squared(a, b);
  return s;
}

// Rigid-body modes (s = 0, perturbed by round-off to about 1e-7) are left out of the growth rates:
// every other mode of these blocks has |s| > 0.1.
constexpr Real rigidMode = 1e-4;

// From the eigenvalues lambda of M^-1 K_sys: the largest |lambda|, the central-difference step
// 2 / sqrt of it, and the growth rate of the undamped modes exp(s t), s = sqrt(-lambda) (the
// principal root has Re s >= 0).
struct Undamped {
  Real largest = 0;
  Real step = 0;
  Real growth = 0;
};

Undamped undamped(const Dense& accelerationFromDisplacement) {
  const Eigen::VectorXcd eigenvalues = generalEigenvalues(-accelerationFromDisplacement);
  Undamped u;
  u.largest = eigenvalues.cwiseAbs().maxCoeff();
  u.step = 2 / std::sqrt(u.largest);
  for (const std::complex<Real>& lambda : eigenvalues) {
    const std::complex<Real> root = std::sqrt(-lambda);
    if (std::abs(root) > rigidMode) u.growth = std::max(u.growth, root.real());
  }
  return u;
}

// Largest real part over the eigenvalues of [[0, I], [A, -B]] (rigid modes left out).
Real growthRate(const Dense& a, const Dense& b) {
  const Index m = a.rows();
  Dense companion = Dense::Zero(2 * m, 2 * m);
  companion.topRightCorner(m, m).setIdentity();
  companion.bottomLeftCorner(m, m) = a;
  companion.bottomRightCorner(m, m) = -b;
  const Eigen::VectorXcd eigenvalues = generalEigenvalues(companion);
  Real growth = -std::numeric_limits<Real>::infinity();
  for (const std::complex<Real>& s : eigenvalues)
    if (std::abs(s) > rigidMode) growth = std::max(growth, s.real());
  return growth;
}

struct Measured {
  Undamped published, consistent;
  Real publishedHalfSpace = 0;
  Real consistentFreeFiltered = 0, consistentHalfSpace = 0, consistentHalfSpaceFiltered = 0,
       consistentTransmitting = 0;
};

template <int D>
Measured measureSpectra(const char* title, const Block<D>& block) {
  Measured m;
  const Scheme p = schemeOf(block, VeryWeakSphVariant::Published);
  m.published = undamped(p.accelerationFromDisplacement);
  m.publishedHalfSpace = growthRate(p.accelerationFromDisplacement, p.dampingHalfSpace);
  const Scheme c = schemeOf(block, VeryWeakSphVariant::Consistent);
  m.consistent = undamped(c.accelerationFromDisplacement);
  m.consistentFreeFiltered = growthRate(c.accelerationFromDisplacement, c.filter);
  m.consistentHalfSpace = growthRate(c.accelerationFromDisplacement, c.dampingHalfSpace);
  m.consistentHalfSpaceFiltered = growthRate(c.accelerationFromDisplacement, c.dampingHalfSpace + c.filter);
  m.consistentTransmitting = growthRate(c.accelerationFromDisplacement, c.dampingTransmitting);
  std::printf("%s\n  published:  max|eig| %.10g, step %.10g; growth free %.9g, half-space %.9g\n", title,
              m.published.largest, m.published.step, m.published.growth, m.publishedHalfSpace);
  std::printf("  consistent: max|eig| %.10g, step %.10g; growth free %.9g (filtered %.9g), half-space %.9g "
              "(filtered %.9g), all transmitting %.9g\n",
              m.consistent.largest, m.consistent.step, m.consistent.growth, m.consistentFreeFiltered,
              m.consistentHalfSpace, m.consistentHalfSpaceFiltered, m.consistentTransmitting);
  return m;
}

}  // namespace

namespace {

// Asserted as measured: eigenvalue magnitudes and steps to 1e-8 relative, growth rates to 1e-6.
void expectMeasured(const Measured& m, const std::array<Real, 4>& published, const std::array<Real, 7>& consistent) {
  EXPECT_NEAR(m.published.largest, published[0], 1e-8 * published[0]);
  EXPECT_NEAR(m.published.step, published[1], 1e-8 * published[1]);
  EXPECT_NEAR(m.published.growth, published[2], 1e-6);
  EXPECT_NEAR(m.publishedHalfSpace, published[3], 1e-6);
  EXPECT_NEAR(m.consistent.largest, consistent[0], 1e-8 * consistent[0]);
  EXPECT_NEAR(m.consistent.step, consistent[1], 1e-8 * consistent[1]);
  EXPECT_NEAR(m.consistent.growth, consistent[2], 1e-6);
  EXPECT_NEAR(m.consistentFreeFiltered, consistent[3], 1e-6);
  EXPECT_NEAR(m.consistentHalfSpace, consistent[4], 1e-6);
  EXPECT_NEAR(m.consistentHalfSpaceFiltered, consistent[5], 1e-6);
  EXPECT_NEAR(m.consistentTransmitting, consistent[6], 1e-6);
}

}  // namespace

TEST(ConsistentVariantSpectrum, TwoDimensions) {
  const Block<2> block(Vec2::Zero(), Vec2::Constant(8), 1.0, 2, 1.0);
  const Measured m = measureSpectra("2-D 9 x 9 (81 particles)", block);
  // The consistent step is 2.6 % longer. Free faces: both schemes have growing complex modes; the
  // filter brings the consistent one's from 0.044 to 0.002. With the top face free and the others
  // transmitting (the Lamb setting) the consistent variant decays, the published one grows slowly.
  expectMeasured(m, {12.37851134, 0.5684546015, 0.0644739592, 0.0026064324},
                 {11.76880118, 0.5829937281, 0.0443716131, 0.00206496337, -0.00109619444, -0.0536373326,
                  -0.00926876942});
  EXPECT_GT(m.consistent.step, 1.02 * m.published.step);
  EXPECT_GT(m.consistent.growth, 0.04);
  EXPECT_LT(m.consistentHalfSpace, 0.0);
  EXPECT_LT(m.consistentTransmitting, 0.0);
}

TEST(ConsistentVariantSpectrum, ThreeDimensions) {
  const Block<3> block(Vec3::Zero(), Vec3::Constant(4), 1.0, 2, 1.0);
  const Measured m = measureSpectra("3-D 5 x 5 x 5 (125 particles)", block);
  // The consistent step is 10.7 % longer. Free faces: growth 0.199 (published 0.176), 0.132 with
  // the filter. Top face free, the others transmitting: a slow growth 0.00126 (published 0.0077)
  // that the filter turns into decay (-0.071). All faces transmitting: every mode decays.
  expectMeasured(m, {13.24998453, 0.5494425766, 0.176038886, 0.00772613449},
                 {10.82156304, 0.6079739885, 0.198611486, 0.132458167, 0.00125908852, -0.0706735175,
                  -0.00570432674});
  EXPECT_GT(m.consistent.step, 1.10 * m.published.step);
  EXPECT_GT(m.consistentHalfSpace, 0.0);
  EXPECT_LT(m.consistentHalfSpaceFiltered, -0.05);
  EXPECT_LT(m.consistentTransmitting, 0.0);
}

namespace {

struct LongRun {
  Real initial = 0;  // max |u| at t = 0
  Real middle = 0;   // max |u| after half the steps
  Real final = 0;    // max |u| at the end
  Real time = 0;
  Real rate = 0;     // ln(final / middle) / (time / 2): the growth rate of the second half
};

// Central difference (dashpots implicit, eq. (32)) from a random displacement, v = 0, for `steps`
// steps of `cfl` times the step of the largest |eigenvalue|; optionally the filter
// v <- v - gamma dt (I - S)^2 v on the half-step velocity.
LongRun longRun(const Block<3>& block, std::uint8_t transmitting, bool filtered, int steps, Real cfl) {
  VeryWeakSphOptions options;
  options.variant = VeryWeakSphVariant::Consistent;
  VeryWeakSph<3> vw = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, options);
  vw.system.setDamping(dashpotsThroughTractionMatrix(vw.data.tractionMatrix, vw.data.facets, options.material, transmitting));
  const Real dt = cfl * undamped(-inverseMassTimes(vw.system.mass(), vw.system.stiffness())).step;
  const ParticleMatrix smoothing = smoothingMatrix(block.particles, block.neighbours, block.kernel, vw.data.volume);
  const Real gamma = 0.25 * options.material.sWaveSpeed() / block.kernel.smoothingLength();

  const Index dofs = vw.system.size();
  std::mt19937 random(2024);
  Vector u0(dofs);
  for (Index i = 0; i < dofs; ++i) u0[i] = 2.0 * static_cast<Real>(random()) / 4294967295.0 - 1.0;
  CentralDifference integrator;
  if (filtered) {
    integrator.setVelocityFilter([&smoothing, gamma](Real step, Vector& v) {
      Vector once, twice;
      multiplyComponents(smoothing, v, 3, once);
      once = v - once;  // (I - S) v
      multiplyComponents(smoothing, once, 3, twice);
      v -= gamma * step * (once - twice);  // gamma dt (I - S)^2 v
    });
  }
  integrator.initialise(vw.system, 0.0, u0, Vector::Zero(dofs), dt);
  LongRun run;
  run.initial = u0.cwiseAbs().maxCoeff();
  for (int step = 1; step <= steps; ++step) {
    integrator.step();
    if (step == steps / 2) run.middle = integrator.state().displacement.cwiseAbs().maxCoeff();
  }
  run.final = integrator.state().displacement.cwiseAbs().maxCoeff();
  run.time = integrator.time();
  run.rate = std::log(run.final / run.middle) / (run.time / 2);
  std::printf("  %s, %s: dt %.9g, t %.9g; max|u| %.9g -> %.9g (half way) -> %.9g; second-half rate %.9g\n",
              transmitting == allFaces(3) ? "all faces transmitting" : "half-space (top free)",
              filtered ? "filtered" : "no filter", dt, run.time, run.initial, run.middle, run.final, run.rate);
  return run;
}

}  // namespace

TEST(ConsistentVariantSpectrum, LongRunOfTwentyThousandSteps) {
  const Block<3> block(Vec3::Zero(), Vec3::Constant(4), 1.0, 2, 1.0);
  const auto halfSpace = static_cast<std::uint8_t>(allFaces(3) & ~faceBit(BoxFace::PlusZ));
  std::printf("3-D 5 x 5 x 5, consistent variant, central difference at 0.9 of the stable step, 20000 steps\n");
  // All faces transmitting: bounded; what stays is the rigid-body part of the initial displacement
  // (a static translation or rotation is an equilibrium that no dashpot sees).
  const LongRun all = longRun(block, allFaces(3), false, 20000, 0.9);
  EXPECT_NEAR(all.final, 0.118412972, 1e-6);
  EXPECT_LT(std::abs(all.rate), 1e-9);
  // Top face free: unbounded without the filter, at the rate of the spectrum's growing mode (0.00116
  // per unit time against the continuous 0.00126), from 1 to 5.4e5 over t = 10944.
  const LongRun free = longRun(block, halfSpace, false, 20000, 0.9);
  EXPECT_NEAR(free.rate, 0.00115690533, 1e-7);
  EXPECT_GT(free.final, 1e5);
  // With the filter: bounded, decayed to the rigid-body part.
  const LongRun filtered = longRun(block, halfSpace, true, 20000, 0.9);
  EXPECT_NEAR(filtered.final, 0.164766697, 1e-6);
  EXPECT_LT(std::abs(filtered.rate), 1e-9);
}
