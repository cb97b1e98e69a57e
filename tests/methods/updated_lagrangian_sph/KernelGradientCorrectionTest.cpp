// The kernel-gradient correction (KernelGradientCorrection.hpp) makes the velocity gradient of
// Li eq. (22) exact for every linear velocity field v = A x, at every particle: interior, face,
// edge and corner, on a jittered lattice. Then the stress rate of an unstressed body is
// 2G dev(sym A) (Li eq. 26 with s = 0) and the continuity rate is -rho0 tr A, to round-off.
// Without the correction the same rates are off by tens of percent at the faces: a particle there
// misses the part of its support outside the body, which is what makes the uncorrected cantilever
// plate too soft (docs/studies/sph-solids.md).

#include "UlsphTestSupport.hpp"

#include "methods/updated_lagrangian_sph/StressVoigt.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

using namespace mfwave;

namespace {

struct RateErrors {
  Real stress;   // max_i |ds_i/dt - 2G dev(sym A)| / |2G dev(sym A)|
  Real density;  // max_i |drho_i/dt + rho0 tr A| / (rho0 |A|)
};

template <int D>
RateErrors linearFieldRateErrors(bool corrected, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  const Real dp = D == 3 ? 0.2 : 0.1;
  ParticleSet<D> particles = makeLattice<D>(Vec<D>::Zero(), Vec<D>::Ones(), dp);
  for (Index i = 0; i < particles.size(); ++i) {
    Vec<D> x = particles.position(i);
    for (int a = 0; a < D; ++a) x[a] += 0.1 * dp * u(rng);
    particles.setPosition(i, x);
  }
  UpdatedLagrangianSphOptions options;
  options.material = Material::fromLame(2.0, 1.5, 3.0);
  options.kernelGradientCorrection = corrected;
  UpdatedLagrangianSph<D> system(particles, options);

  Mat<D> A;
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) A(a, b) = u(rng);
  const Index n = system.particleCount();
  Vector v(n * D);
  for (Index i = 0; i < n; ++i) v.segment<D>(i * D) = A * particles.position(i);
  const Vector y = system.initialState(v);
  Vector qdot(system.configurationSize());
  system.configurationRate(0, y, qdot);

  // 2G dev(sym A), the deviator taken with the 3-D trace as the method does (plane/uniaxial strain).
  const Real G = options.material.mu();
  Mat<D> expected = G * (A + A.transpose());
  expected.diagonal().array() -= 2 * G * A.trace() / 3;
  const Real rho0 = options.material.density();
  RateErrors errors{0, 0};
  const auto& layout = system.layout();
  for (Index i = 0; i < n; ++i) {
    const Mat<D> rate = stressFromVoigt<D>(qdot.data() + layout.stress(i, 0));
    errors.stress = std::max(errors.stress, (rate - expected).norm() / expected.norm());
    errors.density =
        std::max(errors.density, std::abs(qdot[layout.density(i)] + rho0 * A.trace()) / (rho0 * A.norm()));
  }
  return errors;
}

// Corrected: exact to round-off at every particle; plain: off by more than 20 % somewhere (the
// faces), so the comparison can fail.
template <int D>
void expectCorrectionMakesLinearRatesExact(unsigned seed) {
  const RateErrors corrected = linearFieldRateErrors<D>(true, seed);
  const RateErrors plain = linearFieldRateErrors<D>(false, seed);
  std::printf("%d-D linear field, worst particle: corrected stress %.2e density %.2e; plain stress %.3f density %.3f\n",
              D, corrected.stress, corrected.density, plain.stress, plain.density);
  EXPECT_LT(corrected.stress, 1e-12);
  EXPECT_LT(corrected.density, 1e-12);
  EXPECT_GT(plain.stress, 0.2);
}

}  // namespace

TEST(UlsphKernelGradientCorrection, LinearVelocityGivesExactRatesEverywhere2d) { expectCorrectionMakesLinearRatesExact<2>(21); }

TEST(UlsphKernelGradientCorrection, LinearVelocityGivesExactRatesEverywhere3d) { expectCorrectionMakesLinearRatesExact<3>(22); }

TEST(UlsphKernelGradientCorrection, LinearVelocityGivesExactRatesAtBothEnds1d) { expectCorrectionMakesLinearRatesExact<1>(23); }
