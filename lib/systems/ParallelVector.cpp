#include "systems/ParallelVector.hpp"

namespace mfwave {
namespace {

constexpr long kParallelFrom = 1L << 16;

// f(i) for i in [0, n): OpenMP-parallel from kParallelFrom entries; below it on the calling thread
// with no parallel region at all (an `if`-disabled region still costs a microsecond or two, which a
// small system stepped millions of times pays on every call). Each entry is computed alone.
template <class Function>
void forEachEntry(long n, Function&& f) {
  if (n < kParallelFrom) {
    for (long i = 0; i < n; ++i) f(i);
    return;
  }
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) f(i);
}

}  // namespace

void addScaled(Vector& y, Real s, const Vector& x) {
  Real* out = y.data();
  const Real* in = x.data();
  forEachEntry(static_cast<long>(y.size()), [&](long i) { out[i] += s * in[i]; });
}

void assignSum(Vector& y, const Vector& a, Real s, const Vector& b) {
  y.resize(a.size());
  Real* out = y.data();
  const Real* first = a.data();
  const Real* second = b.data();
  forEachEntry(static_cast<long>(a.size()), [&](long i) { out[i] = first[i] + s * second[i]; });
}

void assignCopy(Vector& y, const Vector& x) {
  y.resize(x.size());
  Real* out = y.data();
  const Real* in = x.data();
  forEachEntry(static_cast<long>(x.size()), [&](long i) { out[i] = in[i]; });
}

}  // namespace mfwave
