// lib/studies/lamb3d/LambCollocationCase: the plane-strain Lamb problem of data/scenes/lamb2d.toml
// by RK collocation at dx = 0.5 (561 nodes, a fraction of a second): the lattice nodes, the stable
// step, every probe scored against the exact response (an interior probe's interpolated value is the
// state itself: raw = reported), the notes on the fixed faces' first reflection (after the error
// window, or inside it when the window is longer) and the files; a 3-D scene is refused.

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

CaseSettings rkCase(const Scene& scene) {
  CaseSettings c;
  c.name = "rk_0.5";
  c.geometry = scene.geometry;
  c.writeFrames = true;
  CollocationSpec spec;
  spec.order = 2;
  spec.supportRatio = 2.5;
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
  for (const ProbeResult& p : r.probes) {
    EXPECT_TRUE(p.hasExact) << p.name;
    EXPECT_EQ(p.raw.relativeL2, p.reported.relativeL2) << p.name;
  }
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

TEST(LambCollocationCase, SaysWhenTheFixedFacesReflectIntoTheErrorWindowAndRefuses3d) {
  const StudySettings study = lamb2dCaseStudy({"geometry.spacing=0.5", "integrator.end_time=8.0"}, 8.0);
  const fs::path folder = fs::temp_directory_path() / "mfwave-lamb-collocation-window";
  fs::create_directories(folder);
  const CaseResult r = runCollocationCase(study, rkCase(study.scene), folder.string(), false);
  EXPECT_TRUE(anyNoteHas(r.notes, "INSIDE the error window 8"));
  fs::remove_all(folder);

  StudySettings threeD = study;
  threeD.scene.info.dimension = 3;
  try {
    runCollocationCase(threeD, rkCase(study.scene), folder.string(), false);
    FAIL() << "a 3-D scene is refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method.name");
  }
}

}  // namespace
}  // namespace mfwave::lamb3d
