// Reproducing-kernel shape-function evaluations per second (values, gradients and Hessians, as
// strong-form collocation needs them) in 2-D and 3-D for orders m = 1..3, on a perturbed lattice
// with support radius a = (m + 1.5) dx, the radius the unit tests use. One ShapeFunctionValues is
// reused, as in an assembly loop.

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"

namespace {

using mfwave::Coordinates;
using mfwave::Real;

template <int D>
Coordinates<D> perturbedLattice(int cells) {
  const Real dx = 1.0 / cells;
  std::mt19937 rng(7u);
  std::uniform_real_distribution<Real> shift(-0.3 * dx, 0.3 * dx);
  Coordinates<D> nodes;
  const int along[3] = {cells + 1, D >= 2 ? cells + 1 : 1, D >= 3 ? cells + 1 : 1};
  for (int k = 0; k < along[2]; ++k)
    for (int j = 0; j < along[1]; ++j)
      for (int i = 0; i < along[0]; ++i) {
        const int index[3] = {i, j, k};
        for (int a = 0; a < D; ++a) nodes[static_cast<std::size_t>(a)].push_back(index[a] * dx + shift(rng));
      }
  return nodes;
}

template <int D>
void rkEvaluationWithHessians(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  const int cells = D == 2 ? 40 : 16;
  const Real dx = 1.0 / cells;
  const mfwave::ReproducingKernelShapeFunctions<D> rk(perturbedLattice<D>(cells), order, (order + 1.5) * dx);
  std::mt19937 rng(3u);
  std::uniform_real_distribution<Real> unit(0.0, 1.0);
  std::vector<mfwave::Vec<D>> points(256);
  for (auto& x : points)
    for (int a = 0; a < D; ++a) x[a] = unit(rng);
  mfwave::ShapeFunctionValues<D> values;
  double neighbours = 0;
  for (auto _ : state) {
    for (const auto& x : points) {
      rk.evaluate(x, 2, values);
      benchmark::DoNotOptimize(values.hessian.data());
      neighbours += static_cast<double>(values.nodes.size());
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
  state.counters["neighbours"] = benchmark::Counter(
      neighbours / static_cast<double>(state.iterations() * static_cast<std::int64_t>(points.size())));
}

}  // namespace

BENCHMARK_TEMPLATE(rkEvaluationWithHessians, 2)->DenseRange(1, 3)->ArgName("order");
BENCHMARK_TEMPLATE(rkEvaluationWithHessians, 3)->DenseRange(1, 3)->ArgName("order");

BENCHMARK_MAIN();
