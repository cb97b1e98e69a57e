// The sources' dominant frequency: the Ricker wavelet's peak, the load rate's spectral peak otherwise.
#include "catalogue/SourceFrequency.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfwave {
namespace {

TEST(SourceFrequency, ARickerWaveletPeaksAtItsPeakFrequency) {
  EXPECT_DOUBLE_EQ(dominantFrequency(TimeFunction::ricker(4.0, 0.3), 2.0), 4.0);
}

TEST(SourceFrequency, TheTrianglePulsesRateSpectrumPeaksWhereTanPiNuIsTwoPiNu) {
  // Ding-Long-Wu's triangle (rise = fall = 1): F(nu) = sinc^2(nu), so |R| = 2 pi nu |F| is
  // |sin^2(pi nu)| / (pi nu), whose maximum solves tan(pi nu) = 2 pi nu: nu = 0.371046.
  std::string rule;
  const Real nu = dominantFrequency(TimeFunction::triangle(0, 1, 1), 10.0, &rule);
  EXPECT_NEAR(nu, 0.371046, 2e-3);
  EXPECT_EQ(rule, "peak of the load rate's amplitude spectrum");
  // Twice as long, half the frequency.
  EXPECT_NEAR(dominantFrequency(TimeFunction::triangle(0, 2, 2), 10.0), 0.371046 / 2, 1e-3);
}

TEST(SourceFrequency, ARampFallsBackToTheHalfMaximum) {
  // The rate of a ramp over d is a box: |R| = |sinc(nu d)|, half its maximum at nu d = 0.6034.
  std::string rule;
  const Real nu = dominantFrequency(TimeFunction::ramp(0, 0.5), 4.0, &rule);
  EXPECT_EQ(rule, "half-maximum of the load rate's amplitude spectrum");
  EXPECT_NEAR(nu * 0.5, 0.6034, 0.02);
}

TEST(SourceFrequency, AConstantHasNone) { EXPECT_EQ(dominantFrequency(TimeFunction::constant(2), 1.0), 0.0); }

}  // namespace
}  // namespace mfwave
