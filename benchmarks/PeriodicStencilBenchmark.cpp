// The planewave study's operator, u'' = A u on a periodic lattice with one method's interior row on
// every node, applied two ways: the assembled sparse matrix (periodicLatticeSystem, what the study
// stepped on before) and the matrix-free stencil (periodicStencilSystem, lib/lattice). Methods: the
// consistent very weak SPH (cubic spline, h = 1.3 dx: 2 x 2 blocks at 25 offsets) and the 5-point
// finite difference, 2-D, 256^2 and 1024^2 nodes; 1 and 2 OpenMP threads.
// Counter: particle_steps/s (one product per step: what a central-difference step costs beyond its
// vector updates).

#include "spectra/LatticeMethods.hpp"
#include "numerics/PeriodicLattice.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <memory>
#include <string>

using namespace mfwave;

namespace {

PeriodicLatticeOperator<2> planeWaveOperator(const std::string& method, int cells) {
  const Real dx = 1.0 / cells;
  const MethodLatticeStencil<2> stencil = latticeMethodStencil<2>(method, LatticeMethodSettings{}, dx);
  return makePeriodicLatticeOperator<2>(stencil.acceleration, dx, cells, stencil.mass);
}

void run(benchmark::State& state, const std::string& method, bool matrixFree) {
  const int cells = static_cast<int>(state.range(0)), threads = static_cast<int>(state.range(1));
  const auto op = planeWaveOperator(method, cells);
  std::unique_ptr<LinearOperatorSystem> system;
  if (matrixFree)
    system = periodicStencilSystem(op);
  else
    system = std::make_unique<LinearSecondOrderSystem>(periodicLatticeSystem(op));
  Vector u = Vector::LinSpaced(op.size(), 0, 1), a(op.size());
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  system->acceleration(0, u, u, a);  // whatever a storage prepares on first use stays out of the timing
  for (auto _ : state) {
    system->acceleration(0, u, u, a);
    benchmark::DoNotOptimize(a.data());
    benchmark::ClobberMemory();
  }
  omp_set_num_threads(before);
  state.counters["particle_steps/s"] =
      benchmark::Counter(static_cast<double>(op.nodes()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_VwsphConsistentSparse(benchmark::State& s) { run(s, "vwsph_consistent", false); }
void BM_VwsphConsistentStencil(benchmark::State& s) { run(s, "vwsph_consistent", true); }
void BM_FiniteDifferenceSparse(benchmark::State& s) { run(s, "finite_difference", false); }
void BM_FiniteDifferenceStencil(benchmark::State& s) { run(s, "finite_difference", true); }

void sizes(benchmark::internal::Benchmark* b) {
  for (int cells : {256, 1024})
    for (int threads : {1, 2}) b->Args({cells, threads});
  b->ArgNames({"cells", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();
}

}  // namespace

BENCHMARK(BM_VwsphConsistentSparse)->Apply(sizes);
BENCHMARK(BM_VwsphConsistentStencil)->Apply(sizes);
BENCHMARK(BM_FiniteDifferenceSparse)->Apply(sizes);
BENCHMARK(BM_FiniteDifferenceStencil)->Apply(sizes);

BENCHMARK_MAIN();
