// Kernel evaluations per second in 3-D: value, gradient and Hessian over a batch of pair vectors
// spread through the support, called through the Kernel base as the particle loops do.

#include "kernels/KernelFactory.hpp"

#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

namespace {

using mfwave::Real;
using mfwave::Vec3;

const std::vector<std::string>& benchmarkedKernels() {
  static const std::vector<std::string> names = {"cubic_spline", "gaussian", "quintic_spline", "wendland_c2",
                                                 "wendland_c4"};
  return names;
}

// Pair vectors with |r| uniform in a cube around the support, so some fall outside, as in a
// cell-list neighbour loop.
std::vector<Vec3> pairVectors(Real supportRadius) {
  std::mt19937 rng(42u);
  std::uniform_real_distribution<Real> coordinate(-supportRadius, supportRadius);
  std::vector<Vec3> pairs(4096);
  for (Vec3& r : pairs) r = Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
  return pairs;
}

template <class Evaluate>
void runKernelBenchmark(benchmark::State& state, Evaluate evaluate) {
  const auto kernel = mfwave::makeKernel(benchmarkedKernels()[static_cast<std::size_t>(state.range(0))], 3, 0.5);
  const std::vector<Vec3> pairs = pairVectors(kernel->supportRadius());
  for (auto _ : state) {
    for (const Vec3& r : pairs) evaluate(*kernel, r);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs.size()));
  state.SetLabel(kernel->name());
}

void BM_Value3D(benchmark::State& state) {
  runKernelBenchmark(state, [](const mfwave::Kernel& k, const Vec3& r) { benchmark::DoNotOptimize(k.value(r)); });
}

void BM_Gradient3D(benchmark::State& state) {
  runKernelBenchmark(state, [](const mfwave::Kernel& k, const Vec3& r) { benchmark::DoNotOptimize(k.gradient(r)); });
}

void BM_Hessian3D(benchmark::State& state) {
  runKernelBenchmark(state, [](const mfwave::Kernel& k, const Vec3& r) { benchmark::DoNotOptimize(k.hessian(r)); });
}

BENCHMARK(BM_Value3D)->DenseRange(0, 4);
BENCHMARK(BM_Gradient3D)->DenseRange(0, 4);
BENCHMARK(BM_Hessian3D)->DenseRange(0, 4);

}  // namespace

BENCHMARK_MAIN();
