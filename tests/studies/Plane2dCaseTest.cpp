// lib/studies/plane2d: the interior spectrum refuses RK collocation where its 2-D rows have growing
// modes (a / h >= 3, exit 3) and lets a run there on purpose say so; a stable case converges
// against the manufactured solution.

#include "core/Error.hpp"
#include "io/scene/LoadScene.hpp"
#include "studies/plane2d/Plane2dCase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace mfwave::plane2d {
namespace {

Scene squareScene(const std::string& stability = "") {
  const std::string text = R"(
[scene]
name = "plane2d"
dimension = 2
[geometry]
shape = "rectangle"
lower = [0.0, 0.0]
upper = [1.0, 1.0]
spacing = 0.125
[material]
density = 1.0
lambda = 2.0
mu = 1.0
[method]
name = "reproducing_kernel"
[[boundary]]
faces = ["-x", "+x", "-y", "+y"]
type = "fixed"
[integrator]
name = "central_difference"
cfl = 0.5
end_time = 0.3
)" + stability;
  SceneSchema schema = SceneSchema::common();
  schema.addChoice("method.name", "reproducing_kernel");
  SceneReader reader = parseScene(text, "plane2d.toml", {}, schema);
  return readScene(reader);
}

TEST(Plane2dCase, GrowingInteriorModesAreRefusedUnlessAskedFor) {
  EXPECT_TRUE(checkInteriorStability(squareScene(), 2, 2.5).empty());
  EXPECT_THROW(checkInteriorStability(squareScene(), 2, 3.0), InstabilityError);
  const std::vector<std::string> notes =
      checkInteriorStability(squareScene("[stability]\nallow_growth = true\n"), 2, 3.0);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("growing modes"), std::string::npos);
}

TEST(Plane2dCase, ConvergesAgainstTheManufacturedSolution) {
  const Scene scene = squareScene();
  std::vector<std::string> notes;
  const CaseResult coarse = runCase(scene, 2, 2.5, 2 * kPi, 8, notes);
  const CaseResult fine = runCase(scene, 2, 2.5, 2 * kPi, 16, notes);
  EXPECT_TRUE(notes.empty());
  EXPECT_EQ(fine.record.particles, 17 * 17);
  EXPECT_LT(fine.errorU, 0.5 * coarse.errorU) << coarse.errorU << " -> " << fine.errorU;
  EXPECT_LE(fine.record.timeStep, 0.5 * fine.record.stableTimeStep * (1 + 1e-12));
}

}  // namespace
}  // namespace mfwave::plane2d
