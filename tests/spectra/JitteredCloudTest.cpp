// The jittered-cloud spectra: with no jitter the folded operator is the lattice operator (its
// largest omega^2 equals the FFT spectrum's), the corrected methods keep quadratic fields exact on
// irregular clouds while the updated-Lagrangian SPH does not, and the growing modes the atlas
// reports on irregular clouds are found (docs/studies/stability-atlas.md, "Irregular clouds").

#include "spectra/JitteredCloud.hpp"

#include "numerics/InteriorStability.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

namespace {

template <int D>
Real latticeOmegaMaxSquared(const std::string& method, const LatticeMethodSettings& settings, int cells) {
  const MethodLatticeStencil<D> stencil = latticeMethodStencil<D>(method, settings, 1.0);
  const InteriorStability<D> verdict = interiorStability<D>(stencil.acceleration, stencil.mass, 1.0, cells);
  EXPECT_EQ(verdict.cells, cells);
  return verdict.largestOmegaSquared;
}

// From the reported Courant number c_p dt / dx at dt = 2 / omega_max (dx = 1).
Real omegaMaxSquared(const JitteredCloudReport& r, Real cp2) { return 4 * cp2 / (r.courant * r.courant); }

}  // namespace

TEST(JitteredCloud, WithoutJitterItIsTheLatticeOperator) {
  LatticeMethodSettings s;  // lambda = mu = rho = 1: c_p = sqrt 3
  const Real cp2 = 3;
  for (const char* method : {"vwsph_published", "vwsph_consistent", "rkcm"}) {
    const JitteredCloudReport r = jitteredCloudSpectrum<2>(method, s, 12, 0.0, 1);
    ASSERT_NE(r.status.rfind("fails", 0), 0u) << method << ": " << r.status;
    EXPECT_NEAR(omegaMaxSquared(r, cp2) / latticeOmegaMaxSquared<2>(method, s, 12), 1, 1e-9) << method;
    EXPECT_EQ(r.unknowns, 288);
    EXPECT_DOUBLE_EQ(r.closestPair, 1.0);
  }
  // The linearised updated-Lagrangian rows come from central differences (RestModes).
  const JitteredCloudReport ul = jitteredCloudSpectrum<1>("ulsph", s, 32, 0.0, 1);
  EXPECT_NEAR(omegaMaxSquared(ul, cp2) / latticeOmegaMaxSquared<1>("ulsph", s, 32), 1, 1e-6);
  // Its sawtooth (k dx = pi) is a zero-energy mode on the lattice.
  EXPECT_EQ(ul.spuriousLowModes, 1);
}

TEST(JitteredCloud, CorrectedRowsStayQuadraticallyExactOnIrregularClouds) {
  LatticeMethodSettings s;
  for (const char* method : {"vwsph_consistent", "rkcm"}) {
    const JitteredCloudReport r = jitteredCloudSpectrum<2>(method, s, 12, 0.25, 2);
    EXPECT_LT(r.quadraticResidual, 1e-9) << method;
    EXPECT_LT(r.closestPair, 0.75) << method;
  }
  // First-order RK reproduces linear fields only.
  LatticeMethodSettings linear = s;
  linear.rkOrder = 1;
  EXPECT_GT(jitteredCloudSpectrum<2>("rkcm", linear, 12, 0.25, 2).quadraticResidual, 0.01);
  // The updated-Lagrangian SPH is exact for quadratics on the lattice at h = dx (to the noise of
  // the central difference that applies it, about 2e-9 of c_p^2) and loses it when the particles
  // move: an O(1) error in the second derivative.
  LatticeMethodSettings ul = s;
  ul.smoothingLengthRatio = 1.0;
  EXPECT_LT(jitteredCloudSpectrum<1>("ulsph", ul, 32, 0.0, 1).quadraticResidual, 1e-8);
  EXPECT_GT(jitteredCloudSpectrum<1>("ulsph", ul, 32, 0.1, 1).quadraticResidual, 1);
}

TEST(JitteredCloud, IrregularCloudsGrowWhereLatticesDoNot) {
  LatticeMethodSettings s;
  s.rkSupportRatio = 2.0;
  // RK collocation (m = 2, a = 2 dx) is stable on the 2-D lattice and flutters on every 10 %
  // jittered cloud tried: complex omega^2 of about 1.5 % of omega^2_max.
  // Central difference at 0.9 of each operator's limit confirms both: bounded on the lattice,
  // growing on the clouds as much as the spectrum says.
  const JitteredCloudReport lattice = jitteredCloudSpectrum<2>("rkcm", s, 12, 0.0, 1, 2000);
  EXPECT_EQ(lattice.status, "ok");
  EXPECT_LT(lattice.lowestModeError, 0.02);
  EXPECT_EQ(lattice.confirmation, "bounded as predicted");
  EXPECT_LT(lattice.measuredLogGrowth, std::log(10.0));
  for (std::uint64_t seed : {1, 2, 3}) {
    const JitteredCloudReport r = jitteredCloudSpectrum<2>("rkcm", s, 12, 0.1, seed, 2000);
    EXPECT_EQ(r.status, "growing") << seed;
    EXPECT_GT(r.imaginaryRatio, 0.01) << seed;
    EXPECT_EQ(r.confirmation, "grew as predicted") << seed;
    EXPECT_GT(r.measuredLogGrowth, 0.5 * r.predictedLogGrowth) << seed;
  }
  // The consistent very weak SPH (h = 1.3 dx) likewise: a complex pair of 0.2 % at 10 % jitter.
  const JitteredCloudReport vw = jitteredCloudSpectrum<2>("vwsph_consistent", LatticeMethodSettings{}, 12, 0.1, 1);
  EXPECT_EQ(vw.status, "growing");
  EXPECT_GT(vw.imaginaryRatio, 1e-3);
  // The updated-Lagrangian SPH linearised about rest has no growing mode on the same clouds.
  EXPECT_EQ(jitteredCloudSpectrum<2>("ulsph", LatticeMethodSettings{}, 12, 0.25, 1).status, "ok");
}

TEST(JitteredCloud, BadArgumentsNameTheirKey) {
  LatticeMethodSettings s;
  auto keyOf = [](auto&& call) {
    try {
      call();
    } catch (const InputError& e) {
      return e.key();
    }
    return std::string("none");
  };
  EXPECT_EQ(keyOf([&] { jitteredCloudSpectrum<2>("finite_difference", s, 12, 0.1, 1); }), "method");
  EXPECT_EQ(keyOf([&] { jitteredCloudSpectrum<2>("rkcm", s, 12, 0.5, 1); }), "jitter");
  EXPECT_EQ(keyOf([&] { jitteredCloudSpectrum<2>("rkcm", s, 2, 0.1, 1); }), "cells");
  // Two supports of a 2 dx cubic spline (8 dx) do not fit a 6-cell tile's copies.
  s.smoothingLengthRatio = 2.0;
  EXPECT_EQ(keyOf([&] { jitteredCloudSpectrum<2>("vwsph_published", s, 6, 0.1, 1); }), "cells");
}
