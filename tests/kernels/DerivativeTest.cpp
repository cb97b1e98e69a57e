// Gradient and Hessian against central differences of value and gradient, at random points in the
// support, close to r = 0 and on both sides of every piece boundary.

#include "KernelCases.hpp"
#include "kernels/KernelFactory.hpp"

#include <cmath>
#include <random>

namespace mfwave {
namespace {

using test::KernelCase;

constexpr Real kLength = 0.37;   // not 1, so a wrong power of h cannot pass
constexpr Real kStep = 1e-6;     // finite-difference step, in units of the length
constexpr Real kTolerance = 1e-6;

template <int D>
Vec<D> randomDirection(std::mt19937& rng) {
  std::normal_distribution<Real> normal;
  Vec<D> v;
  do {
    for (int i = 0; i < D; ++i) v(i) = normal(rng);
  } while (v.norm() < 1e-3);
  return v.normalized();
}

// Radii (units of the length) to probe: random ones away from the piece boundaries, a few close
// to r = 0, and boundary +- 1e-3.
std::vector<Real> probeRadii(const std::vector<Real>& breaks, std::mt19937& rng) {
  const Real kappa = breaks.back();
  std::vector<Real> radii = {1e-3, 1e-2, 0.1};
  for (std::size_t i = 1; i + 1 < breaks.size(); ++i) {
    radii.push_back(breaks[i] - 1e-3);
    radii.push_back(breaks[i] + 1e-3);
  }
  radii.push_back(kappa - 1e-3);
  std::uniform_real_distribution<Real> uniform(0.0, kappa);
  while (radii.size() < 60) {
    const Real q = uniform(rng);
    bool nearBreak = false;
    for (const Real b : breaks) nearBreak = nearBreak || std::abs(q - b) < 1e-4;
    if (!nearBreak) radii.push_back(q);
  }
  return radii;
}

template <int D>
void checkDerivatives(const std::string& name) {
  const auto kernel = makeKernel(name, D, kLength);
  const Real h = kLength;
  const Real eps = kStep * h;
  // Scales of |grad W| and |Hess W|: the tolerance is relative to these, since individual
  // components pass through zero.
  const Real gradScale = kernel->value(0.0) / h;
  const Real hessScale = kernel->value(0.0) / (h * h);
  std::mt19937 rng(12345u + static_cast<unsigned>(D));

  for (const Real q : probeRadii(test::pieceBoundaries(name), rng)) {
    const Vec<D> r = q * h * randomDirection<D>(rng);
    const Vec<D> grad = kernel->gradient(r);
    const Mat<D> hess = kernel->hessian(r);
    for (int j = 0; j < D; ++j) {
      const Vec<D> step = eps * Vec<D>::Unit(j);
      const Real dW = (kernel->value(Vec<D>(r + step)) - kernel->value(Vec<D>(r - step))) / (2.0 * eps);
      EXPECT_NEAR(grad(j), dW, kTolerance * gradScale) << name << " " << D << "-D, q = " << q << ", j = " << j;
      const Vec<D> dGrad = (kernel->gradient(Vec<D>(r + step)) - kernel->gradient(Vec<D>(r - step))) / (2.0 * eps);
      for (int i = 0; i < D; ++i) {
        EXPECT_NEAR(hess(i, j), dGrad(i), kTolerance * hessScale)
            << name << " " << D << "-D, q = " << q << ", (i, j) = (" << i << ", " << j << ")";
      }
    }
    EXPECT_LE((hess - hess.transpose()).cwiseAbs().maxCoeff(), 1e-14 * hessScale);
  }
}

class Derivatives : public ::testing::TestWithParam<KernelCase> {};

TEST_P(Derivatives, MatchCentralDifferences) {
  const auto& [name, d] = GetParam();
  switch (d) {
    case 1: checkDerivatives<1>(name); break;
    case 2: checkDerivatives<2>(name); break;
    default: checkDerivatives<3>(name); break;
  }
}

INSTANTIATE_TEST_SUITE_P(AllKernels, Derivatives, test::allKernelCases(), test::caseName);

}  // namespace
}  // namespace mfwave
