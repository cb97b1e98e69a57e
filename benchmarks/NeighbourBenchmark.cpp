// Neighbour search throughput: cell-list rebuild and CSR neighbour-list build for 3-D clouds
// of 10^5 and 10^6 particles with ~45 (random) or 57 (lattice) neighbours each, the range of
// SPH / RKPM supports. A moving-particle run pays both every step, a fixed one pays them once.
// Wall-clock time (UseRealTime): the work runs on OpenMP threads.

#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/Lattice.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

using namespace mfwave;

namespace {


// n points uniform in the unit cube, and the radius whose ball holds `neighbours` on average.
Coordinates<3> randomCloud(Index n) {
  std::mt19937_64 engine(12345);
  std::uniform_real_distribution<Real> uniform(0, 1);
  Coordinates<3> x;
  for (auto& axis : x) axis.resize(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i)
    for (auto& axis : x) axis[static_cast<std::size_t>(i)] = uniform(engine);
  return x;
}
Real radiusFor(Index n, Real neighbours) { return std::cbrt(3 * neighbours / (4 * kPi * static_cast<Real>(n))); }

// A cubic lattice with about n nodes and spacing 1; radius 2.3 spacings: 57 neighbours inside.
Coordinates<3> latticeCloud(Index n) {
  const Real side = std::round(std::cbrt(static_cast<Real>(n))) - 1;
  return makeBlock(Vec3::Zero(), Vec3::Constant(side), 1.0).coordinates();
}

void run(benchmark::State& state, const Coordinates<3>& x, Real radius, bool listToo) {
  CellList<3> cells(radius);
  NeighbourList list;
  // One untimed build first: the timed ones are the steady-state rebuilds of a moving-particle
  // run, which reuse the storage instead of page-faulting it in (360 MB of indices at 10^6).
  cells.rebuild(x);
  if (listToo) buildNeighbourList(cells, list);
  for (auto _ : state) {
    cells.rebuild(x);
    if (listToo) buildNeighbourList(cells, list);
    benchmark::DoNotOptimize(list.indices.data());
    benchmark::DoNotOptimize(cells.sortedIndex().data());
    benchmark::ClobberMemory();
  }
  const auto n = static_cast<Real>(x[0].size());
  state.counters["particles"] = n;
  state.counters["particles/s"] = benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
  if (listToo) state.counters["mean_neighbours"] = list.meanCount();
}

void NeighbourListRandom(benchmark::State& state) {
  const Coordinates<3> x = randomCloud(state.range(0));
  run(state, x, radiusFor(state.range(0), 45), true);
}
void NeighbourListLattice(benchmark::State& state) {
  run(state, latticeCloud(state.range(0)), 2.3, true);
}
void CellListRebuildRandom(benchmark::State& state) {
  const Coordinates<3> x = randomCloud(state.range(0));
  run(state, x, radiusFor(state.range(0), 45), false);
}

}  // namespace

BENCHMARK(NeighbourListRandom)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(NeighbourListLattice)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(CellListRebuildRandom)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
