// lib/studies/lamb3d/LambSolidCase: the plane-strain Lamb problem of data/scenes/lamb2d.toml by the
// updated-Lagrangian SPH at dx = 0.5 (561 particles, a fraction of a second) and small amplitude: the
// lattice's particles without ghosts and with tributary masses, the strip's load (its end particles
// carry half: the total force is the strip's width times f(t), checked on the method's own
// accelerations), every probe scored against the exact response (measured errors), the notes; a 1-D
// scene is refused (3-D: LambSolidCase3dTest.cpp).

#include "core/Error.hpp"
#include "LambCaseScene.hpp"
#include "studies/lamb3d/LambSolidCase.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace mfwave::lamb3d {
namespace {

namespace fs = std::filesystem;
using testing::anyNoteHas;
using testing::lamb2dCaseStudy;

CaseSettings solidCase(const Scene& scene) {
  CaseSettings c;
  c.name = "ulsph_0.5";
  c.geometry = scene.geometry;
  c.writeFrames = true;
  c.solid = LambSolidSpec::linearDefaults(scene.material.material());
  return c;
}

TEST(LambSolidCase, TheStripsTotalForceIsItsWidthTimesTheLoad) {
  const StudySettings study = lamb2dCaseStudy({"geometry.spacing=0.5"}, 6.0);
  const Scene& scene = study.scene;
  const ParticleSet<2> particles = lambSolidParticles<2>(scene.geometry, true);
  ASSERT_EQ(particles.size(), 33 * 17);  // no ghosts
  EXPECT_EQ(particles.physicalCount(), 33 * 17);
  Real mass = 0;
  for (Index i = 0; i < particles.size(); ++i) mass += particles.volume[static_cast<std::size_t>(i)];
  EXPECT_NEAR(mass, 16.0 * 8.0, 1e-12);  // tributary areas fill the rectangle

  // x = -0.5, 0, 0.5 on the top face: the ends carry half their segment
  const PatchTraction strip = patchTraction<2>(scene.loads[0], particles, 0.5);
  ASSERT_EQ(strip.particles.size(), 3u);
  EXPECT_EQ(strip.measures, (std::vector<Real>{0.25, 0.5, 0.25}));
  EXPECT_DOUBLE_EQ(strip.totalMeasure(), 1.0);
  // At 0.25 five particles, the same total.
  const GeometrySpec finer = scene.geometry.withLattice(scene.geometry.lower, scene.geometry.upper, 0.25);
  EXPECT_DOUBLE_EQ(patchTraction<2>(scene.loads[0], lambSolidParticles<2>(finer, true), 0.25).totalMeasure(), 1.0);

  // The method's own forces at rest: sum m a = eps * width * T_y * f(t), f(0.5) = 0.5.
  const LambSolidSpec spec = LambSolidSpec::linearDefaults(scene.material.material());
  UpdatedLagrangianSph<2> system(particles, spec.options);
  applyPatchLoad<2>(system, scene.loads[0], strip, 1e-4);
  const Vector y0 = system.initialState();
  Vector ydot = Vector::Zero(y0.size());
  system.rhs(0.5, y0, ydot);
  Real forceX = 0, forceY = 0;
  for (Index i = 0; i < system.particleCount(); ++i) {
    const Real m = system.masses()[static_cast<std::size_t>(i)];
    forceX += m * ydot[system.layout().velocity(i, 0)];
    forceY += m * ydot[system.layout().velocity(i, 1)];
  }
  EXPECT_NEAR(forceX, 0.0, 1e-15);
  EXPECT_NEAR(forceY, 1e-4 * 1.0 * 0.5, 1e-15);
}

TEST(LambSolidCase, RunsThePlaneStrainLambProblemAtSmallAmplitudeAndScoresEveryProbe) {
  const StudySettings study = lamb2dCaseStudy({"geometry.spacing=0.5"}, 6.0);
  const fs::path folder = fs::temp_directory_path() / "mfwave-lamb-solid-case";
  fs::remove_all(folder);
  fs::create_directories(folder);
  const CaseResult r = runSolidCase(study, solidCase(study.scene), folder.string(), false);
  EXPECT_EQ(r.record.particles, 33 * 17);
  EXPECT_EQ(r.settings.methodLabel(), "ul-sph alpha=1 beta=0 kgc");
  EXPECT_NEAR(r.smoothingLength, 1.3 * 0.5, 1e-12);  // h / dx = 1.3 despite the faces' smaller volumes
  // courant 0.3 h / (c_p (1 + 1.2 alpha)), c_p = sqrt 3
  EXPECT_NEAR(r.record.stableTimeStep, 0.3 * 0.65 / (std::sqrt(3.0) * 2.2), 1e-3);
  EXPECT_GT(r.record.steps, 100);
  ASSERT_EQ(r.probes.size(), 3u);
  testing::expectEveryProbeScoredAsRaw(r);
  // Measured (dx = 0.5 is coarse: the strip is two spacings wide; the errors fall to 0.056 / 0.134 /
  // 0.044 at dx = 0.0625).
  EXPECT_NEAR(r.probes[0].reported.relativeL2, 1.081, 0.02);   // centre
  EXPECT_NEAR(r.probes[1].reported.relativeL2, 0.8627, 0.02);  // receiver
  EXPECT_NEAR(r.probes[2].reported.relativeL2, 0.6706, 0.015);  // buried
  EXPECT_EQ(r.record.primaryError, "largest_relative_l2");
  EXPECT_TRUE(anyNoteHas(r.notes, "small amplitude: the traction is 0.0001 times the scene's"));
  EXPECT_TRUE(anyNoteHas(r.notes, "acts on 3 particles of the loaded face with a total length 1 "));
  EXPECT_TRUE(
      anyNoteHas(r.notes, "reaches a probe at t = 7.79 (13.5 / c_p from the load's patch via the +x face"));
  EXPECT_TRUE(anyNoteHas(r.notes, "after the error window 6"));
  EXPECT_TRUE(anyNoteHas(r.notes, "artificial viscosity alpha = 1, beta = 0"));
  EXPECT_EQ(r.files, (std::vector<std::string>{"exact.csv", "ulsph_0.5-probes.csv"}));
  for (const std::string& file : r.files) EXPECT_TRUE(fs::exists(folder / file)) << file;
  fs::remove_all(folder);

  StudySettings oneD = study;
  oneD.scene.info.dimension = 1;
  try {
    runSolidCase(oneD, solidCase(study.scene), folder.string(), false);
    FAIL() << "a 1-D scene is refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method.name");
  }
}

}  // namespace
}  // namespace mfwave::lamb3d
