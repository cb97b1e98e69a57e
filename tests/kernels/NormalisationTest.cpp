// Every kernel must integrate to 1 over R^d: the radial integral S_d int_0^R r^{d-1} W(r) dr,
// done by Gauss-Legendre on each polynomial piece (exact up to rounding), subdivided for the
// Gaussian.

#include "KernelCases.hpp"
#include "core/GaussLegendre.hpp"
#include "kernels/KernelFactory.hpp"

#include <cmath>

namespace mfwave {
namespace {

using test::KernelCase;

Real radialMeasure(int d, Real r) {
  if (d == 1) return 2.0;
  if (d == 2) return 2.0 * M_PI * r;
  return 4.0 * M_PI * r * r;
}

class Normalisation : public ::testing::TestWithParam<KernelCase> {};

TEST_P(Normalisation, IntegratesToOneOverSpace) {
  const auto& [name, d] = GetParam();
  const QuadratureRule rule = gaussLegendre(12);
  const int pieces = name == "gaussian" ? 40 : 1;
  for (const Real length : {0.3, 1.0, 2.5}) {
    const auto kernel = makeKernel(name, d, length);
    const std::vector<Real> breaks = test::pieceBoundaries(name);
    Real total = 0.0;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
      total += integrate(
          rule, breaks[i] * length, breaks[i + 1] * length,
          [&](Real r) { return radialMeasure(d, r) * kernel->value(r); }, pieces);
    }
    EXPECT_NEAR(total, 1.0, 1e-10) << name << " " << d << "-D, length " << length;
  }
}

INSTANTIATE_TEST_SUITE_P(AllKernels, Normalisation, test::allKernelCases(), test::caseName);

// The closed-form sigma_d the kernels are built with (their correctness is the test above).
TEST(Normalisation, ClosedFormConstants) {
  struct Expected {
    const char* name;
    Real sigma[3];
  };
  const Real pi = M_PI;
  const Real gaussMass[3] = {std::erf(3.0), 1.0 - std::exp(-9.0), std::erf(3.0) - 6.0 / std::sqrt(pi) * std::exp(-9.0)};
  const Expected table[] = {
      {"cubic_spline", {2.0 / 3.0, 10.0 / (7.0 * pi), 1.0 / pi}},
      {"quintic_spline", {1.0 / 120.0, 7.0 / (478.0 * pi), 1.0 / (120.0 * pi)}},
      {"wendland_c2", {5.0 / 8.0, 7.0 / (4.0 * pi), 21.0 / (16.0 * pi)}},
      {"wendland_c4", {3.0 / 4.0, 9.0 / (4.0 * pi), 495.0 / (256.0 * pi)}},
      {"cubic_b_spline", {2.0, 60.0 / (7.0 * pi), 12.0 / pi}},
      {"gaussian",
       {1.0 / (std::sqrt(pi) * gaussMass[0]), 1.0 / (pi * gaussMass[1]), 1.0 / (std::pow(pi, 1.5) * gaussMass[2])}},
  };
  for (const Expected& e : table) {
    for (int d = 1; d <= 3; ++d) {
      EXPECT_NEAR(makeKernel(e.name, d, 1.0)->normalisation(), e.sigma[d - 1], 1e-14 * e.sigma[d - 1])
          << e.name << " " << d << "-D";
    }
  }
}

}  // namespace
}  // namespace mfwave
