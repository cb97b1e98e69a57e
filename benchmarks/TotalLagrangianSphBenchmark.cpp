// Total-Lagrangian SPH (lib/methods/total_lagrangian_sph): one acceleration evaluation (deformation
// gradients, Saint Venant-Kirchhoff stress, the pair forces and the hourglass penalty) in 2-D and
// 3-D on a square / cube lattice with h = 1.3 dp (cubic spline), a smooth displacement field.
// Arguments: particles per side, OpenMP threads. Counters: particle_steps/s, per core, pairs per
// particle, bytes per particle of the reference pairs (index + gradient per pair, B and V per
// particle). Wall-clock time (UseRealTime): the 2-thread numbers need an otherwise idle machine.

#include "methods/total_lagrangian_sph/TotalLagrangianSph.hpp"
#include "particles/Lattice.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>

using namespace mfwave;

namespace {

template <int D>
void acceleration(benchmark::State& state) {
  const auto perSide = static_cast<Index>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  const Real dp = 1.0 / static_cast<Real>(perSide - 1);
  const ParticleSet<D> particles = makeLattice<D>(Vec<D>::Zero(), Vec<D>::Ones(), dp);
  TotalLagrangianSphOptions options;
  options.material = Material::fromYoung(1e7, 0.3, 1000);
  TotalLagrangianSph<D> system(particles, options);
  const Index n = system.particleCount();
  Vector u(n * D), v = Vector::Zero(n * D), a(n * D);
  for (Index i = 0; i < n; ++i)
    for (int c = 0; c < D; ++c) u[i * D + c] = 1e-3 * std::sin(3.0 * particles.position(i)[(c + 1) % D]);
  for (auto _ : state) {
    system.acceleration(0, u, v, a);
    benchmark::DoNotOptimize(a.data());
  }
  const auto iterations = static_cast<double>(state.iterations());
  state.counters["particle_steps/s"] = benchmark::Counter(static_cast<double>(n) * iterations, benchmark::Counter::kIsRate);
  state.counters["particle_steps/s/core"] =
      benchmark::Counter(static_cast<double>(n) * iterations / threads, benchmark::Counter::kIsRate);
  state.counters["pairs_per_particle"] = system.meanNeighbourCount();
  state.counters["particles"] = static_cast<double>(n);
  state.counters["bytes_per_particle"] =
      system.meanNeighbourCount() * static_cast<double>(sizeof(Index) + D * sizeof(Real)) +
      static_cast<double>((D * D + 1 + 3 * D) * sizeof(Real));
}

void Acceleration2d(benchmark::State& state) { acceleration<2>(state); }
void Acceleration3d(benchmark::State& state) { acceleration<3>(state); }

// 2-D: 101^2 = 1.0e4, 317^2 = 1.0e5, 1001^2 = 1.0e6 particles; 3-D: 22^3 = 1.1e4, 47^3 = 1.0e5.
BENCHMARK(Acceleration2d)->ArgsProduct({{101, 317, 1001}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(Acceleration3d)->ArgsProduct({{22, 47}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
