// The inline kernels of KernelProfiles.hpp (what the updated-Lagrangian SPH pair table evaluates)
// give the virtual kernels' W and grad W, for every kernel and dimension, at many radii: inside
// each piece, at the piece boundaries, at r = 0, at and beyond the support.

#include "KernelCases.hpp"
#include "kernels/KernelFactory.hpp"
#include "kernels/KernelProfiles.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace mfwave;
using mfwave::test::KernelCase;

class InlineKernelTest : public ::testing::TestWithParam<KernelCase> {};

namespace {

template <int D>
void compareAlongRandomDirections(const Kernel& kernel, const std::vector<Real>& radii) {
  visitInlineKernel(kernel, [&](const auto& inlined) {
    EXPECT_DOUBLE_EQ(inlined.supportRadius2(), kernel.supportRadius() * kernel.supportRadius());
    std::mt19937 rng(17);
    std::normal_distribution<Real> normal;
    for (Real r : radii) {
      Vec<D> direction;
      for (int a = 0; a < D; ++a) direction[a] = normal(rng);
      const Vec<D> x = r * direction.normalized();
      // Equal up to the last bits (the same expressions; a compiler may contract them differently).
      EXPECT_DOUBLE_EQ(inlined.value(x), kernel.value(x)) << "r = " << r;
      const Vec<D> g = inlined.gradient(x);
      const Vec<D> reference = kernel.gradient(x);
      for (int a = 0; a < D; ++a) {
        EXPECT_DOUBLE_EQ(g[a], reference[a]) << "r = " << r << ", component " << a;
      }
      const Real distance = x.norm();
      if (distance * distance < inlined.supportRadius2()) {
        EXPECT_DOUBLE_EQ(inlined.valueAt(distance), kernel.value(x)) << "r = " << r;
        if (distance > 0) {
          for (int a = 0; a < D; ++a) {
            EXPECT_DOUBLE_EQ(inlined.gradientFactorAt(distance) * x[a], reference[a]) << "r = " << r;
          }
        }
      }
    }
  });
}

}  // namespace

TEST_P(InlineKernelTest, ValueAndGradientEqualTheVirtualKernel) {
  const auto& [name, dimension] = GetParam();
  const Real length = 0.37;
  const std::unique_ptr<Kernel> kernel = makeKernel(name, dimension, length);
  std::vector<Real> radii = {0.0};
  const Real support = kernel->supportRadius();
  for (int k = 1; k <= 400; ++k) radii.push_back(1.1 * support * k / 400.0);
  for (Real q : mfwave::test::pieceBoundaries(name)) radii.push_back(q * length);
  radii.push_back(std::nextafter(support, 0.0));
  switch (dimension) {
    case 1: compareAlongRandomDirections<1>(*kernel, radii); break;
    case 2: compareAlongRandomDirections<2>(*kernel, radii); break;
    default: compareAlongRandomDirections<3>(*kernel, radii); break;
  }
}

INSTANTIATE_TEST_SUITE_P(AllKernels, InlineKernelTest, mfwave::test::allKernelCases(), mfwave::test::caseName);
