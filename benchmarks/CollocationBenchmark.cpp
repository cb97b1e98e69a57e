// Reproducing-kernel shape-function evaluations per second (values, gradients and Hessians, as
// strong-form collocation needs them) in 2-D and 3-D for orders m = 1..3, on a perturbed lattice
// with support radius a = (m + 1.5) dx, the radius the unit tests use. One ShapeFunctionValues is
// reused, as in an assembly loop.
//
// ExplicitStep2d: one central-difference step of explicit RK collocation on the unit square
// (plane strain, order 2, a = 2.5 h, displacement rows on the edge), 1e4 and 1e5 nodes: a sparse
// LU solve with C and a product with A_I per step (ConstrainedCollocationSystem). The LU solve is
// serial (UMFPACK), so the thread count is not an argument.

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "integrators/CentralDifference.hpp"
#include "methods/collocation/CollocationSystem.hpp"
#include "methods/collocation/ConstrainedCollocationSystem.hpp"
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

void ExplicitStep2d(benchmark::State& state) {
  const int cells = static_cast<int>(state.range(0));
  const Real h = 1.0 / cells;
  Coordinates<2> nodes;
  mfwave::CollocationPoints<2> points;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      const mfwave::Vec2 x(i * h, j * h);
      nodes[0].push_back(x[0]);
      nodes[1].push_back(x[1]);
      const bool edge = i == 0 || j == 0 || i == cells || j == cells;
      points.add(x, edge ? mfwave::CollocationRowKind::Displacement : mfwave::CollocationRowKind::Interior);
    }
  const mfwave::Material material = mfwave::Material::fromLame(1, 1, 1);
  const mfwave::ReproducingKernelShapeFunctions<2> shapes(nodes, 2, 2.5 * h);
  mfwave::ConstrainedCollocationSystem system(
      mfwave::assembleCollocation<2>(shapes, points, material, mfwave::CollocationLoads<2>{}));
  mfwave::Vector u0 = mfwave::Vector::Random(system.size()) * 1e-3, v0 = mfwave::Vector::Zero(system.size());
  mfwave::CentralDifference integrator;
  integrator.initialise(system, 0, u0, v0, 0.1 * h);  // well inside the limit (0.5 h / c_p at this support)
  for (auto _ : state) {
    integrator.step();
    benchmark::DoNotOptimize(integrator.state().displacement.data());
  }
  const double n = static_cast<double>(nodes[0].size());
  state.counters["particles"] = n;
  state.counters["particle_steps/s"] = benchmark::Counter(n * static_cast<double>(state.iterations()),
                                                          benchmark::Counter::kIsRate);
  // The matrices the step streams (12 bytes per stored entry): A_I and C; the LU factors of C,
  // which the solve also streams, are not visible here and come on top.
  state.counters["matrix_bytes_per_particle"] =
      12.0 * static_cast<double>(system.interiorOperator().nonZeros() + system.constraintMatrix().nonZeros()) / n;
}

}  // namespace

BENCHMARK(ExplicitStep2d)->Arg(100)->Arg(316)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(rkEvaluationWithHessians, 2)->DenseRange(1, 3)->ArgName("order");
BENCHMARK_TEMPLATE(rkEvaluationWithHessians, 3)->DenseRange(1, 3)->ArgName("order");

BENCHMARK_MAIN();
