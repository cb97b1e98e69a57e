// Updated-Lagrangian SPH (lib/methods/updated_lagrangian_sph): one full step of the right-hand side
// in 2-D and 3-D, on a square / cube lattice with h = 1.3 dp (cubic spline), a smooth velocity field
// and some stress, so every term of the momentum, stress and energy equations is evaluated.
//  - Rhs:        F(t, y) with the neighbour lists valid (what most stages of a run pay).
//  - RebuildRhs: the particles are moved by more than half the skin before every evaluation, so each
//                one also rebuilds the cell list and the neighbour lists: the worst case of a step.
//  - CorrectedRhs: Rhs with the kernel-gradient correction (one more pass over the pairs).
// Arguments: particles per side, OpenMP threads.
// Counters: particle_steps/s (evaluations per second times particles), particle_steps/s/core (divided
// by the threads), mean_neighbours (self included, list radius (1 + skin) 2h), bytes_per_particle
// (state y, its rate and the neighbour indices). Wall-clock time (UseRealTime): the work runs on
// OpenMP threads; the 2-thread numbers need an otherwise idle machine.

#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "particles/Lattice.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>

using namespace mfwave;

namespace {

template <int D>
ParticleSet<D> cubeLattice(Index perSide) {
  const Real dp = 1.0 / static_cast<Real>(perSide - 1);
  return makeLattice<D>(Vec<D>::Zero(), Vec<D>::Ones(), dp);
}

template <int D>
void fullStep(benchmark::State& state, bool rebuildEveryStep, bool corrected = false) {
  const auto perSide = static_cast<Index>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  const ParticleSet<D> particles = cubeLattice<D>(perSide);
  UpdatedLagrangianSphOptions options;
  options.material = Material::fromYoung(1e7, 0.3, 1000);
  options.artificialStress.enabled = true;
  options.kernelGradientCorrection = corrected;
  UpdatedLagrangianSph<D> system(particles, options);
  const Index n = system.particleCount();
  Vector velocity(n * D);
  for (Index i = 0; i < n; ++i)
    for (int a = 0; a < D; ++a) velocity[i * D + a] = 0.01 * std::sin(3.0 * particles.position(i)[(a + 1) % D]);
  Vector y = system.initialState(velocity);
  const auto& layout = system.layout();
  for (Index i = 0; i < n; ++i) y[layout.stress(i, 0)] = 1e3 * particles.position(i)[0];
  Vector ydot(y.size());
  system.rhs(0, y, ydot);  // builds the lists once

  // A shift of the whole body that exceeds half the skin: forces a rebuild without changing any pair.
  const Real shift = system.options().neighbourSkin * 2.0 * system.smoothingLength();
  Real sign = 1;
  for (auto _ : state) {
    if (rebuildEveryStep) {
      for (Index i = 0; i < n; ++i) y[layout.position(i, 0)] += sign * shift;
      sign = -sign;
    }
    system.rhs(0, y, ydot);
    benchmark::DoNotOptimize(ydot.data());
  }
  const auto iterations = static_cast<double>(state.iterations());
  state.counters["particle_steps/s"] = benchmark::Counter(static_cast<double>(n) * iterations, benchmark::Counter::kIsRate);
  state.counters["particle_steps/s/core"] =
      benchmark::Counter(static_cast<double>(n) * iterations / threads, benchmark::Counter::kIsRate);
  state.counters["mean_neighbours"] = system.meanNeighbourCount();
  state.counters["particles"] = static_cast<double>(n);
  state.counters["rebuilds"] = static_cast<double>(system.neighbourRebuilds());
  state.counters["bytes_per_particle"] =
      static_cast<double>(2 * y.size() * 8) / static_cast<double>(n) + system.meanNeighbourCount() * 8;
}

void Rhs2d(benchmark::State& state) { fullStep<2>(state, false); }
void RebuildRhs2d(benchmark::State& state) { fullStep<2>(state, true); }
void Rhs3d(benchmark::State& state) { fullStep<3>(state, false); }
void RebuildRhs3d(benchmark::State& state) { fullStep<3>(state, true); }
void CorrectedRhs2d(benchmark::State& state) { fullStep<2>(state, false, true); }
void CorrectedRhs3d(benchmark::State& state) { fullStep<3>(state, false, true); }

// 2-D: 101^2 = 1.0e4, 317^2 = 1.0e5, 1001^2 = 1.0e6 particles; 3-D: 22^3 = 1.1e4, 47^3 = 1.0e5, 100^3 = 1e6.
BENCHMARK(Rhs2d)->ArgsProduct({{101, 317, 1001}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(RebuildRhs2d)->ArgsProduct({{101, 317, 1001}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(Rhs3d)->ArgsProduct({{22, 47, 100}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(RebuildRhs3d)->ArgsProduct({{22, 47, 100}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(CorrectedRhs2d)->ArgsProduct({{101, 317, 1001}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(CorrectedRhs3d)->ArgsProduct({{22, 47, 100}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
