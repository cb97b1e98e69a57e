#pragma once
// What the tests under mpirun share (tests/decomposition/mpi): this rank and the rank count,
// reductions of a test's findings over the ranks, and the lattice case of the distributed runs.

#include "decomposition/mpi/DistributedLatticeSystem.hpp"
#include "lattice/LatticeSecondOrderSystem.hpp"

#include "core/TimeFunction.hpp"
#include "systems/SparseLoads.hpp"

#include <mpi.h>

#include <cmath>
#include <optional>
#include <vector>

namespace mfwave::test {

inline int worldRank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

inline int worldSize() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

inline long sumOverRanks(long value) {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  return value;
}

inline Real maxOverRanks(Real value) {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return value;
}

// Owned entries of `got` that differ from the owned part of the serial `expected`, over all ranks.
template <int D, int C>
long differencesOverRanks(const DistributedLatticeSystem<D, C>& system, const Vector& got, const Vector& expected) {
  const Vector mine = system.restrict(expected);
  long different = 0;
  for (Index i = 0; i < mine.size(); ++i)
    if (got[i] != mine[i]) ++different;
  return sumOverRanks(different);
}

// max |got - expected| over the owned entries of all ranks, relative to max |expected|.
template <int D, int C>
Real relativeDifferenceOverRanks(const DistributedLatticeSystem<D, C>& system, const Vector& got, const Vector& expected) {
  const Vector mine = system.restrict(expected);
  return maxOverRanks((got - mine).cwiseAbs().maxCoeff()) / expected.cwiseAbs().maxCoeff();
}

// The lattice case of the distributed runs: M u'' + C u' + K u = f on `nodes`, K the lattice
// Laplacian of the 3^D - 1 neighbours (weight 1 / |offset|^2, fewer neighbours at the faces),
// M = 1.5 I, a smooth bump as u0, at rest; the serial system and this rank's share of it (x kept
// whole, unless `splitX` or in 1-D: then every axis may be cut, and the grid with the smallest
// faces often cuts x). With `loaded`, the faces carry dashpots on their own dofs (C = 0.7 I there, the Galerkin
// very weak SPH's kind) and two loads of their own histories push on a few nodes (one near a
// corner, one in the middle). With `coupled` too, each face node's dashpot also pulls on its face
// neighbours along every axis (-0.1 I each): dashpots that couple nodes, as the consistent very
// weak SPH's do, solved through the surface block of eq. (32).
template <int D>
struct LatticeCase {
  LatticeCase(const std::array<Index, D>& nodes, bool loaded = false, bool coupled = false, bool splitX = false)
      : types(nodes, 1), ramp(TimeFunction::ramp(0.5, 2.0, 3.0)), constant(TimeFunction::constant(-0.4)) {
    Box<D> compact;
    compact.hi = types.compactNodes();
    std::vector<Triplet> k, m, dashpots;
    compact.forEachNode([&](const std::array<Index, D>& row) {
      const Index i = compact.localIndex(row);
      bool face = false;
      for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) face = face || row[s] == 0 || row[s] == compact.hi[s] - 1;
      if (face && loaded)
        for (int c = 0; c < D; ++c) dashpots.emplace_back(static_cast<int>(D * i + c), static_cast<int>(D * i + c), 0.7);
      if (face && loaded && coupled)
        for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s)
          for (Index step : {Index{-1}, Index{1}}) {
            std::array<Index, D> next = row;
            next[s] += step;
            if (!compact.contains(next)) continue;
            bool nextOnFace = false;
            for (std::size_t r = 0; r < static_cast<std::size_t>(D); ++r)
              nextOnFace = nextOnFace || next[r] == 0 || next[r] == compact.hi[r] - 1;
            if (!nextOnFace) continue;
            const Index j = compact.localIndex(next);
            for (int c = 0; c < D; ++c) dashpots.emplace_back(static_cast<int>(D * i + c), static_cast<int>(D * j + c), -0.1);
          }
      Box<D> around;
      for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
        around.lo[s] = row[s] - 1;
        around.hi[s] = row[s] + 2;
      }
      Real diagonal = 0;
      intersection(around, compact).forEachNode([&](const std::array<Index, D>& column) {
        const Index j = compact.localIndex(column);
        if (j == i) return;
        Real r2 = 0;
        for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s)
          r2 += static_cast<Real>((column[s] - row[s]) * (column[s] - row[s]));
        for (int c = 0; c < D; ++c) k.emplace_back(static_cast<int>(D * i + c), static_cast<int>(D * j + c), -1.0 / r2);
        diagonal += 1.0 / r2;
      });
      for (int c = 0; c < D; ++c) {
        k.emplace_back(static_cast<int>(D * i + c), static_cast<int>(D * i + c), diagonal);
        m.emplace_back(static_cast<int>(D * i + c), static_cast<int>(D * i + c), 1.5);
      }
    });
    const int unknowns = static_cast<int>(D * compact.count());
    SparseMatrix stiffness(unknowns, unknowns), mass(unknowns, unknowns), damping(unknowns, unknowns);
    stiffness.setFromTriplets(k.begin(), k.end());
    mass.setFromTriplets(m.begin(), m.end());
    damping.setFromTriplets(dashpots.begin(), dashpots.end());

    Box<D> all;
    all.hi = nodes;
    std::vector<SparseLoad> loads;
    if (loaded) {
      std::array<Index, D> corner{}, middle{};
      for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
        corner[s] = 1;
        middle[s] = nodes[s] / 2;
      }
      loads.push_back({{D * all.localIndex(corner), D * all.localIndex(middle) + D - 1}, {1.25, -0.5}, &ramp});
      loads.push_back({{D * all.localIndex(middle)}, {0.75}, &constant});
    }
    serial.emplace(LatticeStencils<D>(types, mass), loaded ? LatticeStencils<D>(types, damping) : LatticeStencils<D>(),
                   LatticeStencils<D>(types, stiffness), loads);

    u0 = Vector::Zero(D * types.nodeCount());
    v0 = Vector::Zero(D * types.nodeCount());
    all.forEachNode([&](const std::array<Index, D>& node) {
      Real r2 = 0;
      for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
        const Real x = (static_cast<Real>(node[s]) - 0.4 * static_cast<Real>(nodes[s])) / static_cast<Real>(nodes[s]);
        r2 += x * x;
      }
      for (int c = 0; c < D; ++c) u0[D * all.localIndex(node) + c] = std::exp(-20 * r2) * (1.0 + 0.1 * c);
    });
    std::array<bool, D> splittable = BlockDecomposition<D>::allAxes();
    splittable[0] = splitX || D == 1;  // x whole: the decomposition a lattice share prefers
    decomposition.emplace(types, worldSize(), std::vector<Real>{}, splittable);
    distributed.emplace(*serial, *decomposition, worldRank(), MPI_COMM_WORLD);
  }

  LatticeCase(const LatticeCase&) = delete;  // the loads point at the histories below
  LatticeCase& operator=(const LatticeCase&) = delete;

  LatticeRowTypes<D> types;
  TimeFunction ramp, constant;  // the loads' histories
  std::optional<LatticeSecondOrderSystem<D>> serial;
  std::optional<BlockDecomposition<D>> decomposition;
  std::optional<DistributedLatticeSystem<D>> distributed;
  Vector u0, v0;
};

}  // namespace mfwave::test
