// Exact properties: the Hessian at r = 0, compact support, symmetry, radial consistency, and the
// dimension check on the evaluators.

#include "KernelCases.hpp"
#include "core/Error.hpp"
#include "kernels/CubicSplineKernel.hpp"
#include "kernels/KernelFactory.hpp"

#include <cmath>
#include <limits>
#include <random>

namespace mfwave {
namespace {

using test::KernelCase;

TEST(CubicSplineKernel, HessianAtOriginIn3D) {
  for (const Real h : {0.5, 1.0, 1.3}) {
    const CubicSplineKernel kernel(3, h);
    const Mat3 expected = -3.0 / (M_PI * std::pow(h, 5)) * Mat3::Identity();
    const Mat3 hess = kernel.hessian(Vec3::Zero());
    EXPECT_LE((hess - expected).cwiseAbs().maxCoeff(), 1e-14 * std::abs(expected(0, 0))) << "h = " << h;
    EXPECT_TRUE(kernel.gradient(Vec3::Zero()).isZero(0.0));
    EXPECT_DOUBLE_EQ(kernel.value(Vec3::Zero()), 1.0 / (M_PI * h * h * h));
  }
}

TEST(CubicSplineKernel, MatchesLiPrimerFormulaIn3D) {
  const Real h = 0.8;
  const CubicSplineKernel kernel(3, h);
  for (const Real q : {0.0, 0.3, 0.9, 1.0, 1.4, 1.99}) {
    const Real expected = q <= 1.0 ? (1.0 - 1.5 * q * q + 0.75 * q * q * q) / (M_PI * h * h * h)
                                   : std::pow(2.0 - q, 3) / (4.0 * M_PI * h * h * h);
    EXPECT_NEAR(kernel.value(Vec3(q * h, 0.0, 0.0)), expected, 1e-14 / (M_PI * h * h * h)) << "q = " << q;
  }
}

TEST(CubicBSplineKernel, IsTheCubicSplineWithHalfTheSupportRadius) {
  // Both integrate to 1 and have the same shape, so they must agree pointwise for h = a/2.
  const Real a = 1.7;
  for (int d = 1; d <= 3; ++d) {
    const auto bspline = makeKernel("cubic_b_spline", d, a);
    const auto cubic = makeKernel("cubic_spline", d, a / 2.0);
    EXPECT_DOUBLE_EQ(bspline->supportRadius(), a);
    for (const Real z : {0.0, 0.2, 0.5, 0.7, 0.95}) {
      EXPECT_NEAR(bspline->value(z * a), cubic->value(z * a), 1e-14 * cubic->value(0.0)) << d << "-D, z = " << z;
    }
  }
}

template <int D>
Vec<D> randomVector(std::mt19937& rng, Real length) {
  std::normal_distribution<Real> normal;
  Vec<D> v;
  for (int i = 0; i < D; ++i) v(i) = normal(rng);
  return length * v.normalized();
}

template <int D>
void checkExactProperties(const std::string& name) {
  const Real h = 0.6;
  const auto kernel = makeKernel(name, D, h);
  const Real R = kernel->supportRadius();
  std::mt19937 rng(777u);

  // Hessian at the origin: sigma f''(0) / h^{d+2} I.
  const Real h0 = kernel->normalisation() * test::profileCurvatureAtZero(name, D) / std::pow(h, D + 2);
  const Mat<D> hess0 = kernel->hessian(Vec<D>::Zero());
  EXPECT_LE((hess0 - h0 * Mat<D>::Identity()).cwiseAbs().maxCoeff(), 1e-13 * std::abs(h0)) << name << " " << D;
  EXPECT_TRUE(kernel->gradient(Vec<D>::Zero()).isZero(0.0));

  // Compact support: exactly zero at and beyond the support radius.
  EXPECT_EQ(kernel->value(R), 0.0);
  EXPECT_EQ(kernel->value(-R), 0.0);
  for (int j = 0; j < D; ++j) {
    for (const Real s : {1.0, -1.0}) {
      const Vec<D> onSupport = s * R * Vec<D>::Unit(j);
      EXPECT_EQ(kernel->value(onSupport), 0.0) << name << " " << D << "-D";
      EXPECT_TRUE(kernel->gradient(onSupport).isZero(0.0)) << name << " " << D << "-D";
      EXPECT_TRUE(kernel->hessian(onSupport).isZero(0.0)) << name << " " << D << "-D";
    }
  }
  for (const Real factor : {1.0 + 1e-12, 1.001, 1.5, 10.0}) {
    const Vec<D> beyond = randomVector<D>(rng, factor * R);
    EXPECT_EQ(kernel->value(beyond), 0.0) << name << " " << D << "-D, |r| = " << factor << " R";
    EXPECT_EQ(kernel->value(factor * R), 0.0);
    EXPECT_TRUE(kernel->gradient(beyond).isZero(0.0)) << name << " " << D << "-D";
    EXPECT_TRUE(kernel->hessian(beyond).isZero(0.0)) << name << " " << D << "-D";
  }

  // Inside: positive, radial (vector and scalar evaluators agree), even value and Hessian, odd
  // gradient, gradient pointing inwards.
  std::uniform_real_distribution<Real> radius(0.0, R);
  for (int k = 0; k < 50; ++k) {
    const Real rn = radius(rng);
    const Vec<D> r = randomVector<D>(rng, rn);
    const Real w = kernel->value(r);
    EXPECT_GT(w, 0.0);
    EXPECT_NEAR(w, kernel->value(rn), 1e-14 * kernel->value(0.0));
    EXPECT_EQ(kernel->value(Vec<D>(-r)), w);
    EXPECT_EQ(kernel->gradient(Vec<D>(-r)), Vec<D>(-kernel->gradient(r)));
    EXPECT_EQ(kernel->hessian(Vec<D>(-r)), kernel->hessian(r));
    EXPECT_LT(kernel->gradient(r).dot(r), 0.0) << name << " " << D << "-D, |r| = " << rn;
  }
}

class ExactProperties : public ::testing::TestWithParam<KernelCase> {};

TEST_P(ExactProperties, HoldForEveryKernel) {
  const auto& [name, d] = GetParam();
  switch (d) {
    case 1: checkExactProperties<1>(name); break;
    case 2: checkExactProperties<2>(name); break;
    default: checkExactProperties<3>(name); break;
  }
}

INSTANTIATE_TEST_SUITE_P(AllKernels, ExactProperties, test::allKernelCases(), test::caseName);

TEST(KernelEvaluators, AcceptEigenExpressions) {
  // Pair loops pass x_a - x_b directly; that must agree with the evaluated vector.
  const auto kernel = makeKernel("wendland_c2", 3, 0.5);
  const Vec3 xa(0.1, 0.2, -0.05);
  const Vec3 xb(-0.2, 0.3, 0.25);
  const Vec3 r = xa - xb;
  EXPECT_EQ(kernel->value(xa - xb), kernel->value(r));
  EXPECT_EQ(kernel->gradient(xa - xb), kernel->gradient(r));
  EXPECT_EQ(kernel->hessian(xa - xb), kernel->hessian(r));
  EXPECT_GT(kernel->value(xa - xb), 0.0);
  EXPECT_THROW((void)kernel->gradient(Vec2(xa.head<2>() - xb.head<2>())), InputError);
}

TEST(KernelDimension, EvaluatingWithTheWrongDimensionThrows) {
  const auto kernel = makeKernel("cubic_spline", 2, 1.0);
  try {
    (void)kernel->gradient(Vec3(0.1, 0.2, 0.3));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "dimension");
  }
  EXPECT_THROW((void)kernel->value(Vec1(0.1)), InputError);
  EXPECT_THROW((void)kernel->hessian(Vec3::Zero()), InputError);
  EXPECT_NO_THROW((void)kernel->hessian(Vec2::Zero()));
}

}  // namespace
}  // namespace mfwave
