// The memory bandwidth this machine sustains, STREAM-style: the triad a_i = b_i + s c_i over arrays
// far larger than the caches (3 x 160 MB), on 1 and 2 threads. Each element moves 24 bytes (read b
// and c, write a; the write-allocate read of a is not counted, as in STREAM). This is the bound the
// hot loops are compared with in docs/performance.md: a sparse operator product that streams its
// matrix once per step can go no faster than bytes per particle / this bandwidth.

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cstddef>
#include <vector>

namespace {

void Triad(benchmark::State& state) {
  const auto n = static_cast<std::ptrdiff_t>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  std::vector<double> a(static_cast<std::size_t>(n)), b(static_cast<std::size_t>(n)), c(static_cast<std::size_t>(n));
  // First touch in the same static schedule as the loop, so pages sit near the thread using them.
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    a[static_cast<std::size_t>(i)] = 0;
    b[static_cast<std::size_t>(i)] = 1;
    c[static_cast<std::size_t>(i)] = 2;
  }
  const double s = 3;
  for (auto _ : state) {
    double* pa = a.data();
    const double* pb = b.data();
    const double* pc = c.data();
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) pa[i] = pb[i] + s * pc[i];
    benchmark::DoNotOptimize(a.data());
    benchmark::ClobberMemory();
  }
  state.counters["bandwidth"] = benchmark::Counter(24.0 * static_cast<double>(n) * static_cast<double>(state.iterations()),
                                                   benchmark::Counter::kIsRate, benchmark::Counter::kIs1024);
  state.counters["threads"] = threads;
}

}  // namespace

BENCHMARK(Triad)->Args({20000000, 1})->Args({20000000, 2})->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
