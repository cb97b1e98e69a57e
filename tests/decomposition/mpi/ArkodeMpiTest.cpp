// The ARKODE path on SUNDIALS' MPI vectors (issue 22), under mpirun (ctest runs this program on 1,
// 2, 3 and 4 ranks): ArkodeSecondOrder and ArkodeFirstOrder step a DistributedLatticeSystem
// unchanged, on N_Vector Parallel over its communicator (DistributedLatticeSystem::distribution).
// A fixed-step run keeps the serial run's bits on every owned dof; an adaptive run takes the serial
// run's steps on every rank and ends within rounding of the serial state.
#include "decomposition/mpi/DistributedLatticeSystem.hpp"
#include "integrators/ArkodeFirstOrder.hpp"
#include "integrators/ArkodeMpiVectors.hpp"
#include "integrators/ArkodeSecondOrder.hpp"
#include "lattice/LatticeSecondOrderSystem.hpp"
#include "systems/SecondOrderAsFirstOrder.hpp"

#include "core/Error.hpp"

#include "MpiTestSupport.hpp"

#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

using namespace mfwave;
using test::LatticeCase;
using test::differencesOverRanks;
using test::relativeDifferenceOverRanks;
using test::sumOverRanks;
using test::worldRank;
using test::worldSize;

namespace {

template <int D>
void expectAFixedStepRunKeepsTheSerialBits(const std::array<Index, D>& nodes) {
  LatticeCase<D> lattice(nodes);
  ArkodeOptions options;  // classic RK4, a fixed step
  const Real dt = 0.1;
  const int steps = 60;
  ArkodeSecondOrder serialRun(options);
  serialRun.initialise(*lattice.serial, 0, lattice.u0, lattice.v0, dt);
  for (int n = 0; n < steps; ++n) serialRun.step();
  ArkodeSecondOrder run(options);
  run.initialise(*lattice.distributed, 0, lattice.distributed->restrict(lattice.u0),
                 lattice.distributed->restrict(lattice.v0), dt);
  for (int n = 0; n < steps; ++n) run.step();
  EXPECT_EQ(run.stepCount(), steps);
  EXPECT_EQ(run.time(), serialRun.time());
  // Every N_Vector operation of an explicit RK step is element-wise (linear sums of stages), and
  // every owned acceleration is the serial one bit for bit: nothing is summed over the ranks.
  EXPECT_EQ(differencesOverRanks(*lattice.distributed, run.state().displacement, serialRun.state().displacement), 0)
      << D << "-D on " << worldSize() << " ranks";
  EXPECT_EQ(differencesOverRanks(*lattice.distributed, run.state().velocity, serialRun.state().velocity), 0)
      << D << "-D on " << worldSize() << " ranks";
  // The run did something: the bump has moved.
  EXPECT_GT((serialRun.state().displacement - lattice.u0).cwiseAbs().maxCoeff(), 0.1 * lattice.u0.cwiseAbs().maxCoeff());
}

TEST(ArkodeMpiTest, AFixedStepRk4RunOnTheRanksKeepsTheSerialBits) {
  expectAFixedStepRunKeepsTheSerialBits<3>({26, 15, 12});
  expectAFixedStepRunKeepsTheSerialBits<2>({41, 23});
}

template <int D>
void expectAnAdaptiveRunTakesTheSerialSteps(const std::array<Index, D>& nodes) {
  LatticeCase<D> lattice(nodes);
  ArkodeOptions options;
  options.table = "dormand_prince_7_4_5";
  options.adaptive = true;
  options.relativeTolerance = 1e-8;
  options.absoluteTolerance = 1e-10;
  const Real end = 6.0;
  ArkodeSecondOrder serialRun(options);
  serialRun.initialise(*lattice.serial, 0, lattice.u0, lattice.v0, 0.01);
  serialRun.advanceTo(end);
  ArkodeSecondOrder run(options);
  run.initialise(*lattice.distributed, 0, lattice.distributed->restrict(lattice.u0),
                 lattice.distributed->restrict(lattice.v0), 0.01);
  run.advanceTo(end);

  // Every rank took the same steps, and the serial run's: the error test's WRMS norm is reduced over
  // the ranks, so all ranks accept and reject alike, and its sum of squares runs in the lattice's
  // order on every rank count as in the serial lattice system (VectorDistribution::
  // orderedSumOfSquares), so the steps and the states keep the serial bits. With serial vectors on
  // the ranks each would choose its own steps from its own share's norm.
  const ArkodeStatistics serialStatistics = serialRun.arkode().statistics();
  const ArkodeStatistics statistics = run.arkode().statistics();
  long fewest = statistics.stepAttempts, most = statistics.stepAttempts;
  MPI_Allreduce(MPI_IN_PLACE, &fewest, 1, MPI_LONG, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_LONG, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_EQ(fewest, most) << "the ranks took different numbers of steps";
  EXPECT_EQ(statistics.steps, serialStatistics.steps);
  EXPECT_EQ(statistics.stepAttempts, serialStatistics.stepAttempts);
  EXPECT_GT(statistics.steps, 20);  // adaptive steps, not one or two
  EXPECT_EQ(run.time(), end);
  EXPECT_EQ(run.arkode().lastStepSize(), serialRun.arkode().lastStepSize());
  EXPECT_EQ(differencesOverRanks(*lattice.distributed, run.state().displacement, serialRun.state().displacement) +
                differencesOverRanks(*lattice.distributed, run.state().velocity, serialRun.state().velocity),
            0);
  const Real du = relativeDifferenceOverRanks(*lattice.distributed, run.state().displacement, serialRun.state().displacement);
  const Real dv = relativeDifferenceOverRanks(*lattice.distributed, run.state().velocity, serialRun.state().velocity);
  if (worldRank() == 0)
    std::printf("[ adaptive ] %d-D on %d ranks: %ld steps (%ld attempts; serial %ld, %ld), "
                "relative differences u %.3g, v %.3g\n",
                D, worldSize(), statistics.steps, statistics.stepAttempts, serialStatistics.steps,
                serialStatistics.stepAttempts, du, dv);
}

TEST(ArkodeMpiTest, AnAdaptiveRunOnTheRanksTakesTheSerialStepsAndKeepsTheSerialBits) {
  expectAnAdaptiveRunTakesTheSerialSteps<3>({26, 15, 12});
  expectAnAdaptiveRunTakesTheSerialSteps<2>({41, 23});
}

// ArkodeFirstOrder on the first-order view of the distributed system: the view reports twice the
// distributed length, and the fixed-step run keeps the serial bits there too.
TEST(ArkodeMpiTest, TheFirstOrderViewOfTheDistributedSystemRunsOnTheMpiVectors) {
  LatticeCase<2> lattice({41, 23});
  SecondOrderAsFirstOrder serialView(*lattice.serial), view(*lattice.distributed);
  // The serial lattice system fixes only the order of its norms' sums; the share adds its ranks.
  ASSERT_TRUE(serialView.distribution().has_value());
  EXPECT_EQ(serialView.distribution()->communicator, nullptr);
  ASSERT_TRUE(view.distribution().has_value());
  EXPECT_NE(view.distribution()->communicator, nullptr);
  EXPECT_EQ(view.distribution()->globalSize, serialView.size());
  EXPECT_EQ(sumOverRanks(static_cast<long>(view.size())), static_cast<long>(serialView.size()));
  ArkodeOptions options;
  ArkodeFirstOrder serialRun(options), run(options);
  serialRun.initialise(serialView, 0, serialView.pack(lattice.u0, lattice.v0), 0.1);
  run.initialise(view, 0,
                 view.pack(lattice.distributed->restrict(lattice.u0), lattice.distributed->restrict(lattice.v0)), 0.1);
  serialRun.advanceTo(3.05);  // a shortened last step too
  run.advanceTo(3.05);
  Vector u, v, serialU, serialV;
  view.unpack(run.solution(), u, v);
  serialView.unpack(serialRun.solution(), serialU, serialV);
  EXPECT_EQ(differencesOverRanks(*lattice.distributed, u, serialU), 0);
  EXPECT_EQ(differencesOverRanks(*lattice.distributed, v, serialV), 0);
  EXPECT_EQ(run.stepCount(), serialRun.stepCount());
}

// A system whose ranks' sizes do not add up to the global size it reports is refused by ARKODE's
// vector (N_VMake_Parallel checks the sum), as an Error on every rank rather than a wrong run.
class MisreportedSize : public FirstOrderSystem {
 public:
  Index size() const override { return 3; }
  void rhs(Real, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) override { ydot = -y; }
  std::optional<VectorDistribution> distribution() const override {
    return VectorDistribution{&communicator_, 3 * static_cast<Index>(worldSize()) + 1, {}};
  }

 private:
  MPI_Comm communicator_ = MPI_COMM_WORLD;
};

TEST(ArkodeMpiTest, AGlobalSizeTheRanksDoNotAddUpToIsRefused) {
  enableArkodeMpiVectors();  // as a distributed system's constructor does (this test may run alone)
  MisreportedSize system;
  ArkodeOptions options;
  options.fixedStep = 0.1;
  ArkodeExplicit arkode(options);
  EXPECT_THROW(arkode.initialise(system, 0, Vector::Ones(3)), Error);
}

}  // namespace
