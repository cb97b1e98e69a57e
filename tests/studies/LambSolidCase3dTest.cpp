// lib/studies/lamb3d/LambSolidCase in 3-D: the Lamb problem of data/scenes/lamb3d.toml by the
// updated-Lagrangian SPH at dx = 0.5 and small amplitude: tributary volumes (faces 1/2, edges 1/4,
// corners 1/8) fill the block, the square patch's load is its area times eps T f(t) on the method's
// own accelerations (also for a patch whose edges fall between particles), and the case on the
// scene's 7 x 7 x 7 box (every face free) scores every probe with the measured errors.

#include "LambCaseScene.hpp"
#include "studies/lamb3d/LambSolidCase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace mfwave::lamb3d {
namespace {

namespace fs = std::filesystem;
using testing::anyNoteHas;
using testing::lamb3dCaseStudy;

// sum_i m_i a_i of the method at rest at t (f(0.5) = 0.5), every component.
Vec3 totalForceAtRest(UpdatedLagrangianSph<3>& system, Real t) {
  const Vector y0 = system.initialState();
  Vector ydot = Vector::Zero(y0.size());
  system.rhs(t, y0, ydot);
  Vec3 force = Vec3::Zero();
  for (Index i = 0; i < system.particleCount(); ++i)
    for (int d = 0; d < 3; ++d)
      force[d] += system.masses()[static_cast<std::size_t>(i)] * ydot[system.layout().velocity(i, d)];
  return force;
}

TEST(LambSolidCase3d, TheSquaresTotalForceIsItsAreaTimesTheLoad) {
  const StudySettings study = lamb3dCaseStudy({"geometry.spacing=0.5"});
  const Scene& scene = study.scene;
  const ParticleSet<3> particles = lambSolidParticles<3>(scene.geometry, true);
  ASSERT_EQ(particles.size(), 15 * 15 * 15);  // no ghosts
  Real volume = 0;
  for (Index i = 0; i < particles.size(); ++i) volume += particles.volume[static_cast<std::size_t>(i)];
  EXPECT_NEAR(volume, 7.0 * 7.0 * 7.0, 1e-11);  // tributary volumes fill the block

  // The 3 x 3 particles of |x|, |y| <= 0.5 on z = 0: the centre carries dx^2 = 0.25, the edges' middles
  // half of it, the corners a quarter.
  const PatchTraction patch = patchTraction<3>(scene.loads[0], particles, 0.5);
  ASSERT_EQ(patch.particles.size(), 9u);
  std::vector<Real> sorted = patch.measures;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::vector<Real>{0.0625, 0.0625, 0.0625, 0.0625, 0.125, 0.125, 0.125, 0.125, 0.25}));
  EXPECT_DOUBLE_EQ(patch.totalMeasure(), 1.0);

  const LambSolidSpec spec = LambSolidSpec::linearDefaults(scene.material.material());
  UpdatedLagrangianSph<3> system(particles, lambSolidOptions<3>(spec, particles, 0.5));
  applyPatchLoad<3>(system, scene.loads[0], patch, 1e-4);
  const Vec3 force = totalForceAtRest(system, 0.5);
  EXPECT_NEAR(force[0], 0.0, 1e-15);
  EXPECT_NEAR(force[1], 0.0, 1e-15);
  EXPECT_NEAR(force[2], 1e-4 * 1.0 * 1.0 * 0.5, 1e-15);

  // A patch |x|, |y| < 0.6 (edges between particles): each edge particle's square is clipped to
  // 0.35 along the cut axis, the total is still the area 1.2^2 = 1.44.
  LoadSpec wider = scene.loads[0];
  wider.halfWidth = {0.6, 0.6, 0.0};
  const PatchTraction clipped = patchTraction<3>(wider, particles, 0.5);
  EXPECT_EQ(clipped.particles.size(), 9u);
  EXPECT_NEAR(clipped.totalMeasure(), 1.44, 1e-14);
  UpdatedLagrangianSph<3> widerSystem(particles, lambSolidOptions<3>(spec, particles, 0.5));
  applyPatchLoad<3>(widerSystem, wider, clipped, 1e-4);
  EXPECT_NEAR(totalForceAtRest(widerSystem, 0.5)[2], 1e-4 * 1.44 * 0.5, 1e-15);

  // A patch hanging over the block's +x edge (centre x = 3.5): the face clips it to half, 0.5 x 1.
  LoadSpec atEdge = scene.loads[0];
  atEdge.centre = {3.5, 0.0, 0.0};
  EXPECT_NEAR(patchTraction<3>(atEdge, particles, 0.5).totalMeasure(), 0.5, 1e-14);
}

TEST(LambSolidCase3d, RunsTheLambProblemOnTheScenesBoxAndScoresEveryProbe) {
  const StudySettings study = lamb3dCaseStudy({"geometry.spacing=0.5"});
  const fs::path folder = fs::temp_directory_path() / "mfwave-lamb-solid-case-3d";
  fs::remove_all(folder);
  fs::create_directories(folder);
  CaseSettings c;
  c.name = "ulsph_0.5";
  c.geometry = study.scene.geometry;
  c.solid = LambSolidSpec::linearDefaults(study.scene.material.material());
  const CaseResult r = runSolidCase(study, c, folder.string(), false);
  EXPECT_EQ(r.record.particles, 15 * 15 * 15);
  EXPECT_NEAR(r.smoothingLength, 1.3 * 0.5, 1e-12);  // h / dx = 1.3 despite the faces' smaller volumes
  // courant 0.3 h / (c_p (1 + 1.2 alpha)), c_p = sqrt 3
  EXPECT_NEAR(r.record.stableTimeStep, 0.3 * 0.65 / (std::sqrt(3.0) * 2.2), 1e-3);
  ASSERT_EQ(r.probes.size(), 3u);
  for (const ProbeResult& p : r.probes) EXPECT_TRUE(p.hasExact) << p.name;
  // Measured (LambSolidCase.hpp: dx = 0.5 is coarse, the square two spacings wide; 0.377 / 0.904 /
  // 0.634 at 0.25).
  EXPECT_NEAR(r.probes[0].reported.relativeL2, 1.323, 0.02);  // centre
  EXPECT_NEAR(r.probes[1].reported.relativeL2, 0.882, 0.02);  // receiver
  EXPECT_NEAR(r.probes[2].reported.relativeL2, 1.128, 0.02);  // buried
  EXPECT_TRUE(anyNoteHas(r.notes, "the square's traction acts on 9 particles of the loaded face with a total area 1 "));
  EXPECT_TRUE(anyNoteHas(r.notes, "the tributary volume (faces half, edges a quarter, corners an eighth)"));
  // the +x face 1.5 beyond the receiver: 4.5 / c_p from the patch's edge to the receiver's image
  EXPECT_TRUE(anyNoteHas(r.notes, "reaches a probe at t = 2.6 (4.5 / c_p from the load's patch via the +x face to "
                                  "probe receiver), INSIDE the error window 6"));
  fs::remove_all(folder);
}

}  // namespace
}  // namespace mfwave::lamb3d
