// lib/studies/lamb3d/LambCollocationCase: the plane-strain Lamb problem of data/scenes/lamb2d.toml
// by RK collocation at dx = 0.5 (561 nodes, a fraction of a second): the lattice nodes, the stable
// step, every probe scored against the exact response (an interior probe's interpolated value is the
// state itself: raw = reported), the notes on the fixed faces' first reflection (after the error
// window, or inside it when the window is longer) and the files; and the 3-D problem of
// data/scenes/lamb3d.toml at dx = 0.5 (3375 nodes, a / h = 2.2) with its measured errors.

#include "core/Error.hpp"
#include "LambCaseScene.hpp"
#include "studies/lamb3d/LambCollocationCase.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace mfwave::lamb3d {
namespace {

namespace fs = std::filesystem;
using testing::anyNoteHas;
using testing::lamb2dCaseStudy;
using testing::lamb3dCaseStudy;

CaseSettings rkCase(const Scene& scene, Real supportRatio = 2.5) {
  CaseSettings c;
  c.name = "rk_0.5";
  c.geometry = scene.geometry;
  c.writeFrames = true;
  CollocationSpec spec;
  spec.order = 2;
  spec.supportRatio = supportRatio;
  c.collocation = spec;
  return c;
}

TEST(LambCollocationCase, RunsThePlaneStrainLambProblemAndScoresEveryProbe) {
  const StudySettings study = lamb2dCaseStudy({"geometry.spacing=0.5"}, 6.0);
  const fs::path folder = fs::temp_directory_path() / "mfwave-lamb-collocation-case";
  fs::remove_all(folder);
  fs::create_directories(folder);
  const CaseResult r = runCollocationCase(study, rkCase(study.scene), folder.string(), false);
  EXPECT_EQ(r.record.particles, 33 * 17);  // the lattice's nodes, no ghosts
  EXPECT_EQ(r.settings.methodLabel(), "rk m=2 a/h=2.5");
  EXPECT_GT(r.record.stableTimeStep, 0.14);  // 2 / omega_max: 0.1463 from the dense spectrum
  EXPECT_LT(r.record.stableTimeStep, 0.147);
  // integrator.cfl = 0.5, rounded down to a whole number of steps to the end time
  EXPECT_LE(r.record.timeStep, 0.5 * r.record.stableTimeStep * (1 + 1e-12));
  EXPECT_GT(r.record.timeStep, 0.45 * r.record.stableTimeStep);
  EXPECT_GT(r.meanNeighbours, 15);
  ASSERT_EQ(r.probes.size(), 3u);
  testing::expectEveryProbeScoredAsRaw(r);
  // Measured (dx = 0.5 is coarse: the load's strip is two spacings wide).
  EXPECT_NEAR(r.probes[0].reported.relativeL2, 0.347, 0.01);  // centre
  EXPECT_NEAR(r.probes[1].reported.relativeL2, 0.663, 0.02);  // receiver
  EXPECT_NEAR(r.probes[2].reported.relativeL2, 0.278, 0.01);  // buried
  EXPECT_EQ(r.record.primaryError, "largest_relative_l2");
  EXPECT_TRUE(anyNoteHas(r.notes, "reaches a probe at t = 7.79 (13.5 / c_p from the load's patch via the +x face"));
  EXPECT_TRUE(anyNoteHas(r.notes, "after the error window 6"));
  EXPECT_TRUE(anyNoteHas(r.notes, "31 traction rows on the loaded face, 65 displacement rows"));
  for (const char* file : {"exact.csv", "rk_0.5-probes.csv"}) EXPECT_TRUE(fs::exists(folder / file)) << file;
  EXPECT_EQ(r.files, (std::vector<std::string>{"exact.csv", "rk_0.5-probes.csv"}));
  fs::remove_all(folder);
}

TEST(LambCollocationCase, SaysWhenTheFixedFacesReflectIntoTheErrorWindowAndRefuses1d) {
  const StudySettings study = lamb2dCaseStudy({"geometry.spacing=0.5", "integrator.end_time=8.0"}, 8.0);
  const fs::path folder = fs::temp_directory_path() / "mfwave-lamb-collocation-window";
  fs::create_directories(folder);
  const CaseResult r = runCollocationCase(study, rkCase(study.scene), folder.string(), false);
  EXPECT_TRUE(anyNoteHas(r.notes, "INSIDE the error window 8"));
  fs::remove_all(folder);

  StudySettings oneD = study;
  oneD.scene.info.dimension = 1;
  try {
    runCollocationCase(oneD, rkCase(study.scene), folder.string(), false);
    FAIL() << "a 1-D scene is refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method.name");
  }
}

// The 3-D Lamb problem at the paper's spacing 0.5 (15^3 nodes) with the widest stable 3-D support,
// a / h = 2.2: the top face's traction rows without its edges, the measured step and errors, and the
// note that the fixed side faces reflect into the error window.
TEST(LambCollocationCase, RunsThe3dLambProblemAndScoresEveryProbe) {
  const StudySettings study = lamb3dCaseStudy({"output.vtk=false"}, 6.0);
  const fs::path folder = fs::temp_directory_path() / "mfwave-lamb-collocation-3d";
  fs::remove_all(folder);
  fs::create_directories(folder);
  const CaseResult r = runCollocationCase(study, rkCase(study.scene, 2.2), folder.string(), false);
  EXPECT_EQ(r.record.particles, 15 * 15 * 15);
  EXPECT_EQ(r.settings.methodLabel(), "rk m=2 a/h=2.2");
  EXPECT_GT(r.record.stableTimeStep, 0.114);
  EXPECT_LT(r.record.stableTimeStep, 0.118);
  EXPECT_LE(r.record.timeStep, 0.5 * r.record.stableTimeStep * (1 + 1e-12));
  EXPECT_GT(r.record.timeStep, 0.45 * r.record.stableTimeStep);
  ASSERT_EQ(r.probes.size(), 3u);
  testing::expectEveryProbeScoredAsRaw(r);
  // Measured.
  EXPECT_NEAR(r.probes[0].reported.relativeL2, 0.281, 0.01);    // centre
  EXPECT_NEAR(r.probes[1].reported.relativeL2, 0.505, 0.02);  // receiver
  EXPECT_NEAR(r.probes[2].reported.relativeL2, 0.368, 0.01);    // buried
  // the top face's 13 x 13 inner nodes carry traction rows; its edges and the other faces, the
  // remaining 15^3 - 13^3 - 169 = 1009 boundary nodes, displacement rows
  EXPECT_TRUE(anyNoteHas(r.notes, "169 traction rows on the loaded face, 1009 displacement rows"));
  EXPECT_TRUE(anyNoteHas(r.notes, "reaches a probe at t = 2.6 (4.5 / c_p from the load's patch via the +x face to probe receiver"));
  EXPECT_TRUE(anyNoteHas(r.notes, "INSIDE the error window 6"));
  fs::remove_all(folder);
}

}  // namespace
}  // namespace mfwave::lamb3d
