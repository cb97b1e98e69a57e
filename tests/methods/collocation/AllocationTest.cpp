// Evaluation in a loop must not allocate once the caller's ShapeFunctionValues has warmed up:
// the collocation assembly calls evaluate once per point. This file replaces the global
// operator new of the test program with a counting one (malloc underneath, so sanitizers still
// see every block).

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "CollocationTestSupport.hpp"
#include "methods/collocation/RadialBasisShapeFunctions.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"

namespace {
std::atomic<long> allocationCount{0};

void* countedAllocate(std::size_t size) {
  allocationCount.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

void* countedAlignedAllocate(std::size_t size, std::align_val_t alignment) {
  allocationCount.fetch_add(1, std::memory_order_relaxed);
  const auto a = static_cast<std::size_t>(alignment);
  const std::size_t rounded = (size + a - 1) / a * a;
  if (void* p = std::aligned_alloc(a, rounded == 0 ? a : rounded)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) { return countedAllocate(size); }
void* operator new[](std::size_t size) { return countedAllocate(size); }
void* operator new(std::size_t size, std::align_val_t a) { return countedAlignedAllocate(size, a); }
void* operator new[](std::size_t size, std::align_val_t a) { return countedAlignedAllocate(size, a); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

using namespace mfwave;
using namespace mfwave::testing;

namespace {

// Allocations made while evaluating at `points` with Hessians, after one warm-up pass.
template <int D>
long allocationsAfterWarmUp(const ShapeFunctions<D>& shapes, const std::vector<Vec<D>>& points) {
  ShapeFunctionValues<D> values;
  for (const Vec<D>& x : points) shapes.evaluate(x, 2, values);
  const long before = allocationCount.load();
  Real checksum = 0;
  for (int pass = 0; pass < 2; ++pass) {
    for (const Vec<D>& x : points) {
      shapes.evaluate(x, 2, values);
      checksum += values.value[0];
    }
  }
  const long after = allocationCount.load();
  EXPECT_TRUE(std::isfinite(checksum));
  return after - before;
}

}  // namespace

TEST(ShapeFunctionAllocation, CountingOperatorNewSeesAllocations) {
  // The counter works (otherwise the tests below could not fail).
  const long before = allocationCount.load();
  std::vector<Real>* v = new std::vector<Real>(100);
  delete v;
  EXPECT_GE(allocationCount.load() - before, 2);
}

TEST(ShapeFunctionAllocation, ReproducingKernelEvaluationDoesNotAllocateAfterWarmUp) {
  const Coordinates<3> nodes = unitLattice<3>(8, 0.3);
  const ReproducingKernelShapeFunctions<3> rk(nodes, 3, 4.5 / 8);
  EXPECT_EQ(allocationsAfterWarmUp<3>(rk, samplePoints<3>(20, 1.0 / 8)), 0);
  const Coordinates<2> nodes2 = unitLattice<2>(12, 0.3);
  const ReproducingKernelShapeFunctions<2> rk2(nodes2, 2, 3.5 / 12);
  EXPECT_EQ(allocationsAfterWarmUp<2>(rk2, samplePoints<2>(20, 1.0 / 12)), 0);
}

TEST(ShapeFunctionAllocation, RadialBasisEvaluationDoesNotAllocateAfterWarmUp) {
  const Coordinates<2> nodes = unitLattice<2>(6, 0.3);
  const RadialBasisShapeFunctions<2> rbf(nodes, RadialBasisFunction(RadialBasisKind::Multiquadric, 0.3), 1);
  EXPECT_EQ(allocationsAfterWarmUp<2>(rbf, samplePoints<2>(10, 1.0 / 6)), 0);
}
