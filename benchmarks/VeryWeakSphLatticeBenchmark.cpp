// The very weak SPH (galerkin variant) stored as lattice stencils (issue 18) on the lamb3d setting
// scaled up: a block with n nodes per side, free top face, dashpots on the other five, lambda = mu =
// rho = 1. Sides 100 (1.0 x 10^6 particles) and 216 (1.0 x 10^7), 1 and 2 OpenMP threads.
//  - Setup: VeryWeakSphProblem with the lattice storage (compact assemblies, checks, loads).
//  - Acceleration: one a = M^-1 (f - K u - C v): the operator applied once, fused with the mass.
//  - Step: one central-difference step with the dashpot solve of eq. (32), what a run pays.
// Counters: particle_steps/s, bytes_per_particle (the vectors a step streams: nothing of the
// operator is per particle), bandwidth (bytes streamed per second), of_triad (that over the triad
// bandwidth measured in the same process: the bound of a streaming loop), flops_per_particle (a
// multiply and an add per nonzero coefficient of the interior row), gflops and of_peak (over the
// machine's peak: the clock of /proc/cpuinfo x 16 flops per cycle per core, two 4-wide multiply
// and two 4-wide add pipes, x threads; the loop does not fuse multiply and add, to stay bitwise
// equal across instruction sets).

#include "GalerkinBlock.hpp"
#include "core/TimeFunction.hpp"
#include "integrators/CentralDifference.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <fstream>
#include <string>
#include <map>
#include <memory>
#include <vector>

using namespace mfwave;

namespace {

constexpr Real kSpacing = 0.05;

VeryWeakSphProblemSettings<3> settingsFor(Index side) {
  return bench::galerkinBlock({side, side, side}, kSpacing, static_cast<std::uint8_t>(allFaces(3) & ~faceBit(BoxFace::PlusZ)));
}

// The triad a = b + s c over 3 x 2e7 doubles on `threads` threads, bytes per second (best of 5).
double triadBandwidth(int threads) {
  static std::map<int, double> measured;
  if (measured.count(threads)) return measured[threads];
  omp_set_num_threads(threads);
  const std::ptrdiff_t n = 20000000;
  std::vector<double> a(static_cast<std::size_t>(n)), b(static_cast<std::size_t>(n), 1.0), c(static_cast<std::size_t>(n), 2.0);
  double best = 0;
  for (int repeat = 0; repeat < 5; ++repeat) {
    const auto start = std::chrono::steady_clock::now();
    double* pa = a.data();
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) pa[i] = b[static_cast<std::size_t>(i)] + 3.0 * c[static_cast<std::size_t>(i)];
    benchmark::DoNotOptimize(a.data());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, 24.0 * static_cast<double>(n) / seconds);
  }
  return measured[threads] = best;
}

// Peak double-precision flops per second of one core: clock x 16 (see above).
double corePeakFlops() {
  std::ifstream info("/proc/cpuinfo");
  std::string line;
  while (std::getline(info, line))
    if (line.rfind("cpu MHz", 0) == 0) return std::stod(line.substr(line.find(':') + 1)) * 1e6 * 16.0;
  return 0;
}

struct Case {
  ParticleSet<3> particles;
  std::unique_ptr<VeryWeakSphProblem<3>> problem;
};

Case& caseFor(Index side) {
  static std::map<Index, Case> cases;
  auto it = cases.find(side);
  if (it != cases.end()) return it->second;
  if (!cases.empty()) cases.clear();  // one size at a time: 10^7 particles are a gigabyte of state
  Case& c = cases[side];
  const VeryWeakSphProblemSettings<3> s = settingsFor(side);
  c.particles = makeLattice<3>(s.lower, s.upper, s.spacing);
  c.problem = std::make_unique<VeryWeakSphProblem<3>>(c.particles, s);
  return c;
}

void setCounters(benchmark::State& state, Index particles, double bytesPerParticle, int threads) {
  const auto& k = dynamic_cast<const LatticeSecondOrderSystem<3>&>(caseFor(state.range(0)).problem->system()).stiffness();
  // the interior type: the middle of the compact lattice
  const Index interior = k.types().typeCount() / 2;
  double nonzeros = 0;
  for (Index e = k.begin(interior); e < k.end(interior); ++e)
    for (int i = 0; i < 9; ++i) nonzeros += k.block(e)[i] != 0 ? 1 : 0;
  const double flops = 2.0 * nonzeros;
  const double rate = static_cast<double>(particles) * static_cast<double>(state.iterations());
  state.counters["particle_steps/s"] = benchmark::Counter(rate, benchmark::Counter::kIsRate);
  state.counters["bytes_per_particle"] = bytesPerParticle;
  state.counters["bandwidth"] = benchmark::Counter(rate * bytesPerParticle, benchmark::Counter::kIsRate,
                                                   benchmark::Counter::kIs1024);
  state.counters["of_triad"] = benchmark::Counter(rate * bytesPerParticle / triadBandwidth(threads),
                                                 benchmark::Counter::kIsRate);
  state.counters["of_peak"] =
      benchmark::Counter(rate * flops / (corePeakFlops() * threads), benchmark::Counter::kIsRate);
  state.counters["flops_per_particle"] = flops;
  state.counters["gflops"] = benchmark::Counter(rate * flops * 1e-9, benchmark::Counter::kIsRate);
}

void Setup(benchmark::State& state) {
  const Index side = state.range(0);
  omp_set_num_threads(static_cast<int>(state.range(1)));
  const VeryWeakSphProblemSettings<3> s = settingsFor(side);
  const ParticleSet<3> particles = makeLattice<3>(s.lower, s.upper, s.spacing);
  for (auto _ : state) {
    VeryWeakSphProblem<3> problem(particles, s);
    benchmark::DoNotOptimize(&problem);
  }
  state.counters["particles"] = static_cast<double>(particles.physicalCount());
}

void Acceleration(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(1));
  Case& c = caseFor(state.range(0));
  omp_set_num_threads(threads);
  LinearOperatorSystem& system = c.problem->system();
  const Vector u = Vector::Random(system.size()), v = Vector::Random(system.size());
  Vector a(system.size());
  system.acceleration(0.5, u, v, a);  // warm: first touch of a's pages outside the timing
  for (auto _ : state) {
    system.acceleration(0.5, u, v, a);
    benchmark::DoNotOptimize(a.data());
  }
  // zeroing a, then u and v read and a read and written once (the surface's v is a small part)
  setCounters(state, c.particles.physicalCount(), 8.0 * 3 * 4, threads);
}

void Step(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(1));
  Case& c = caseFor(state.range(0));
  omp_set_num_threads(threads);
  LinearOperatorSystem& system = c.problem->system();
  CentralDifference integrator;
  integrator.initialise(system, 0, Vector::Random(system.size()) * 1e-3, Vector::Zero(system.size()), 1e-3);
  integrator.step();  // warm
  for (auto _ : state) integrator.step();
  // kick (v, a), drift (u, v), the solve (zero a, read u, v, a, write a), the synchronous v (v, a, v)
  setCounters(state, c.particles.physicalCount(), 8.0 * 3 * (3 + 3 + 4 + 3), threads);
}

void sizes(benchmark::internal::Benchmark* b) {
  for (long side : {100L, 216L})
    for (long threads : {1L, 2L}) b->Args({side, threads});
}

}  // namespace

BENCHMARK(Setup)->Apply(sizes)->ArgNames({"side", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(Acceleration)->Apply(sizes)->ArgNames({"side", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Step)->Apply(sizes)->ArgNames({"side", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
