// BodyMotionRecorder: each body's centre of mass, its velocity and its extent from a particle view,
// with current positions held by the particle set (a moved copy) or formed as X + u; one sample
// per step, non-finite views left out, bad bodies refused. StepSizeRecorder: the smallest, largest
// and last step the observers saw, the initial state counting none.

#include "core/Error.hpp"
#include "observers/BodyMotionRecorder.hpp"
#include "observers/StepSizeRecorder.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

using namespace mfwave;

namespace {

// Four particles in 2-D: body "a" = {0, 1}, body "b" = {2, 3}.
ParticleSet<2> fourParticles() {
  ParticleSet<2> p;
  p.add(Vec2(0, 0), 1);
  p.add(Vec2(1, 0), 1);
  p.add(Vec2(3, 1), 1);
  p.add(Vec2(4, 3), 1);
  return p;
}

}  // namespace

TEST(BodyMotionRecorder, GivesEachBodysCentreOfMassVelocityAndExtent) {
  const ParticleSet<2> particles = fourParticles();
  BodyMotionRecorder<2> motion(particles, {1, 3, 2, 2}, {{"a", {0, 1}}, {"b", {2, 3}}});
  Vector u = Vector::Zero(8), v(8);
  v << 4, 0, 0, 0, -1, 2, -3, 0;
  motion.begin({0, 0.0, u, v, 0.1});
  motion.observe({5, 0.5, u, v, 0.1});
  motion.end({5, 0.5, u, v, 0.1});  // the same step: no second sample
  ASSERT_EQ(motion.samples().size(), 2u);
  const auto& first = motion.samples()[0];
  EXPECT_EQ(first.dt, 0.0);  // the initial state took no step
  EXPECT_EQ(motion.samples()[1].dt, 0.1);
  EXPECT_EQ(motion.samples()[1].time, 0.5);
  // a: masses 1 and 3 at x = 0 and 1: centre 0.75; momentum (4, 0) over mass 4: velocity (1, 0)
  EXPECT_DOUBLE_EQ(first.centre[0][0], 0.75);
  EXPECT_DOUBLE_EQ(first.centre[0][1], 0.0);
  EXPECT_DOUBLE_EQ(first.velocity[0][0], 1.0);
  // b: equal masses at (3, 1) and (4, 3): centre (3.5, 2), velocity (-2, 1), extent x in [3, 4]
  EXPECT_DOUBLE_EQ(first.centre[1][0], 3.5);
  EXPECT_DOUBLE_EQ(first.centre[1][1], 2.0);
  EXPECT_DOUBLE_EQ(first.velocity[1][0], -2.0);
  EXPECT_DOUBLE_EQ(first.velocity[1][1], 1.0);
  EXPECT_EQ(first.lower[1], Vec2(3, 1));
  EXPECT_EQ(first.upper[1], Vec2(4, 3));
  EXPECT_EQ(first.upper[0][0], 1.0);  // the gap between the bodies along x: 3 - 1
}

TEST(BodyMotionRecorder, AddsTheDisplacementForFixedParticlesAndLeavesOutNonFiniteViews) {
  const ParticleSet<2> particles = fourParticles();
  BodyMotionRecorder<2> motion(particles, {1, 1, 1, 1}, {{"all", {0, 1, 2, 3}}}, true);
  Vector u = Vector::Constant(8, 0.5), v = Vector::Zero(8);
  motion.observe({1, 0.1, u, v, 0.1});
  ASSERT_EQ(motion.samples().size(), 1u);
  EXPECT_DOUBLE_EQ(motion.samples()[0].centre[0][0], 2.0 + 0.5);
  EXPECT_DOUBLE_EQ(motion.samples()[0].lower[0][1], 0.5);
  u[3] = std::numeric_limits<Real>::quiet_NaN();
  motion.observe({2, 0.2, u, v, 0.1});
  EXPECT_EQ(motion.samples().size(), 1u);  // left out
}

TEST(BodyMotionRecorder, RefusesBodiesThatDoNotFitTheParticles) {
  const ParticleSet<2> particles = fourParticles();
  EXPECT_THROW(BodyMotionRecorder<2>(particles, {1, 1, 1}, {{"a", {0}}}), Error);
  EXPECT_THROW(BodyMotionRecorder<2>(particles, {1, 1, 1, 1}, {{"a", {}}}), Error);
  EXPECT_THROW(BodyMotionRecorder<2>(particles, {1, 1, 1, 1}, {{"a", {0, 4}}}), Error);
}

TEST(StepSizeRecorder, RecordsTheSmallestLargestAndLastStepTaken) {
  StepSizeRecorder steps;
  const Vector x = Vector::Zero(1);
  steps.begin({0, 0.0, x, x, 0.5});  // the step about to be taken is not one taken
  EXPECT_EQ(steps.steps(), 0);
  steps.observe({1, 0.1, x, x, 0.1});
  steps.observe({2, 0.12, x, x, 0.02});
  steps.observe({3, 0.42, x, x, 0.3});
  steps.end({3, 0.42, x, x, 0.3});  // already seen
  EXPECT_EQ(steps.steps(), 3);
  EXPECT_EQ(steps.smallest(), 0.02);
  EXPECT_EQ(steps.largest(), 0.3);
  EXPECT_EQ(steps.last(), 0.3);
}
