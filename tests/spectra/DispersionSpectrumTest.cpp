// The FFT dispersion spectrum (DispersionSpectrum) against closed forms and against the direct
// symbol sums of LatticeDispersion and CollocationStability.

#include "spectra/CollocationStability.hpp"
#include "numerics/DispersionSpectrum.hpp"
#include "spectra/MethodLatticeStencils.hpp"
#include "spectra/VeryWeakSphDispersion.hpp"
#include "core/Error.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

namespace {


// omega^2 of the second-order finite-difference Laplacian: (2 c / dx)^2 sum_j sin^2(k_j dx / 2).
template <int D>
Real finiteDifferenceOmegaSquared(const Vec<D>& k, Real dx, Real c) {
  Real sum = 0;
  for (int j = 0; j < D; ++j) sum += std::pow(std::sin(k(j) * dx / 2), 2);
  return std::pow(2 * c / dx, 2) * sum;
}

template <int D>
void checkFiniteDifferenceEverywhere(int cells) {
  const Real dx = 0.25, c = 2;
  const MethodLatticeStencil<D> fd = finiteDifferenceInteriorStencil<D>(dx, c);
  const DispersionSpectrum<D> spectrum(makePeriodicLatticeOperator<D>(fd.acceleration, dx, cells));
  const Real scale = std::pow(2 * c / dx, 2) * D;
  Real worst = 0;
  for (Index at = 0; at < spectrum.points(); ++at) {
    std::array<int, D> m{};
    Index rest = at;
    for (int d = 0; d < D; ++d) {
      m[static_cast<std::size_t>(d)] = static_cast<int>(rest % cells);
      rest /= cells;
    }
    const Vec<D> k = spectrum.wavevector(m);
    const auto modes = spectrum.modes(m, latticeAxis<D>());
    worst = std::max(worst, std::abs(modes[0].omegaSquared - finiteDifferenceOmegaSquared<D>(k, dx, c)) / scale);
  }
  EXPECT_LT(worst, 1e-14) << D << "-D";
  const auto extremes = spectrum.extremes();
  EXPECT_NEAR(extremes.largestOmegaSquared / scale, 1, 1e-14);
  EXPECT_NEAR(extremes.smallestOmegaSquared / scale, 0, 1e-14);
  EXPECT_LT(extremes.largestImaginaryRatio, 1e-14);
}

}  // namespace

TEST(DispersionSpectrum, FiniteDifferenceLaplacianMatchesTheClosedFormAtEveryLatticeWavenumber) {
  checkFiniteDifferenceEverywhere<1>(64);
  checkFiniteDifferenceEverywhere<2>(32);
  checkFiniteDifferenceEverywhere<3>(16);
}

TEST(DispersionSpectrum, FiniteDifferenceGroupSpeedAndPointsPerWavelengthAreTheClosedForm) {
  const Real dx = 0.5, c = 3;
  const int cells = 512;
  const DispersionSpectrum<1> spectrum(
      makePeriodicLatticeOperator<1>(finiteDifferenceInteriorStencil<1>(dx, c).acceleration, dx, cells));
  const auto line = spectrumLine(spectrum, LatticeDirection::Axis, Polarisation::Scalar, c);
  ASSERT_EQ(line.size(), 256u);
  Real worstPhase = 0, worstGroup = 0;
  for (const auto& s : line) {
    worstPhase = std::max(worstPhase, std::abs(s.phaseSpeedRatio - std::sin(s.kdx / 2) / (s.kdx / 2)));
    worstGroup = std::max(worstGroup, std::abs(s.groupSpeedRatio - std::cos(s.kdx / 2)));
  }
  // Round-off: omega^2 carries an absolute error of ~1e-16 of its largest value, so omega / k is
  // relatively worst at the smallest |k| dx (2 pi / 512): 1e-16 * 4 / kdx^2 / 2 ~ 1e-12.
  EXPECT_LT(worstPhase, 2e-12);
  EXPECT_LT(worstGroup, 2e-12);
  // sin(x/2)/(x/2) = 0.99 at x = 0.490636: 12.806 points per wavelength; the line samples |k| dx
  // every 2 pi / 512 and interpolates the error linearly in between.
  const AccuracyResolution one = lineAccuracy(line, 0.01);
  EXPECT_TRUE(one.attained);
  EXPECT_NEAR(one.kdx, 0.490636, 2e-5);
  EXPECT_NEAR(one.pointsPerWavelength, 12.8062, 5e-4);
}

TEST(DispersionSpectrum, FiniteDifferenceAnisotropyIsTheClosedForm) {
  // Along the 2-D diagonal omega dx / c = 2 sqrt(2) sin(kdx / (2 sqrt 2)).
  const Real dx = 1, c = 1;
  const DispersionSpectrum<2> spectrum(
      makePeriodicLatticeOperator<2>(finiteDifferenceInteriorStencil<2>(dx, c).acceleration, dx, 256));
  const auto axis = spectrumLine(spectrum, LatticeDirection::Axis, Polarisation::Scalar, c);
  const auto diagonal = spectrumLine(spectrum, LatticeDirection::Diagonal, Polarisation::Scalar, c);
  for (const auto& s : diagonal)
    EXPECT_NEAR(s.phaseSpeedRatio, 2 * std::sqrt(2.0) * std::sin(s.kdx / (2 * std::sqrt(2.0))) / s.kdx, 1e-12);
  const auto aniso = anisotropy(axis, diagonal);
  ASSERT_EQ(aniso.size(), 90u);  // diagonal samples with |k| dx = sqrt(2) 2 pi j / 256 <= pi
  for (const auto& a : aniso) {
    const Real exact = (2 * std::sqrt(2.0) * std::sin(a.kdx / (2 * std::sqrt(2.0)))) / (2 * std::sin(a.kdx / 2)) - 1;
    EXPECT_NEAR(a.ratioMinusOne, exact, 2e-5) << a.kdx;  // linear interpolation of the axis line
  }
  EXPECT_GT(aniso.back().ratioMinusOne, 0.1);  // the diagonal is faster near |k| dx = pi
}

TEST(DispersionSpectrum, VeryWeakSphAgreesWithTheDirectSymbolOnTheAxisAndDiagonalIn2DAnd3D) {
  const Material material = Material::fromLame(2, 1, 1.5);
  const auto check = [&](auto dimension) {
    constexpr int D = decltype(dimension)::value;
    const auto vw = veryWeakSphInteriorStencil<D>(VeryWeakSphDispersionVariant::Published, "cubic_spline", 1.3,
                                                  material, 0.5);
    const DispersionSpectrum<D> spectrum(makePeriodicLatticeOperator<D>(vw.stencil, 0.5, 16));
    for (LatticeDirection direction : {LatticeDirection::Axis, LatticeDirection::Diagonal})
      for (Polarisation polarisation : {Polarisation::P, Polarisation::S}) {
        const auto line = spectrumLine(spectrum, direction, polarisation, material.pWaveSpeed());
        const Vec<D> n = latticeDirectionVector<D>(direction);
        for (const auto& s : line) {
          const LatticeMode direct = latticeMode(vw.stencil, n, s.wavenumber, polarisation);
          if (std::isnan(direct.phaseSpeed)) {  // the published scheme has omega^2 < 0 at high k
            EXPECT_TRUE(std::isnan(s.phaseSpeedRatio)) << D << " " << s.kdx;
            continue;
          }
          EXPECT_NEAR(s.phaseSpeedRatio, direct.phaseSpeed / material.pWaveSpeed(), 1e-12) << D << " " << s.kdx;
          if (std::isfinite(direct.groupSpeed)) {
            EXPECT_NEAR(s.groupSpeedRatio, direct.groupSpeed / material.pWaveSpeed(), 1e-10) << D << " " << s.kdx;
          }
        }
      }
  };
  check(std::integral_constant<int, 2>());
  check(std::integral_constant<int, 3>());
}

TEST(DispersionSpectrum, CollocationWithItsMassSymbolAgreesWithLuoLiuHuangEq45) {
  // 1-D RK collocation (cubic B-spline, m = 2, a = 3.3 h): the FFT relation with M(k) against the
  // explicit stencil sums of CollocationStability (eq. (45)).
  const Real h = 0.5;
  const Material material = Material::fromYoung(10, 0, 1);
  const auto rk = collocationInteriorStencil<1>(CollocationBasis::ReproducingKernel, 2, 3.3, material, h);
  EXPECT_LT(rk.translationDifference, 1e-10);
  const DispersionSpectrum<1> spectrum(makePeriodicLatticeOperator<1>(rk.acceleration, h, 128, rk.mass));
  const auto line = spectrumLine(spectrum, LatticeDirection::Axis, Polarisation::P, material.pWaveSpeed());

  const Coordinates<1> nodes = uniformLine(201, h);
  const ReproducingKernelShapeFunctions<1> shapes(nodes, 2, 3.3 * h);
  const CollocationRows rows = collocationRows(shapes, nodes, 100, h);
  Real worst = 0, worstGroup = 0;
  for (const auto& s : line) {
    worst = std::max(worst, std::abs(s.phaseSpeedRatio - phaseSpeed(rows.stiffnessColumn, rows.massColumn, s.kdx, h)));
    worstGroup = std::max(worstGroup, std::abs(s.groupSpeedRatio - groupSpeed(rows.stiffnessColumn, rows.massColumn, s.kdx, h)));
  }
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(worstGroup, 1e-8);
}

TEST(DispersionSpectrum, BadInputIsRefusedWithTheKeyNamed) {
  const MethodLatticeStencil<2> fd = finiteDifferenceInteriorStencil<2>(1, 1);
  const auto key = [](auto&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.key();
    }
    return std::string("none");
  };
  EXPECT_EQ(key([&] { makePeriodicLatticeOperator<2>(fd.acceleration, 1, 15); }), "cells");  // odd
  EXPECT_EQ(key([&] { makePeriodicLatticeOperator<2>(fd.acceleration, 1, 2); }), "cells");   // reach 1 needs > 2
  EXPECT_EQ(key([&] { makePeriodicLatticeOperator<2>(fd.acceleration, 0.3, 16); }), "stencil");  // off the lattice
  EXPECT_EQ(key([&] { makePeriodicLatticeOperator<2>(fd.acceleration, -1, 16); }), "spacing");
  const DispersionSpectrum<2> spectrum(makePeriodicLatticeOperator<2>(fd.acceleration, 1, 16));
  EXPECT_EQ(key([&] { spectrumLine(spectrum, LatticeDirection::Axis, Polarisation::P, 1); }), "polarisation");
  EXPECT_EQ(key([&] { spectrumLine(spectrum, LatticeDirection::Axis, Polarisation::Scalar, 0); }), "reference_speed");
  EXPECT_EQ(key([&] { spectrum.modes({16, 0}, latticeAxis<2>()); }), "wavenumber_index");
  EXPECT_EQ(key([&] { parseLatticeDirection("sideways"); }), "direction");
}
