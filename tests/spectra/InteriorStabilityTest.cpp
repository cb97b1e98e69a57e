// interiorStability: the verdict a driver acts on before stepping. The finite-difference Laplacian
// (closed form omega^2 = (2c/dx)^2 sum sin^2(k_j dx / 2), never negative) is stable; RK collocation
// in 2-D at a / h = 3 has omega^2 < 0 near the zone corner (its mass symbol changes sign), at
// a / h = 2.5 it has none.
#include "numerics/InteriorStability.hpp"

#include "spectra/MethodLatticeStencils.hpp"
#include "core/Error.hpp"
#include "core/Material.hpp"

#include <gtest/gtest.h>

namespace mfwave {
namespace {

TEST(InteriorStability, FiniteDifferencesAreStableWithTheClosedFormLargestFrequency) {
  const MethodLatticeStencil<2> fd = finiteDifferenceInteriorStencil<2>(0.5, 2.0);
  const InteriorStability<2> v = interiorStability<2>(fd.acceleration, fd.mass, 0.5, 16);
  EXPECT_FALSE(v.growing());
  EXPECT_NEAR(v.largestOmegaSquared, 2 * 16.0 * 4.0, 1e-9);  // 2 (2 c / dx)^2 at k dx = (pi, pi)
  EXPECT_EQ(v.cells, 16);
  EXPECT_THROW(interiorStability<2>(fd.acceleration, fd.mass, 0.5, 3), InputError);
  EXPECT_EQ(periodicLatticeCells<2>(fd.acceleration, fd.mass, 0.5, 5), 6);  // rounded up to even
}

TEST(InteriorStability, LatticeSizesKeepTheStencilWithinHalfThePeriod) {
  // RK collocation at a = 2.5 dx couples nodes 2 spacings away (the mass too): a lattice of 4 would
  // fold the stencil onto itself. The spectra double it (their k samples nest), the runs take the
  // smallest even size that fits.
  const Material material = Material::fromLame(2, 1, 1);
  const auto rk = collocationInteriorStencil<2>(CollocationBasis::ReproducingKernel, 2, 2.5, material, 1.0);
  EXPECT_EQ(periodicLatticeCells<2>(rk.acceleration, rk.mass, 1.0, 4), 8);
  EXPECT_EQ(smallestPeriodicLatticeCells<2>(rk.acceleration, rk.mass, 1.0, 4), 6);
  EXPECT_EQ(smallestPeriodicLatticeCells<2>(rk.acceleration, rk.mass, 1.0, 9), 10);
  const MethodLatticeStencil<2> fd = finiteDifferenceInteriorStencil<2>(1.0, 1.0);
  EXPECT_EQ(smallestPeriodicLatticeCells<2>(fd.acceleration, fd.mass, 1.0, 4), 4);
  EXPECT_THROW(smallestPeriodicLatticeCells<2>(fd.acceleration, fd.mass, 1.0, 3), InputError);
}

TEST(InteriorStability, RkCollocationGrowsAtThreeSupportsAndNotAtTwoAndAHalf) {
  const Material material = Material::fromLame(2, 1, 1);
  const auto stable = collocationInteriorStencil<2>(CollocationBasis::ReproducingKernel, 2, 2.5, material, 1.0);
  EXPECT_FALSE(interiorStability<2>(stable.acceleration, stable.mass, 1.0, 32).growing());
  const auto wide = collocationInteriorStencil<2>(CollocationBasis::ReproducingKernel, 2, 3.0, material, 1.0);
  const InteriorStability<2> v = interiorStability<2>(wide.acceleration, wide.mass, 1.0, 32);
  EXPECT_TRUE(v.growing());
  EXPECT_NEAR(v.smallestOverLargest(), -0.237, 0.01);
  EXPECT_NEAR(v.smallestAtKdx.maxCoeff(), M_PI, 1e-12);
  EXPECT_NE(v.describe().find("omega^2 reaches -0.23"), std::string::npos) << v.describe();
}

}  // namespace
}  // namespace mfwave
