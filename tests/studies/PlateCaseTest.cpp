// lib/studies/plate: the plate's particles (a cell-centred lattice that fills the plate exactly, with
// the clamp columns behind x = 0 and the tip column at x = L - dp / 2) and the tip analysis that
// both methods' runs share (period, references, expected amplitude, the record's errors).

#include "studies/plate/PlateCase.hpp"
#include "studies/plate/PlateLattice.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfwave::plate {
namespace {

TEST(PlateLattice, FillsThePlateAndPutsTheClampBehindTheRoot) {
  const Real length = 0.2, thickness = 0.02, lowerY = -0.01;
  const PlateLattice p = cellCentredPlate(length, thickness, lowerY, 5, 3);
  EXPECT_EQ(p.rows, 5);
  EXPECT_EQ(p.columns, 50);
  EXPECT_NEAR(p.spacing, 0.004, 1e-15);
  ASSERT_EQ(p.particles.physicalCount(), (50 + 3) * 5);
  ASSERT_EQ(p.clamp.size(), 15u);
  ASSERT_EQ(p.tip.size(), 5u);
  Real plateVolume = 0;
  for (Index i = 0; i < p.particles.physicalCount(); ++i)
    if (p.particles.position(i)[0] > 0) plateVolume += p.particles.volume[static_cast<std::size_t>(i)];
  EXPECT_NEAR(plateVolume, length * thickness, 1e-15);  // the plate's mass is rho L H
  for (Index i : p.clamp) {
    EXPECT_LT(p.particles.position(i)[0], 0);
    EXPECT_GT(p.particles.position(i)[0], -3 * p.spacing);
  }
  for (std::size_t k = 0; k < p.tip.size(); ++k) {
    const Vec2 x = p.particles.position(p.tip[k]);
    EXPECT_NEAR(x[0], length - 0.5 * p.spacing, 1e-15);
    EXPECT_NEAR(x[1], lowerY + (static_cast<Real>(k) + 0.5) * p.spacing, 1e-15);  // bottom to top
  }
}

TEST(PlateTipAnalysis, MeasuresThePeriodAndScoresItAgainstTheReferences) {
  const Material steelLike = Material::fromYoung(2e6, 0.3975, 1000);
  const CantileverPlate plate(0.2, 0.02, steelLike);
  const Real period = 0.26, amplitude = 1e-3, endTime = 10 * period;
  TimeSeries tip("t [s]", {"u_x [m]", "u_y [m]", "v_x [m/s]", "v_y [m/s]"});
  for (int k = 0; k <= 20000; ++k) {
    const Real t = endTime * k / 20000;
    tip.append(t, {0, amplitude * std::sin(2 * kPi * t / period), 0, 0});
  }
  PlateCaseResult r;
  r.settings.name = "synthetic";
  r.settings.endTime = endTime;
  r.tipStartVelocity = 2 * kPi * amplitude / period;
  analyseTip(r, tip, plate, Real(5) / 6);
  EXPECT_NEAR(r.tip.period, period, 1e-4 * period);
  EXPECT_NEAR(r.expectedAmplitude, amplitude, 1e-4 * amplitude);
  EXPECT_NEAR(r.thinPeriod, plate.period(), 1e-15);
  EXPECT_NEAR(r.timoshenkoError(), period / plate.timoshenkoPeriod(Real(5) / 6) - 1, 1e-4);
  EXPECT_NEAR(r.periodsRun(), 10, 1e-3);
  ASSERT_EQ(r.record.errors.size(), 3u);
  EXPECT_EQ(r.record.primaryError, "abs_period_error_timoshenko");
  EXPECT_NEAR(r.record.errors[2].second, std::abs(r.timoshenkoError()), 1e-15);
  EXPECT_TRUE(r.notes.empty());

  // A tip that never turns has no period, and the case says so.
  TimeSeries still("t [s]", {"u_x [m]", "u_y [m]", "v_x [m/s]", "v_y [m/s]"});
  for (int k = 0; k <= 100; ++k) still.append(0.01 * k, {0, 1e-6 * k, 0, 0});
  PlateCaseResult s;
  s.settings.name = "still";
  analyseTip(s, still, plate, Real(5) / 6);
  ASSERT_EQ(s.notes.size(), 1u);
  EXPECT_NE(s.notes[0].find("fewer than two half periods"), std::string::npos);
}

}  // namespace
}  // namespace mfwave::plate
