// One rank's share of a lattice system under mpirun (ctest runs this program on 1, 2, 3 and 4
// ranks, with HaloExchangeMpiTest.cpp): the serial integrator stepping DistributedLatticeSystem
// keeps the serial run's bits, with and without dashpots and loads, with x whole and with x cut
// (1-D, and 2-D and 3-D with every axis splittable), and what the system does not take yet is
// refused by name.
#include "decomposition/mpi/DistributedLatticeSystem.hpp"
#include "decomposition/mpi/LatticeShare.hpp"
#include "integrators/CentralDifference.hpp"
#include "lattice/LatticeSecondOrderSystem.hpp"

#include "core/Error.hpp"

#include "MpiTestSupport.hpp"

#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <string>
#include <vector>

using namespace mfwave;
using test::LatticeCase;
using test::worldRank;
using test::worldSize;

namespace {

// A wave run on the ranks keeps the serial bits: central difference, 60 steps of the lattice case
// (MpiTestSupport.hpp); the integrator is the serial one, stepping the owned vectors of
// DistributedLatticeSystem. With `loaded`, the dashpot solve (eq. (32)), the loads and the ledger's
// figures (dashpot power, load work's dot) keep the serial bits too.
template <int D>
void expectTheDistributedRunKeepsTheSerialBits(const std::array<Index, D>& nodes, bool loaded, bool coupled = false,
                                               bool splitX = false) {
  LatticeCase<D> lattice(nodes, loaded, coupled, splitX);
  // A case that asks for x to be split must split it on more than one rank, or it tests nothing new.
  if ((splitX || D == 1) && worldSize() > 1) {
    ASSERT_GT(lattice.decomposition->grid()[0], 1);
  }
  LatticeSecondOrderSystem<D>& serial = *lattice.serial;
  ASSERT_EQ(serial.hasDamping(), loaded);
  ASSERT_EQ(loaded && !serial.damping().blockDiagonal(), coupled);
  const Real dt = 0.1;
  const int steps = 60;
  CentralDifference serialRun;
  serialRun.initialise(serial, 0, lattice.u0, lattice.v0, dt);
  for (int n = 0; n < steps; ++n) serialRun.step();
  const Vector u = serialRun.state().displacement, v = serialRun.state().velocity;
  const Real serialEnergy = serial.kineticEnergy(v) + serial.strainEnergy(u);
  const Real serialPower = serial.dampingPower(v), serialDot = serial.dot(u, v);
  Vector serialForce;
  serial.force(1.5, serialForce);

  DistributedLatticeSystem<D>& distributed = *lattice.distributed;
  CentralDifference run;
  run.initialise(distributed, 0, distributed.restrict(lattice.u0), distributed.restrict(lattice.v0), dt);
  EXPECT_EQ(run.implicitDamping(), loaded);
  EXPECT_EQ(serialRun.implicitDamping(), loaded);
  for (int n = 0; n < steps; ++n) run.step();
  Vector force;
  distributed.force(1.5, force);
  const long different = test::differencesOverRanks(distributed, run.state().displacement, u) +
                         test::differencesOverRanks(distributed, run.state().velocity, v) +
                         test::differencesOverRanks(distributed, force, serialForce);
  EXPECT_EQ(different, 0) << D << "-D on " << worldSize() << " ranks";
  const Vector& ur = run.state().displacement;
  const Vector& vr = run.state().velocity;
  const Real energy = distributed.kineticEnergy(vr) + distributed.strainEnergy(ur);
  EXPECT_EQ(energy, serialEnergy) << "difference " << energy - serialEnergy;
  EXPECT_EQ(distributed.dampingPower(vr), serialPower);
  EXPECT_EQ(distributed.dot(ur, vr), serialDot);
  if (loaded) {
    EXPECT_GT(serialPower, 0.0);
    EXPECT_NE(serialForce.squaredNorm(), 0.0);
  }
  // The run did something: the bump has spread and its energy is kept.
  EXPECT_GT((u - lattice.u0).cwiseAbs().maxCoeff(), 0.1 * lattice.u0.cwiseAbs().maxCoeff());
  if (!loaded) {
    const Real initialEnergy = serial.strainEnergy(lattice.u0);
    EXPECT_NEAR(serialEnergy, initialEnergy, 0.05 * initialEnergy);
  }
}

}  // namespace

TEST(DistributedLatticeSystemMpiTest, ACentralDifferenceRunOnTheRanksKeepsTheSerialBits) {
  expectTheDistributedRunKeepsTheSerialBits<3>({26, 15, 12}, false);
  expectTheDistributedRunKeepsTheSerialBits<2>({41, 23}, false);
}

TEST(DistributedLatticeSystemMpiTest, DashpotsAndLoadsOnTheRanksKeepTheSerialBits) {
  expectTheDistributedRunKeepsTheSerialBits<3>({26, 15, 12}, true);
  expectTheDistributedRunKeepsTheSerialBits<2>({41, 23}, true);
}

// Dashpots that couple nodes: C v through its own halo, the surface block solved whole on every
// rank from the right-hand side gathered from its owners.
TEST(DistributedLatticeSystemMpiTest, DashpotsThatCoupleNodesOnTheRanksKeepTheSerialBits) {
  expectTheDistributedRunKeepsTheSerialBits<3>({26, 15, 12}, true, true);
  expectTheDistributedRunKeepsTheSerialBits<2>({41, 23}, true, true);
}

// A 1-D lattice has only x to split: each rank owns a piece of the one lattice line, and the sums
// chain the pieces in x order (LineSums.hpp). (The case's coupled dashpots need a face of more
// than one node, so 1-D has own-dof dashpots only.)
TEST(DistributedLatticeSystemMpiTest, AOneDimensionalLatticeCutAlongXKeepsTheSerialBits) {
  expectTheDistributedRunKeepsTheSerialBits<1>({41}, false);
  expectTheDistributedRunKeepsTheSerialBits<1>({41}, true);
}

// 2-D and 3-D lattices with every axis splittable: the grids with the smallest faces cut x on 2 to
// 4 ranks (checked above; on 4 ranks y too), so the lines' pieces chain their sums within each
// x-row of the rank grid, several rows at once where y is cut as well.
TEST(DistributedLatticeSystemMpiTest, LatticesCutAlongXKeepTheSerialBits) {
  expectTheDistributedRunKeepsTheSerialBits<2>({41, 23}, false, false, true);
  expectTheDistributedRunKeepsTheSerialBits<2>({41, 23}, true, false, true);
  expectTheDistributedRunKeepsTheSerialBits<2>({41, 23}, true, true, true);
  expectTheDistributedRunKeepsTheSerialBits<3>({26, 15, 12}, true, true, true);
}

// A lattice share keeps x whole when the other axes can take the ranks (whole lines run faster),
// and cuts x only when it must: always in 1-D, and when the other axes have too few nodes.
TEST(DistributedLatticeSystemMpiTest, ALatticeShareCutsXOnlyWhenItMust) {
  LatticeCase<1> line({41});
  const LatticeShare<1> pieces(*line.serial, MPI_COMM_WORLD);
  EXPECT_EQ(pieces.decomposition().grid()[0], worldSize());
  LatticeCase<2> plane({41, 23});  // all axes may be cut: 2 or 3 ranks would cut x, not y
  const LatticeShare<2> rows(*plane.serial, MPI_COMM_WORLD);
  EXPECT_EQ(rows.decomposition().grid()[0], 1);
  EXPECT_EQ(rows.decomposition().grid()[1], worldSize());
  if (worldSize() > 2) {
    LatticeCase<2> strip({41, 2}, false, false, true);  // 3 or 4 ranks do not fit 2 nodes across
    const LatticeShare<2> cut(*strip.serial, MPI_COMM_WORLD);
    EXPECT_GT(cut.decomposition().grid()[0], 1);
  }
}

namespace {

// Prescribed displacements (eq. (30)) on a rank's share: the serial run holds every dof of the
// -x face and of one interior node at g(t) (one component of the interior node only, so its free
// components are solved again from its block); each rank holds its own dofs of that list, in its
// numbering, at the same values. With own-dof dashpots on the faces too.
template <int D>
void expectPrescribedDofsKeepTheSerialBits(const std::array<Index, D>& nodes, bool loaded) {
  LatticeCase<D> lattice(nodes, loaded);
  LatticeSecondOrderSystem<D>& serial = *lattice.serial;
  DistributedLatticeSystem<D>& distributed = *lattice.distributed;
  std::vector<Index> dofs;
  for (Index p = 0; p < serial.types().nodeCount(); ++p)
    if (serial.types().node(p)[0] == 0)
      for (int c = 0; c < D; ++c) dofs.push_back(D * p + c);
  Box<D> all;
  all.hi = nodes;
  std::array<Index, D> middle{};
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) middle[s] = nodes[s] / 2;
  dofs.push_back(D * all.localIndex(middle) + (D - 1));
  auto g = [](Real t, Index k) { return 0.02 * std::sin(3 * t + 0.1 * static_cast<Real>(k)); };
  const Real dt = 0.1;
  const int steps = 60;
  Vector u0 = lattice.u0;
  for (std::size_t k = 0; k < dofs.size(); ++k) u0[dofs[k]] = g(0, static_cast<Index>(k));
  CentralDifference serialRun;
  serialRun.setPrescribedDisplacement(dofs, [&](Real t, Vector& values) {
    for (Index k = 0; k < values.size(); ++k) values[k] = g(t, k);
  });
  serialRun.initialise(serial, 0, u0, lattice.v0, dt);
  for (int n = 0; n < steps; ++n) serialRun.step();

  std::vector<Index> mine, which;  // this rank's dofs, and their places in the serial list
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    const Index local = distributed.localNode(dofs[k] / D);
    if (local < 0) continue;
    mine.push_back(D * local + dofs[k] % D);
    which.push_back(static_cast<Index>(k));
  }
  CentralDifference run;
  run.setPrescribedDisplacement(mine, [&](Real t, Vector& values) {
    for (Index k = 0; k < values.size(); ++k) values[k] = g(t, which[static_cast<std::size_t>(k)]);
  });
  run.initialise(distributed, 0, distributed.restrict(u0), distributed.restrict(lattice.v0), dt);
  for (int n = 0; n < steps; ++n) run.step();
  const long different = test::differencesOverRanks(distributed, run.state().displacement,
                                                     serialRun.state().displacement) +
                         test::differencesOverRanks(distributed, run.state().velocity, serialRun.state().velocity);
  EXPECT_EQ(different, 0) << D << "-D on " << worldSize() << " ranks";
  // The prescribed dofs moved as g says, and the free components of the interior node did too.
  const Index last = dofs.back();
  EXPECT_EQ(serialRun.state().displacement[last], g(steps * dt, static_cast<Index>(dofs.size() - 1)));
  EXPECT_NE(serialRun.state().displacement[last - 1], lattice.u0[last - 1]);
}

}  // namespace

TEST(DistributedLatticeSystemMpiTest, PrescribedDofsOnTheRanksKeepTheSerialBits) {
  expectPrescribedDofsKeepTheSerialBits<3>({26, 15, 12}, false);
  expectPrescribedDofsKeepTheSerialBits<3>({26, 15, 12}, true);
  expectPrescribedDofsKeepTheSerialBits<2>({41, 23}, true);
}

// What the distributed system does not take yet is refused by name: a load given as a function,
// and prescribed dofs beside dashpots that couple nodes.
TEST(DistributedLatticeSystemMpiTest, ALoadFunctionAndPrescribedDofsBesideCoupledDashpotsAreRefusedByName) {
  const LatticeRowTypes<2> types({12, 9}, 1);
  const Index n = 2 * types.compactNodes()[0] * types.compactNodes()[1];
  SparseMatrix identity(n, n);
  identity.setIdentity();
  const BlockDecomposition<2> decomposition(types, worldSize(), {}, {false, true});
  std::string key;
  try {
    const LatticeSecondOrderSystem<2> serial(LatticeStencils<2>(types, identity), LatticeStencils<2>(),
                                             LatticeStencils<2>(types, identity),
                                             [](Real, Eigen::Ref<Vector> f) { f[0] += 1; });
    DistributedLatticeSystem<2> distributed(serial, decomposition, worldRank(), MPI_COMM_WORLD);
  } catch (const InputError& e) {
    key = e.key();
  }
  EXPECT_EQ(key, "loads");
  LatticeCase<2> coupled({41, 23}, true, true);
  key.clear();
  try {
    coupled.distributed->centredDamping(0.1, {0});
  } catch (const InputError& e) {
    key = e.key();
  }
  EXPECT_EQ(key, "prescribed_displacement");
}
