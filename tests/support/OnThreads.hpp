#pragma once
// Runs f with OpenMP's thread count set to `threads` and restores the count after (also when f
// throws), returning f's result: the thread-independence tests compare onThreads(1, f) with
// onThreads(2, f) bit for bit. Without OpenMP f simply runs.

#ifdef _OPENMP
#include <omp.h>
#endif

#include <utility>

namespace mfwave::testing {

template <class F>
auto onThreads(int threads, F&& f) -> decltype(f()) {
#ifdef _OPENMP
  struct Restore {
    int before = omp_get_max_threads();
    ~Restore() { omp_set_num_threads(before); }
  } restore;
  omp_set_num_threads(threads);
#else
  (void)threads;
#endif
  return std::forward<F>(f)();
}

}  // namespace mfwave::testing
