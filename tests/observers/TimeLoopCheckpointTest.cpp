// The time loop's checkpoints (issue 20): a loop stopped by SIGTERM writes the state it reached,
// and a loop restored from it ends with the same state and the same observer records as one that
// never stopped; a run with a part that cannot be checkpointed is refused before its first step.

#include "../integrators/TestSystems.hpp"
#include "core/CheckpointStore.hpp"
#include "core/Error.hpp"
#include "core/Interruption.hpp"
#include "integrators/CentralDifference.hpp"
#include "observers/EnergyObserver.hpp"
#include "observers/LinearEnergyLedger.hpp"
#include "observers/ProbeRecorder.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <map>
#include <memory>

namespace mfwave {
namespace {

// Checkpoints kept in memory: every write of each loop, and a point to resume each loop from.
class MemoryStore : public CheckpointStore {
 public:
  explicit MemoryStore(long every) : every_(every) {}
  long everySteps() const override { return every_; }
  double everySeconds() const override { return 0; }
  std::string settingName() const override { return "--checkpoint-every"; }
  std::optional<CheckpointPoint> resumePoint(int loop) override {
    const auto found = resume.find(loop);
    if (found == resume.end()) return std::nullopt;
    return found->second;
  }
  void write(int loop, long step, Real time, const StateArchive& archive) override {
    written[loop].push_back({step, time, StateArchive(archive.arrays()), "memory"});
  }
  std::map<int, std::vector<CheckpointPoint>> written;
  std::map<int, CheckpointPoint> resume;

 private:
  long every_;
};

// Raises SIGTERM after step `at` (as a scheduler would); gathers nothing.
class SignalAt : public StatelessObserver {
 public:
  explicit SignalAt(long at) : at_(at) {}
  void observe(const StateView& s) override {
    if (s.step == at_) std::raise(SIGTERM);
  }

 private:
  long at_;
};

struct Outcome {
  RunStatistics stats;
  Vector u, v;
  TimeSeries probes, energy, ledger;
};

// A spring chain by central difference with a probe, the energy, the ledger and the stability
// monitor, to t = 6 (120 steps).
Outcome runChain(long signalAt) {
  auto system = test::springChain(8);
  CentralDifference integrator;
  integrator.initialise(*system, 0, test::chainInitialDisplacement(8), Vector::Zero(8), 0.05);
  ProbeRecorder probes({{"third", 3, 0, ProbeQuantity::Velocity}}, 1);
  EnergyObserver energy(EnergyObserver::ofLinearSystem(*system));
  LinearEnergyLedgerOptions ledgerOptions;
  ledgerOptions.quietAfter = 0;
  ledgerOptions.checkEvery = 3;
  LinearEnergyLedger ledger(*system, ledgerOptions);
  StabilityMonitor monitor;
  SignalAt signal(signalAt);
  TimeLoop loop;
  loop.add(probes, 2);
  loop.add(energy, 5);
  loop.add(ledger);
  loop.add(monitor);
  loop.add(signal);
  Outcome outcome{loop.run(integrator, 6.0), integrator.state().displacement, integrator.state().velocity,
                  probes.series(), energy.series(), ledger.series()};
  return outcome;
}

void expectSameSeries(const TimeSeries& a, const TimeSeries& b, const char* what) {
  EXPECT_EQ(a.times(), b.times()) << what;
  for (std::size_t c = 0; c < a.columns(); ++c) EXPECT_EQ(a.column(c), b.column(c)) << what << " column " << c;
}

TEST(TimeLoopCheckpoint, ARunStoppedBySigtermAndRestoredEndsAsOneThatNeverStopped) {
  clearInterruption();
  auto plain = std::make_shared<MemoryStore>(7);
  installCheckpointStore(plain);
  const Outcome reference = runChain(-1);
  ASSERT_EQ(reference.stats.steps, 120);
  // Every 7 steps, and the end.
  ASSERT_EQ(plain->written[0].size(), 120u / 7 + 1);
  EXPECT_EQ(plain->written[0].back().step, 120);

  auto stopped = std::make_shared<MemoryStore>(7);
  installCheckpointStore(stopped);
  const Outcome interrupted = runChain(45);
  EXPECT_TRUE(interrupted.stats.interrupted);
  EXPECT_EQ(interrupted.stats.steps, 45);
  ASSERT_FALSE(stopped->written[0].empty());
  const CheckpointPoint last = stopped->written[0].back();
  EXPECT_EQ(last.step, 45);  // written where the signal stopped it, not only at a multiple of 7
  clearInterruption();

  auto restart = std::make_shared<MemoryStore>(7);
  restart->resume[0] = last;
  installCheckpointStore(restart);
  const Outcome resumed = runChain(-1);
  installCheckpointStore(nullptr);
  EXPECT_EQ(resumed.stats.resumedFromStep, 45);
  EXPECT_EQ(resumed.stats.steps, 120);
  EXPECT_EQ(resumed.stats.startTime, 0);
  EXPECT_EQ(resumed.u, reference.u);
  EXPECT_EQ(resumed.v, reference.v);
  expectSameSeries(resumed.probes, reference.probes, "probes");
  expectSameSeries(resumed.energy, reference.energy, "energy");
  expectSameSeries(resumed.ledger, reference.ledger, "ledger");
  // The final checkpoints hold the same arrays, bit for bit.
  EXPECT_EQ(restart->written[0].back().archive.arrays(), plain->written[0].back().archive.arrays());
}

TEST(TimeLoopCheckpoint, APartThatCannotBeCheckpointedIsRefusedBeforeTheFirstStep) {
  struct Gatherer : Observer {
    void observe(const StateView&) override {}
  } gatherer;
  auto system = test::oscillator(1.0, 0);
  CentralDifference integrator;
  integrator.initialise(*system, 0, Vector::Constant(1, 1.0), Vector::Zero(1), 0.1);
  TimeLoop loop;
  loop.add(gatherer);
  installCheckpointStore(std::make_shared<MemoryStore>(10));
  try {
    loop.run(integrator, 1.0);
    FAIL() << "a run with an observer that cannot be checkpointed was started";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "--checkpoint-every");
    EXPECT_NE(std::string(e.what()).find("Gatherer"), std::string::npos) << e.what();
  }
  installCheckpointStore(nullptr);
  EXPECT_EQ(integrator.stepCount(), 0);
  // Without a store the same loop runs.
  EXPECT_EQ(loop.run(integrator, 1.0).steps, 10);
}

// A store shared by the ranks of a split run with a wall-clock period: each rank's clock fires at
// another step, so the loop takes the period only from the ranks' agreement. Here the period never
// fires locally (a day) and a stand-in for the other ranks says one is due at the fourth boundary:
// the loop writes that checkpoint after step 3, before step 4. Without an agreement the store is
// refused before the first step.
TEST(TimeLoopCheckpoint, OnRanksAWallClockCheckpointIsTakenWhenTheRanksAgree) {
  class RankStore : public MemoryStore {
   public:
    RankStore() : MemoryStore(0) {}
    double everySeconds() const override { return 86400; }
    bool sharedByRanks() const override { return true; }
  };
  auto system = test::oscillator(1.0, 0);
  CentralDifference integrator;
  integrator.initialise(*system, 0, Vector::Constant(1, 1.0), Vector::Zero(1), 0.1);
  auto store = std::make_shared<RankStore>();
  installCheckpointStore(store);
  TimeLoop refused;
  EXPECT_THROW(refused.run(integrator, 1.0), InputError);
  EXPECT_EQ(integrator.stepCount(), 0);

  auto agreed = std::make_shared<RankStore>();
  installCheckpointStore(agreed);
  TimeLoop loop;
  int boundaries = 0;
  loop.agreeAcrossRanks([&boundaries](int* values, int) {
    EXPECT_EQ(values[1], 0);  // not due on this rank's clock
    if (++boundaries == 4) values[1] = 1;
  });
  EXPECT_EQ(loop.run(integrator, 1.0).steps, 10);
  installCheckpointStore(nullptr);
  std::vector<long> steps;
  for (const CheckpointPoint& p : agreed->written[0]) steps.push_back(p.step);
  EXPECT_EQ(steps, (std::vector<long>{3, 10}));  // the agreed one, then the end's
}

}  // namespace
}  // namespace mfwave
