// lib/studies/bar1d: one case of the fixed-free bar by RK collocation converges in h against the
// exact solution by characteristics, at a step within the exact spectrum's limit.

#include "io/scene/LoadScene.hpp"
#include "studies/bar1d/BarCollocationCase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace mfwave::bar1d {
namespace {

Study collocationBarStudy() {
  const std::string text = R"(
[scene]
name = "bar1d"
dimension = 1
[geometry]
shape = "line"
lower = [0.0]
upper = [10.0]
spacing = 0.5
[material]
density = 1.0
youngs_modulus = 10.0
poisson_ratio = 0.0
[method]
name = "reproducing_kernel"
[[boundary]]
faces = ["-x"]
type = "fixed"
[integrator]
name = "central_difference"
cfl = 0.5
end_time = 5.0
)";
  SceneSchema schema = SceneSchema::common();
  schema.addChoice("method.name", "reproducing_kernel");
  SceneReader reader = parseScene(text, "bar1d.toml", {}, schema);
  Study study;
  study.scene = readScene(reader);
  study.errorPoints = 501;
  study.errorSamples = 10;
  return study;
}

TEST(BarCollocationCase, ConvergesInHWithinTheSpectralStepLimit) {
  const Study study = collocationBarStudy();
  const CaseResult coarse = runCase(study, 21, "", false);
  const CaseResult fine = runCase(study, 81, "", false);
  EXPECT_NEAR(fine.h, 0.125, 1e-15);
  EXPECT_LT(fine.errorU, 0.6 * coarse.errorU) << coarse.errorU << " -> " << fine.errorU;
  EXPECT_LT(fine.errorU, 0.05);
  EXPECT_GE(fine.maxErrorU, 0);
  EXPECT_LE(fine.record.timeStep, 0.5 * fine.record.stableTimeStep * (1 + 1e-12));
  EXPECT_EQ(fine.record.primaryError, "relative_l2_u");
  EXPECT_TRUE(fine.notes.empty());
}

}  // namespace
}  // namespace mfwave::bar1d
