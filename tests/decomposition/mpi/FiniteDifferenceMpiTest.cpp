// The finite-difference wave on the ranks (issue 22): its scalar lattice system
// (FiniteDifferenceLattice.hpp, one unknown per node) split by LatticeShare as a driver splits it,
// stepped by the serial central difference, keeps the serial run's bits on 1 to 4 ranks: state,
// loads, energies and dot products.
#include "decomposition/mpi/LatticeShare.hpp"
#include "integrators/CentralDifference.hpp"
#include "methods/finite_difference/FiniteDifferenceLattice.hpp"
#include "particles/BoxFace.hpp"

#include "core/TimeFunction.hpp"

#include "MpiTestSupport.hpp"

#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>

using namespace mfwave;
using test::worldSize;

namespace {

template <int D>
void expectTheFiniteDifferenceRunKeepsTheSerialBits(const std::array<Index, D>& nodes) {
  const Real dx = 0.05, c = std::sqrt(3.0);
  FiniteDifferenceWaveOptions options;
  options.spacing = dx;
  options.density = 1;
  options.modulus = 3;
  options.fixedFaces = allFaces(D);
  // Two point forces of their own histories, off the rank boundaries' symmetry.
  Index count = 1;
  for (Index n : nodes) count *= n;
  const TimeFunction ricker = TimeFunction::ricker(8.0, 0.15);
  const TimeFunction ramp = TimeFunction::ramp(0.0, 0.2, 0.7);
  const std::vector<SparseLoad> loads{{{count / 2 + 3}, {1.0}, &ricker}, {{count / 3}, {-0.4}, &ramp}};
  LatticeSecondOrderSystem<D, 1> serial = finiteDifferenceLatticeSystem<D>(nodes, options, loads);
  LatticeShare<D, 1> share(serial, MPI_COMM_WORLD);
  DistributedLatticeSystem<D, 1>& distributed = share.system();

  const Real dt = 0.5 * dx / (c * std::sqrt(static_cast<Real>(D)));
  const int steps = 80;
  const Vector zero = Vector::Zero(serial.size());
  CentralDifference serialRun;
  serialRun.initialise(serial, 0, zero, zero, dt);
  for (int n = 0; n < steps; ++n) serialRun.step();
  const Vector u = serialRun.state().displacement, v = serialRun.state().velocity;

  CentralDifference run;
  const Vector mine = Vector::Zero(distributed.size());
  run.initialise(distributed, 0, mine, mine, dt);
  for (int n = 0; n < steps; ++n) run.step();
  const Vector& ur = run.state().displacement;
  const Vector& vr = run.state().velocity;
  EXPECT_EQ(test::differencesOverRanks(distributed, ur, u) + test::differencesOverRanks(distributed, vr, v), 0)
      << D << "-D on " << worldSize() << " ranks";
  EXPECT_EQ(distributed.kineticEnergy(vr), serial.kineticEnergy(v));
  EXPECT_EQ(distributed.strainEnergy(ur), serial.strainEnergy(u));
  EXPECT_EQ(distributed.dot(ur, vr), serial.dot(u, v));
  // The run did something: the loads put energy in and the pulse spread over many nodes.
  EXPECT_GT(serial.kineticEnergy(v) + serial.strainEnergy(u), 1e-6);
  long moving = 0;
  for (Index i = 0; i < u.size(); ++i) moving += std::abs(u[i]) > 1e-12 ? 1 : 0;
  EXPECT_GT(moving, u.size() / 20);
}

}  // namespace

TEST(FiniteDifferenceMpiTest, TheScalarWaveOnTheRanksKeepsTheSerialBits) {
  expectTheFiniteDifferenceRunKeepsTheSerialBits<3>({21, 17, 13});
  expectTheFiniteDifferenceRunKeepsTheSerialBits<2>({61, 37});
}
