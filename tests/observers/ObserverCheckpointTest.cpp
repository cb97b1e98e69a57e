// Checkpoints of the particle observers (issue 20): an observer saved part-way through a run and
// restored into a fresh one (restoreState in place of begin(), as TimeLoop does on a restart)
// gathers exactly what one that watched the whole run gathered. ViewAdapter keeps its own counter
// and its observers' states, each in a section of its own.

#include "core/Error.hpp"
#include "core/StateArchive.hpp"
#include "observers/BodyMotionRecorder.hpp"
#include "observers/GroupMeanRecorder.hpp"
#include "observers/PositionSnapshots.hpp"
#include "observers/StepSizeRecorder.hpp"
#include "observers/ViewAdapter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace mfwave;

namespace {

ParticleSet<2> fourParticles() {
  ParticleSet<2> p;
  p.add(Vec2(0, 0), 1);
  p.add(Vec2(1, 0), 1);
  p.add(Vec2(3, 1), 1);
  p.add(Vec2(4, 3), 1);
  return p;
}

// The states of a scripted run: step k at t = sum of growing steps, u and v smooth in k.
struct Script {
  Vector u = Vector::Zero(8), v = Vector::Zero(8);
  StateView at(long k) {
    for (Index i = 0; i < 8; ++i) {
      u[i] = 0.01 * std::sin(0.3 * static_cast<Real>(k) + static_cast<Real>(i));
      v[i] = 0.02 * std::cos(0.2 * static_cast<Real>(k) - static_cast<Real>(i));
    }
    return {k, time(k), u, v, k > 0 ? time(k) - time(k - 1) : 0.0};
  }
  static Real time(long k) { return 0.01 * static_cast<Real>(k) + 1e-4 * static_cast<Real>(k * k); }
};

// Shows the state as it is (the adapter's own work is not under test).
struct PassThrough : ViewAdapter {
  StateView adapt(const StateView& s) override { return s; }
};

// The run's observers behind one adapter, as the UL-SPH drivers add them.
struct Watchers {
  ParticleSet<2> positions = fourParticles();
  PassThrough adapter;
  GroupMeanRecorder mean{"the pair", {1, 2}, 2};
  BodyMotionRecorder<2> motion{positions, {1, 2, 3, 4}, {{"a", {0, 1}}, {"b", {2, 3}}}, true};
  PositionSnapshots<2> snapshots{positions, {0.0, 0.05, 0.2, 0.31, 5.0}, true};
  StepSizeRecorder steps;
  Watchers() {
    adapter.add(mean, 3);
    adapter.add(motion, 2);
    adapter.add(snapshots);
    adapter.add(steps);
  }
};

// first .. last - 1 observed, then end() at last, as TimeLoop does (adapter at every step).
void watch(Watchers& w, Script& script, long first, long last) {
  for (long k = first; k < last; ++k) w.adapter.observe(script.at(k));
  w.adapter.end(script.at(last));
}

}  // namespace

TEST(ObserverCheckpoint, AViewAdapterAndItsObserversGoOnAsIfNeverStopped) {
  // The run starts at step 5 (a later time loop of a driver): the intervals count from there.
  constexpr long start = 5, checkpoint = 16, last = 37;
  Script script;
  Watchers whole;
  whole.adapter.begin(script.at(start));
  watch(whole, script, start + 1, last);

  StateArchive archive;
  {
    Watchers interrupted;
    interrupted.adapter.begin(script.at(start));
    for (long k = start + 1; k <= checkpoint; ++k) interrupted.adapter.observe(script.at(k));
    interrupted.adapter.saveState(archive);
  }
  Watchers restored;
  restored.adapter.restoreState(archive);
  watch(restored, script, checkpoint + 1, last);

  EXPECT_EQ(restored.mean.series().times(), whole.mean.series().times());
  for (std::size_t c = 0; c < whole.mean.series().columns(); ++c) {
    EXPECT_EQ(restored.mean.series().column(c), whole.mean.series().column(c));
  }
  ASSERT_EQ(restored.motion.samples().size(), whole.motion.samples().size());
  for (std::size_t s = 0; s < whole.motion.samples().size(); ++s) {
    const auto& a = restored.motion.samples()[s];
    const auto& b = whole.motion.samples()[s];
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.dt, b.dt);
    for (std::size_t body = 0; body < 2; ++body) {
      EXPECT_EQ(a.centre[body], b.centre[body]);
      EXPECT_EQ(a.velocity[body], b.velocity[body]);
      EXPECT_EQ(a.lower[body], b.lower[body]);
      EXPECT_EQ(a.upper[body], b.upper[body]);
    }
  }
  ASSERT_EQ(restored.snapshots.snapshots().size(), whole.snapshots.snapshots().size());
  for (std::size_t s = 0; s < whole.snapshots.snapshots().size(); ++s) {
    EXPECT_EQ(restored.snapshots.snapshots()[s].time, whole.snapshots.snapshots()[s].time);
    EXPECT_EQ(restored.snapshots.snapshots()[s].positions, whole.snapshots.snapshots()[s].positions);
  }
  EXPECT_EQ(restored.steps.steps(), whole.steps.steps());
  EXPECT_EQ(restored.steps.smallest(), whole.steps.smallest());
  EXPECT_EQ(restored.steps.largest(), whole.steps.largest());
  EXPECT_EQ(restored.steps.last(), whole.steps.last());
}

TEST(ObserverCheckpoint, AnAdapterWithOtherObserversRefusesTheCheckpoint) {
  Script script;
  Watchers saved;
  saved.adapter.begin(script.at(0));
  StateArchive archive;
  saved.adapter.saveState(archive);
  PassThrough fewer;
  GroupMeanRecorder mean("the pair", {1, 2}, 2);
  fewer.add(mean);
  EXPECT_THROW(fewer.restoreState(archive), InputError);
}

// Before any snapshot, and with the step recorder's infinite smallest step: restored as saved.
TEST(ObserverCheckpoint, EmptyRecordersRestoreEmpty) {
  const ParticleSet<2> positions = fourParticles();
  PositionSnapshots<2> snapshots(positions, {1.0}, true);
  StepSizeRecorder steps;
  StateArchive archive;
  StateArchive a = archive.section("snapshots");
  StateArchive b = archive.section("steps");
  snapshots.saveState(a);
  steps.saveState(b);
  PositionSnapshots<2> restoredSnapshots(positions, {1.0}, true);
  StepSizeRecorder restoredSteps;
  restoredSnapshots.restoreState(archive.section("snapshots"));
  restoredSteps.restoreState(archive.section("steps"));
  EXPECT_TRUE(restoredSnapshots.snapshots().empty());
  EXPECT_EQ(restoredSteps.steps(), 0);
  EXPECT_TRUE(std::isinf(restoredSteps.smallest()));
}
