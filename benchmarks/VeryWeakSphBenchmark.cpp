// Very weak form SPH (Ding-Long-Wu) in 3-D on the section 8 setting: a lattice block [0, 7]^3 with
// n nodes per side (15^3 = 3375 is the paper's block at spacing 0.5; 29^3 and 57^3 = 185193 refine
// it), two ghost layers on every face, cubic spline with h = dx, lambda = mu = rho = 1.
//  - Assembly: assembleVeryWeakSph (volumes, facets, alpha, operator K, traction matrix, system).
//  - Apply: y = K u, in the layouts that could carry it, to decide which one a run should use:
//      EigenColMajor  the library's SparseMatrix (column-major, Eigen's kernel is serial);
//      EigenRowMajor  a row-major copy (Eigen runs it with OpenMP when Eigen::nbThreads() > 1);
//      Csr            a hand-written OpenMP loop over the same row-major arrays;
//      Bsr3           the same loop over 3 x 3 blocks (one column index per block, not per entry).
//    Second argument: OpenMP threads.
//  - Step: one central-difference step on the assembled LinearSecondOrderSystem (what a run pays),
//    and the same step on a system whose acceleration uses the row-major copy with 2 threads.
// Counters: particle_steps/s (operator applications or steps per second times particles),
// bytes_per_particle (operator storage nnz * (8 + 4) / N plus the vectors streamed),
// nnz_per_row, mean_neighbours (physical and ghost, self included), memory_bandwidth (bytes
// streamed per second, assuming K and the vectors are read once). Wall-clock time (UseRealTime):
// the work runs on OpenMP threads. The 2-thread numbers need an otherwise idle machine: with other
// jobs on the cores the OpenMP barriers stall, and real time grows far beyond the CPU time.

#include "numerics/StableTimeStep.hpp"
#include "integrators/CentralDifference.hpp"
#include "kernels/CubicSplineKernel.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"
#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cmath>
#include <map>
#include <memory>
#include <vector>

using namespace mfwave;

namespace {

using RowMajorMatrix = Eigen::SparseMatrix<Real, Eigen::RowMajor, int>;

constexpr Real kSide = 7;

// 3 x 3 block compressed rows: block row a holds the blocks (a, column[k]) for k in
// [offset[a], offset[a + 1]), each stored row by row in values[9 k .. 9 k + 9).
struct BlockCsr3 {
  std::vector<int> offset;
  std::vector<int> column;
  std::vector<Real> values;
  Real bytesPerParticle() const {
    return (static_cast<Real>(values.size()) * 8 + static_cast<Real>(column.size() + offset.size()) * 4) /
           static_cast<Real>(offset.size() - 1);
  }
};

// Every row of K holds whole 3 x 3 blocks in increasing block-column order (VeryWeakOperator.cpp).
BlockCsr3 toBlockCsr3(const RowMajorMatrix& k) {
  BlockCsr3 b;
  const int n = static_cast<int>(k.rows() / 3);
  b.offset.assign(static_cast<std::size_t>(n) + 1, 0);
  for (int a = 0; a < n; ++a) {
    const int entries = k.outerIndexPtr()[3 * a + 1] - k.outerIndexPtr()[3 * a];
    b.offset[static_cast<std::size_t>(a) + 1] = b.offset[static_cast<std::size_t>(a)] + entries / 3;
  }
  b.column.resize(static_cast<std::size_t>(b.offset.back()));
  b.values.resize(9 * static_cast<std::size_t>(b.offset.back()));
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i) {
      const int begin = k.outerIndexPtr()[3 * a + i];
      const int end = k.outerIndexPtr()[3 * a + i + 1];
      for (int e = begin; e < end; ++e) {
        const int local = (e - begin) / 3;
        const auto block = static_cast<std::size_t>(b.offset[static_cast<std::size_t>(a)] + local);
        b.column[block] = k.innerIndexPtr()[e] / 3;
        b.values[9 * block + static_cast<std::size_t>(3 * i + k.innerIndexPtr()[e] % 3)] = k.valuePtr()[e];
      }
    }
  return b;
}

void csrApply(const RowMajorMatrix& k, const Vector& u, Vector& y) {
  const int rows = static_cast<int>(k.rows());
  const int* outer = k.outerIndexPtr();
  const int* inner = k.innerIndexPtr();
  const Real* values = k.valuePtr();
  const Real* x = u.data();
  Real* out = y.data();
#pragma omp parallel for schedule(static)
  for (int r = 0; r < rows; ++r) {
    Real sum = 0;
    for (int e = outer[r]; e < outer[r + 1]; ++e) sum += values[e] * x[inner[e]];
    out[r] = sum;
  }
}

void bsrApply(const BlockCsr3& k, const Vector& u, Vector& y) {
  const int n = static_cast<int>(k.offset.size()) - 1;
  const Real* x = u.data();
  Real* out = y.data();
#pragma omp parallel for schedule(static)
  for (int a = 0; a < n; ++a) {
    Real s0 = 0, s1 = 0, s2 = 0;
    for (int block = k.offset[static_cast<std::size_t>(a)]; block < k.offset[static_cast<std::size_t>(a) + 1];
         ++block) {
      const Real* m = k.values.data() + 9 * static_cast<std::size_t>(block);
      const Real* xb = x + 3 * static_cast<std::size_t>(k.column[static_cast<std::size_t>(block)]);
      s0 += m[0] * xb[0] + m[1] * xb[1] + m[2] * xb[2];
      s1 += m[3] * xb[0] + m[4] * xb[1] + m[5] * xb[2];
      s2 += m[6] * xb[0] + m[7] * xb[1] + m[8] * xb[2];
    }
    out[3 * a] = s0;
    out[3 * a + 1] = s1;
    out[3 * a + 2] = s2;
  }
}

// The block and its assembled scheme, built once per size and shared by the benchmarks.
struct Problem {
  ParticleSet<3> particles;
  NeighbourList neighbours;
  CubicSplineKernel kernel;
  std::unique_ptr<VeryWeakSph<3>> scheme;
  RowMajorMatrix rowMajor;  // -K_sys = K, row-major
  BlockCsr3 blocks;
  Vector u;  // a smooth, nonzero field to multiply
  Real safeStep = 0;

  explicit Problem(int perSide)
      : particles(makeLattice<3>(Vec3::Zero(), Vec3::Constant(kSide), kSide / (perSide - 1))),
        kernel(3, kSide / (perSide - 1)) {
    const Real dx = kSide / (perSide - 1);
    addGhostLayers<3>(particles, Vec3::Zero(), Vec3::Constant(kSide), dx, 2, allFaces(3));
    neighbours = buildNeighbourList(CellList<3>(particles, kernel.supportRadius()), particles.physicalCount());
    scheme = std::make_unique<VeryWeakSph<3>>(
        assembleVeryWeakSph(particles, neighbours, kernel, VeryWeakSphOptions{}));
    rowMajor = scheme->data.operatorMatrix;
    blocks = toBlockCsr3(rowMajor);
    safeStep = centralDifferenceSafeStep(scheme->system);
    const Index n = particles.physicalCount();
    u.resize(3 * n);
    for (Index a = 0; a < n; ++a) {
      const Vec3 x = particles.position(a);
      for (int i = 0; i < 3; ++i) u[3 * a + i] = std::sin(0.7 * x[0] + 0.3 * i) * std::cos(0.5 * x[1] - 0.2 * x[2]);
    }
  }
  Index count() const { return particles.physicalCount(); }
  const SparseMatrix& k() const { return scheme->data.operatorMatrix; }
  Real nonZerosPerRow() const { return static_cast<Real>(k().nonZeros()) / static_cast<Real>(k().rows()); }
  // Operator storage as compressed rows (8-byte value and 4-byte index per nonzero) per particle.
  Real operatorBytesPerParticle() const {
    return (static_cast<Real>(k().nonZeros()) * 12 + static_cast<Real>(k().outerSize() + 1) * 4) /
           static_cast<Real>(count());
  }
};

Problem& problem(int perSide) {
  static std::map<int, std::unique_ptr<Problem>> cache;
  auto& slot = cache[perSide];
  if (!slot) slot = std::make_unique<Problem>(perSide);
  return *slot;
}

void setThreads(int threads) {
  omp_set_num_threads(threads);
  Eigen::setNbThreads(threads);
}

// `rates`: an apply or step per iteration, so particle_steps/s and the memory traffic per second
// (bytes_per_particle streamed once per iteration) mean something.
void counters(benchmark::State& state, const Problem& p, Real bytesPerParticle, bool rates = true) {
  const auto n = static_cast<Real>(p.count());
  const auto iterations = static_cast<Real>(state.iterations());
  state.counters["particles"] = n;
  state.counters["bytes_per_particle"] = bytesPerParticle;
  if (rates) {
    state.counters["particle_steps/s"] = benchmark::Counter(n * iterations, benchmark::Counter::kIsRate);
    state.counters["memory_bandwidth"] =
        benchmark::Counter(n * bytesPerParticle * iterations, benchmark::Counter::kIsRate, benchmark::Counter::kIs1024);
  } else {
    state.counters["particles/s"] = benchmark::Counter(n * iterations, benchmark::Counter::kIsRate);
  }
  state.counters["nnz_per_row"] = p.nonZerosPerRow();
  state.counters["mean_neighbours"] = p.neighbours.meanCount();
}

// The result of every layout must agree with Eigen's column-major product.
bool agrees(const Problem& p, const Vector& y) {
  const Vector reference = p.k() * p.u;
  return (y - reference).norm() <= 1e-12 * reference.norm();
}

void Assembly(benchmark::State& state) {
  setThreads(static_cast<int>(state.range(1)));
  Problem& p = problem(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    VeryWeakSph<3> scheme = assembleVeryWeakSph(p.particles, p.neighbours, p.kernel, VeryWeakSphOptions{});
    benchmark::DoNotOptimize(scheme.data.operatorMatrix.valuePtr());
    benchmark::ClobberMemory();
  }
  counters(state, p, p.operatorBytesPerParticle(), false);
}

// Two vectors streamed by an apply: u (read) and y (written), 3 doubles each per particle.
constexpr Real kApplyVectorBytes = 2 * 3 * 8;

void ApplyEigenColMajor(benchmark::State& state) {
  setThreads(static_cast<int>(state.range(1)));
  Problem& p = problem(static_cast<int>(state.range(0)));
  Vector y(p.u.size());
  for (auto _ : state) {
    y.noalias() = p.k() * p.u;
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  counters(state, p, p.operatorBytesPerParticle() + kApplyVectorBytes);
}

void ApplyEigenRowMajor(benchmark::State& state) {
  setThreads(static_cast<int>(state.range(1)));
  Problem& p = problem(static_cast<int>(state.range(0)));
  Vector y(p.u.size());
  y.noalias() = p.rowMajor * p.u;
  if (!agrees(p, y)) state.SkipWithError("row-major product differs");
  for (auto _ : state) {
    y.noalias() = p.rowMajor * p.u;
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  counters(state, p, p.operatorBytesPerParticle() + kApplyVectorBytes);
}

void ApplyCsr(benchmark::State& state) {
  setThreads(static_cast<int>(state.range(1)));
  Problem& p = problem(static_cast<int>(state.range(0)));
  Vector y(p.u.size());
  csrApply(p.rowMajor, p.u, y);
  if (!agrees(p, y)) state.SkipWithError("CSR product differs");
  for (auto _ : state) {
    csrApply(p.rowMajor, p.u, y);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  counters(state, p, p.operatorBytesPerParticle() + kApplyVectorBytes);
}

void ApplyBsr3(benchmark::State& state) {
  setThreads(static_cast<int>(state.range(1)));
  Problem& p = problem(static_cast<int>(state.range(0)));
  Vector y(p.u.size());
  bsrApply(p.blocks, p.u, y);
  if (!agrees(p, y)) state.SkipWithError("block product differs");
  for (auto _ : state) {
    bsrApply(p.blocks, p.u, y);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  counters(state, p, p.blocks.bytesPerParticle() + kApplyVectorBytes);
}

// Vectors a central-difference step streams: u, v_{n-1/2}, a, v (synchronous), the force work
// vector and 1 / M, 3 doubles each per particle.
constexpr Real kStepVectorBytes = 6 * 3 * 8;

// A smooth vertical velocity pulse under the top face, as in ExplicitRunTest: the run stays bounded.
Vector pulse(const Problem& p) {
  Vector v0 = Vector::Zero(3 * p.count());
  const Vec3 centre(3.5, 3.5, 5.5);
  for (Index a = 0; a < p.count(); ++a) v0[3 * a + 2] = std::exp(-(p.particles.position(a) - centre).squaredNorm());
  return v0;
}

void stepLoop(benchmark::State& state, const Problem& p, SecondOrderSystem& system) {
  CentralDifference integrator;
  integrator.initialise(system, 0.0, Vector::Zero(3 * p.count()), pulse(p), 0.5 * p.safeStep);
  for (auto _ : state) {
    integrator.step();
    benchmark::DoNotOptimize(integrator.state().displacement.data());
    benchmark::ClobberMemory();
  }
  if (!std::isfinite(integrator.state().displacement.norm())) state.SkipWithError("the run blew up");
}

void StepLibrary(benchmark::State& state) {
  setThreads(static_cast<int>(state.range(1)));
  Problem& p = problem(static_cast<int>(state.range(0)));
  stepLoop(state, p, p.scheme->system);
  counters(state, p, p.operatorBytesPerParticle() + kStepVectorBytes);
}

// What the step would cost with the row-major operator: a = (K u) / M with Eigen's parallel product.
class RowMajorSystem : public SecondOrderSystem {
 public:
  RowMajorSystem(const RowMajorMatrix& k, Vector inverseMass) : k_(k), inverseMass_(std::move(inverseMass)) {}
  Index size() const override { return k_.rows(); }
  bool dependsOnVelocity() const override { return false; }
  void acceleration(Real, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector>, Eigen::Ref<Vector> a) override {
    a.noalias() = k_ * u;
    a.array() *= inverseMass_.array();
  }

 private:
  const RowMajorMatrix& k_;
  Vector inverseMass_;
};

void StepRowMajor(benchmark::State& state) {
  setThreads(static_cast<int>(state.range(1)));
  Problem& p = problem(static_cast<int>(state.range(0)));
  RowMajorSystem system(p.rowMajor, p.scheme->system.mass().diagonal().cwiseInverse());
  stepLoop(state, p, system);
  counters(state, p, p.operatorBytesPerParticle() + 5 * 3 * 8);
}

// Sizes (nodes per side) and thread counts. The assembly and the 57^3 problem dominate the run.
void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {15, 29, 57}) b->Args({n, 2});
}
void sizesAndThreads(benchmark::internal::Benchmark* b) {
  for (int n : {15, 29, 57})
    for (int threads : {1, 2}) b->Args({n, threads});
}

}  // namespace

BENCHMARK(Assembly)->Apply(sizes)->ArgNames({"side", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(ApplyEigenColMajor)->Apply(sizes)->ArgNames({"side", "threads"})->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(ApplyEigenRowMajor)->Apply(sizesAndThreads)->ArgNames({"side", "threads"})->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(ApplyCsr)->Apply(sizesAndThreads)->ArgNames({"side", "threads"})->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(ApplyBsr3)->Apply(sizesAndThreads)->ArgNames({"side", "threads"})->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(StepLibrary)->Apply(sizes)->ArgNames({"side", "threads"})->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(StepRowMajor)->Apply(sizes)->ArgNames({"side", "threads"})->Unit(benchmark::kMicrosecond)->UseRealTime();

BENCHMARK_MAIN();
