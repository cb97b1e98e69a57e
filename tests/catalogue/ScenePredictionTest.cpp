// The plan's predictions against what runs measure: the phase error of every lattice method against
// the plane-wave study's measured error (within a factor of 1.5), and the plan of a shipped scene.
#include "catalogue/CatalogueScene.hpp"
#include "catalogue/PlanReport.hpp"
#include "catalogue/RowSpectrum.hpp"
#include "catalogue/ScenePrediction.hpp"

#include "spectra/LatticeMethods.hpp"
#include "spectra/SpectralElementDispersion.hpp"
#include "studies/planewave/PlaneWaveRun.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfwave {
namespace {

struct PlaneWaveCase {
  std::string method;
  int dimension;
  int cells;
  bool shear;
};

// The relative L2 error the plan predicts for the plane-wave run `s` (stepped at `dt`): the phase
// lag of the row's branch and the integrator over s.periods periods.
template <int D>
Real predictedPlaneWaveError(const planewave::Settings& s, Real dt) {
  const Real dx = 1.0 / s.cells;
  Vec<D> k = Vec<D>::Zero();
  k[0] = 2 * kPi * s.wavelengths;
  const Real speed = s.shear ? s.lattice.material.sWaveSpeed() : s.lattice.material.pWaveSpeed();
  const IntegratorKind kind = integratorKind(s.integrator);
  if (s.method == "spectral_element") {
    const Real omega = speed * k.norm();
    const Real omegaH = spectralElementFrequency(s.semOrder, dx, speed, k.norm());
    return planeWaveError(std::abs(discreteFrequency(omegaH, dt, kind) / omega - 1), s.periods);
  }
  const auto row = latticeMethodStencil<D>(s.method, s.lattice, dx);
  return planeWaveError(wavePhaseError<D>(row, k, s.shear, speed, dt, kind).total, s.periods);
}

class PredictedPlaneWave : public ::testing::TestWithParam<PlaneWaveCase> {};

TEST_P(PredictedPlaneWave, IsWithinAFactorOfTwoOfTheMeasuredError) {
  const PlaneWaveCase& c = GetParam();
  planewave::Settings s;
  s.dimension = c.dimension;
  s.method = c.method;
  s.integrator = "central_difference";
  s.cells = c.cells;
  s.wavelengths = 2;
  s.periods = 2;
  s.cfl = 0.5;
  s.shear = c.shear;
  s.lattice.smoothingLengthRatio = 1.3;
  s.semOrder = c.method == "spectral_element" && c.cells == 16 ? 2 : 4;
  const planewave::Outcome run = planewave::runPlaneWave(s);
  const Real predicted = c.dimension == 1   ? predictedPlaneWaveError<1>(s, run.record.timeStep)
                         : c.dimension == 2 ? predictedPlaneWaveError<2>(s, run.record.timeStep)
                                            : predictedPlaneWaveError<3>(s, run.record.timeStep);
  RecordProperty("measured", std::to_string(run.error));
  RecordProperty("predicted", std::to_string(predicted));
  // The issue asks for a factor of 2; the row's symbol and the integrator's frequency map give the
  // measured error within 7 % for every lattice row here, and the spectral elements' Bloch analysis
  // within 25 % (2026-11-28: their S wave at N = 2, 16 cells, predicted 0.0159, measured 0.0212), so a
  // factor of 1.5 is asserted.
  EXPECT_GT(predicted, run.error / 1.5) << c.method << ": measured " << run.error << ", predicted " << predicted;
  EXPECT_LT(predicted, run.error * 1.5) << c.method << ": measured " << run.error << ", predicted " << predicted;
}

INSTANTIATE_TEST_SUITE_P(
    EveryLatticeMethod, PredictedPlaneWave,
    ::testing::Values(PlaneWaveCase{"finite_difference", 2, 32, false}, PlaneWaveCase{"finite_difference", 1, 16, false},
                      PlaneWaveCase{"vwsph_galerkin", 2, 32, false}, PlaneWaveCase{"vwsph_galerkin", 2, 32, true},
                      PlaneWaveCase{"vwsph_consistent", 2, 32, false}, PlaneWaveCase{"rkcm", 2, 32, false},
                      PlaneWaveCase{"ulsph_corrected", 2, 32, false}, PlaneWaveCase{"ulsph", 2, 64, false},
                      PlaneWaveCase{"spectral_element", 2, 32, false}, PlaneWaveCase{"spectral_element", 2, 16, true},
                      PlaneWaveCase{"vwsph_galerkin", 3, 16, false}),
    [](const ::testing::TestParamInfo<PlaneWaveCase>& param) {
      return param.param.method + "_" + std::to_string(param.param.dimension) + "d_" +
             std::to_string(param.param.cells) + (param.param.shear ? "_s" : "_p");
    });

std::string shipped(const std::string& name) { return std::string(SCENES_FOLDER) + "/" + name; }

TEST(ScenePrediction, TheLambScenesPlanIsComplete) {
  const auto read = readCatalogueScene(shipped("lamb3d.toml"), {});
  ASSERT_TRUE(read.has_value());
  const Prediction p = predictScene(read->scene, read->choice);
  EXPECT_EQ(p.particles, 15 * 15 * 15);
  EXPECT_EQ(p.method, "very_weak_sph (galerkin)");
  EXPECT_TRUE(p.hasSource);
  EXPECT_NEAR(p.frequency, 0.371, 0.003);
  // The S wave at 0.371 Hz is 2.7 long: 5.4 spacings of 0.5.
  EXPECT_NEAR(p.pointsPerWavelength, 1.0 / 0.371 / 0.5, 0.05);
  EXPECT_GT(p.phaseError, 0.01);
  EXPECT_LT(p.phaseError, 0.2);
  // Halving the spacing: a second-order row's error falls about four times.
  const Prediction fine = predictScene(read->scene, read->choice, 0.25);
  EXPECT_EQ(fine.particles, 29 * 29 * 29);
  EXPECT_NEAR(p.phaseError / fine.phaseError, 4, 1);
  EXPECT_NEAR(fine.stableStep, p.stableStep / 2, 1e-9 * p.stableStep);
  const nlohmann::json j = predictionJson(p);
  for (const char* key : {"particles", "memory_bytes", "stable_step", "steps", "wall_seconds", "phase_error"})
    EXPECT_TRUE(j.contains(key) && !j[key].is_null()) << key;
}

TEST(ScenePrediction, ATargetNamesTheCheapestRunThatReachesIt) {
  const auto read = readCatalogueScene(shipped("lamb2d.toml"), {});
  ASSERT_TRUE(read.has_value());
  const TargetAnswer answer = cheapestForTarget(read->scene, 0.01, 24.0 * 1024 * 1024 * 1024);
  ASSERT_TRUE(answer.found);
  EXPECT_LE(answer.best.phaseError, 0.01);
  for (const Prediction& p : answer.candidates)
    if (p.phaseError <= 0.01) {
      EXPECT_GE(p.wallSeconds, answer.best.wallSeconds);
    }
  // The published very weak SPH does not converge: never proposed.
  for (const Prediction& p : answer.candidates) EXPECT_EQ(p.method.find("published"), std::string::npos);
}

TEST(ScenePrediction, AMethodThatCannotRepresentTheSceneIsRefusedByName) {
  try {
    readCatalogueScene(shipped("block-ricker.toml"), {"method.name=spectral_element"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "load[0].type") << e.what();
    EXPECT_NE(std::string(e.what()).find("supported by: finite_difference"), std::string::npos) << e.what();
  } catch (...) {
    FAIL() << "another error";
  }
}

}  // namespace
}  // namespace mfwave

namespace mfwave {
namespace {

TEST(ScenePrediction, TheUlSphOnALambSceneIsPlannedAsTheLambStudyStepsIt) {
  // The Lamb study runs the UL-SPH at its own criteria 0.3 h / (c_p (1 + 1.2 alpha)) with h = 1.3 dx
  // and alpha = 1 unless the scene sets method.viscosity_alpha: at dx = 0.25 the run's step is
  // 0.02559 (lamb2d, measured).
  const auto read = readCatalogueScene(shipped("lamb2d.toml"), {"method.name=updated_lagrangian_sph"});
  ASSERT_TRUE(read.has_value());
  const Prediction p = predictScene(read->scene, read->choice);
  EXPECT_NEAR(p.stableStep, 0.3 * 1.3 * 0.25 / (std::sqrt(3.0) * 2.2), 1e-12);
  EXPECT_NEAR(p.stableStep, 0.02559, 1e-5);
  const auto inviscid =
      readCatalogueScene(shipped("lamb2d.toml"), {"method.name=updated_lagrangian_sph", "method.viscosity_alpha=0"});
  EXPECT_NEAR(predictScene(inviscid->scene, inviscid->choice).stableStep, 0.3 * 1.3 * 0.25 / std::sqrt(3.0), 1e-12);
}

}  // namespace
}  // namespace mfwave
