// lib/studies/wave1d: one case of the standing wave converges at second order in dx with central
// differences at a fixed fraction of the stable step, and a step above an integrator's limit is
// refused (exit 2) before any case runs, unless stability.allow_growth asks for it.

#include "core/Error.hpp"
#include "io/scene/LoadScene.hpp"
#include "studies/wave1d/Wave1dCase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace mfwave::wave1d {
namespace {

Study barStudy(const std::string& cfl, const std::string& stability = "") {
  const std::string text = R"(
[scene]
name = "wave1d"
dimension = 1
[geometry]
shape = "line"
lower = [0.0]
upper = [1.0]
spacing = 0.0625
[material]
density = 1.0
lambda = 0.0
mu = 0.5
[method]
name = "finite_difference"
[[boundary]]
faces = ["-x", "+x"]
type = "fixed"
[integrator]
name = "central_difference"
cfl = )" + cfl + R"(
end_time = 2.3
)" + stability;
  SceneReader reader = parseScene(text, "wave1d.toml", {}, SceneSchema::common());
  Study study;
  study.scene = readScene(reader);
  study.cells = {16, 32};
  study.integrators = {"central_difference", "newmark"};
  return study;
}

TEST(Wave1dCase, CentralDifferenceConvergesAtSecondOrder) {
  const Study study = barStudy("0.5");
  const CaseResult coarse = runCase(study, "central_difference", 16, "", false);
  const CaseResult fine = runCase(study, "central_difference", 32, "", false);
  const Real order = std::log(coarse.error / fine.error) / std::log(2.0);
  EXPECT_NEAR(order, 2.0, 0.1) << coarse.error << " -> " << fine.error;
  EXPECT_LT(fine.error, 1e-2);
  EXPECT_EQ(fine.record.particles, 33);
  EXPECT_NEAR(fine.record.stableTimeStep, 1.0 / 32, 1e-12);  // dx / c, c = 1
  EXPECT_LE(fine.record.timeStep, 0.5 * fine.record.stableTimeStep * (1 + 1e-12));
  EXPECT_NEAR(fine.record.steps * fine.record.timeStep, 2.3, 1e-9);
  EXPECT_LT(std::abs(fine.energyDrift), 1e-3);
  EXPECT_TRUE(fine.files.empty());
}

TEST(Wave1dCase, StepsAboveTheLimitAreRefusedBeforeAnyCase) {
  Study above = barStudy("1.2");
  EXPECT_THROW(refuseStepsAboveTheLimit(above), InputError);
  Study onPurpose = barStudy("1.2", "[stability]\nallow_growth = true\n");
  refuseStepsAboveTheLimit(onPurpose);
  EXPECT_EQ(onPurpose.notes.size(), 2u);  // central differences at both resolutions (Newmark has no limit)
  Study below = barStudy("0.9");
  refuseStepsAboveTheLimit(below);
  EXPECT_TRUE(below.notes.empty());
}

}  // namespace
}  // namespace mfwave::wave1d
