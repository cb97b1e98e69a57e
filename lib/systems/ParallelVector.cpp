#include "systems/ParallelVector.hpp"

namespace mfwave {
namespace {

constexpr long kParallelFrom = 1L << 16;

}  // namespace

void addScaled(Vector& y, Real s, const Vector& x) {
  const long n = static_cast<long>(y.size());
  Real* out = y.data();
  const Real* in = x.data();
#pragma omp parallel for schedule(static) if (n >= kParallelFrom)
  for (long i = 0; i < n; ++i) out[i] += s * in[i];
}

void assignSum(Vector& y, const Vector& a, Real s, const Vector& b) {
  const long n = static_cast<long>(a.size());
  y.resize(a.size());
  Real* out = y.data();
  const Real* first = a.data();
  const Real* second = b.data();
#pragma omp parallel for schedule(static) if (n >= kParallelFrom)
  for (long i = 0; i < n; ++i) out[i] = first[i] + s * second[i];
}

void assignCopy(Vector& y, const Vector& x) {
  const long n = static_cast<long>(x.size());
  if (n < kParallelFrom) {  // no parallel region for a small copy
    y = x;
    return;
  }
  y.resize(x.size());
  Real* out = y.data();
  const Real* in = x.data();
#pragma omp parallel for schedule(static) if (n >= kParallelFrom)
  for (long i = 0; i < n; ++i) out[i] = in[i];
}

}  // namespace mfwave
