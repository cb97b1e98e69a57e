// lib/wiring/VeryWeakSphScene: a scene's faces and loads become the very weak SPH problem's
// settings (transmitting, traction, fixed and moving faces, patches, the method's switches), and
// every combination the method or the integrator cannot run is refused when the scene is read.

#include "core/Error.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/Scene.hpp"
#include "io/scene/SceneError.hpp"
#include "particles/BoxFace.hpp"
#include "wiring/VeryWeakSphScene.hpp"
#include "wiring/VeryWeakSphSpec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace mfwave {
namespace {

const std::string kBlock = R"(
[scene]
name = "strip"
dimension = 2

[geometry]
shape = "rectangle"
lower = [0.0, 0.0]
upper = [2.0, 1.0]
spacing = 0.25

[material]
density = 1.0
lambda = 1.0
mu = 1.0

[[boundary]]
faces = ["+x"]
type = "transmitting"

[[boundary]]
faces = ["-x"]
type = "fixed"

[[boundary]]
faces = ["-y"]
type = "displacement"
value = [0.0, 0.002]
time_function = { type = "ramp", duration = 0.5 }

[[boundary]]
faces = ["+y"]
type = "traction"
traction = [0.5, 0.0]

[[load]]
type = "surface_patch"
face = "+y"
centre = [1.0, 1.0]
half_width = [0.25, 0.0]
traction = [0.0, -1.0]
time_function = { type = "triangle", start = 0.0, rise = 1.0, fall = 1.0 }
)";

struct Read {
  SceneReader reader;
  Scene scene;
  VeryWeakSphSpec spec;
};

Read read(const std::string& method, const std::string& integrator = "central_difference") {
  SceneSchema schema = SceneSchema::common();
  addVeryWeakSphKeys(schema);
  Read r{parseScene(kBlock + "[method]\nname = \"very_weak_sph\"\n" + method + "\n[integrator]\nname = \"" +
                        integrator + "\"\nend_time = 1.0\n",
                    "strip.toml", {}, schema),
         {}, {}};
  r.scene = readScene(r.reader);
  r.spec = readVeryWeakSph(r.reader, r.scene.material.material());
  r.reader.checkAllKeysRead();
  return r;
}

std::string refusedKey(const Read& r) {
  try {
    checkVeryWeakSphScene(r.reader, r.scene, r.spec, "test");
  } catch (const InputError& e) {
    return e.key();
  }
  return "";
}

TEST(VeryWeakSphScene, EveryFaceAndLoadReachesTheProblem) {
  const Read r = read("variant = \"published\"\nsmoothing_length_ratio = 1.5\ndashpot_lumping = \"consistent\"\n"
                      "smoothing_rate = 0.3\ndeconvolution = true\n");
  EXPECT_EQ(refusedKey(r), "");
  const VeryWeakSphProblemSettings<2> s = veryWeakSphProblemSettings<2>(r.scene, r.scene.geometry, r.spec);
  EXPECT_EQ(s.options.variant, VeryWeakSphVariant::Published);
  EXPECT_DOUBLE_EQ(s.smoothingLength, 1.5 * 0.25);
  EXPECT_EQ(s.dashpotLumping, DashpotLumping::Consistent);
  EXPECT_EQ(s.transmittingFaces, faceBit(BoxFace::PlusX));
  ASSERT_EQ(s.faceTractions.size(), 1u);
  EXPECT_EQ(s.faceTractions[0].faces, faceBit(BoxFace::PlusY));
  EXPECT_EQ(s.faceTractions[0].traction, Vec2(0.5, 0));
  ASSERT_EQ(s.prescribed.size(), 2u);  // in the scene's order: the fixed face, then the moving one
  EXPECT_EQ(s.prescribed[0].faces, faceBit(BoxFace::MinusX));
  EXPECT_EQ(s.prescribed[0].history, nullptr);
  EXPECT_EQ(s.prescribed[1].faces, faceBit(BoxFace::MinusY));
  EXPECT_EQ(s.prescribed[1].value, Vec2(0, 0.002));
  ASSERT_NE(s.prescribed[1].history, nullptr);
  EXPECT_DOUBLE_EQ((*s.prescribed[1].history)(0.25), 0.5);
  ASSERT_EQ(s.patches.size(), 1u);
  EXPECT_EQ(s.patches[0].face, static_cast<int>(BoxFace::PlusY));
  EXPECT_EQ(s.patches[0].centre, Vec2(1, 1));
  EXPECT_EQ(s.patches[0].halfWidths, Vec2(0.25, 0));
  EXPECT_EQ(s.patches[0].traction, Vec2(0, -1));
  EXPECT_DOUBLE_EQ(s.smoothingRate, 0.3);
  EXPECT_TRUE(s.deconvolution);
  EXPECT_EQ(s.upper, Vec2(2, 1));
  EXPECT_DOUBLE_EQ(s.spacing, 0.25);
  // All faces free: no dashpots, no face tractions, nothing prescribed; the patch stays.
  const VeryWeakSphProblemSettings<2> free = veryWeakSphProblemSettings<2>(r.scene, r.scene.geometry, r.spec, false);
  EXPECT_EQ(free.transmittingFaces, 0);
  EXPECT_TRUE(free.faceTractions.empty());
  EXPECT_TRUE(free.prescribed.empty());
  EXPECT_EQ(free.patches.size(), 1u);
  // The loads act until the triangle ends at t = 2; the traction face's constant history never
  // goes quiet.
  EXPECT_TRUE(std::isinf(loadsQuietAfter(r.scene)));
}

TEST(VeryWeakSphScene, RefusesBeforeAnyWorkWhatCannotRun) {
  EXPECT_EQ(refusedKey(read("variant = \"galerkin\"\ndeconvolution = true\n")), "method.deconvolution");
  EXPECT_EQ(refusedKey(read("variant = \"galerkin\"\ndeconvolution = false\nsmoothing_rate = 0.2\n")),
            "method.smoothing_rate");
  EXPECT_EQ(refusedKey(read("variant = \"consistent\"\nsmoothing_rate = 0.2\n", "newmark")), "method.smoothing_rate");
  // prescribed faces (eq. 30) are the central difference's; the scene's refusals name where
  const Read newmark = read("variant = \"galerkin\"\ndeconvolution = false\n", "newmark");
  EXPECT_EQ(refusedKey(newmark), "boundary");
  try {
    checkVeryWeakSphScene(newmark.reader, newmark.scene, newmark.spec, "test");
    FAIL() << "prescribed faces with newmark must be refused";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("strip.toml"), std::string::npos) << e.what();
  }
}

// The method's own refusals (checkVeryWeakSphCombination knows no scene) are said again by the
// scene reader, with the file and line of the key.
TEST(VeryWeakSphScene, LocatesTheMethodsRefusalsInTheScene) {
  const Read r = read("variant = \"galerkin\"\ndeconvolution = true\n");
  try {
    checkVeryWeakSphScene(r.reader, r.scene, r.spec, "test");
    FAIL() << "deconvolution with the galerkin variant must be refused";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key(), "method.deconvolution");
    EXPECT_NE(e.location().find("strip.toml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no kernel estimate to deconvolve"), std::string::npos) << e.what();
    EXPECT_EQ(e.problem().find("strip.toml"), std::string::npos) << "the problem alone, without the location";
  }
}

}  // namespace
}  // namespace mfwave
