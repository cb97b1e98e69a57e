// Radial-basis interpolation shape functions: the interpolation property, polynomial
// reproduction with augmentation, exact derivatives against finite differences, names and errors.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "CollocationTestSupport.hpp"
#include "core/Error.hpp"
#include "methods/collocation/RadialBasisShapeFunctions.hpp"
#include "support/InputErrorKey.hpp"

using namespace mfwave;
using namespace mfwave::testing;

namespace {

const std::array<RadialBasisKind, 3> kKinds = {RadialBasisKind::InverseMultiquadric, RadialBasisKind::Multiquadric,
                                               RadialBasisKind::Gaussian};

Coordinates<1> line(int intervals) {
  Coordinates<1> nodes;
  for (int i = 0; i <= intervals; ++i) nodes[0].push_back(static_cast<Real>(i) / intervals);
  return nodes;
}

}  // namespace

TEST(RadialBasisFunction, DerivativesOfEachProfileAgreeWithFiniteDifferences) {
  // g(x) for r = x - x_j, central differences with step 1e-5 c: the profiles are smooth, so the
  // truncation error is ~1e-10 relative and rounding ~1e-11.
  for (const RadialBasisKind kind : kKinds) {
    SCOPED_TRACE(radialBasisName(kind));
    const Real c = 0.3;
    const RadialBasisFunction g(kind, c);
    const Real h = 1e-5 * c;
    for (const Vec3& r : {Vec3(0, 0, 0), Vec3(0.1, -0.2, 0.05), Vec3(-0.5, 0.3, 0.7)}) {
      const Vec3 gradient = g.gradient<3>(r);
      const Mat3 hessian = g.hessian<3>(r);
      for (int j = 0; j < 3; ++j) {
        const Vec3 step = h * Vec3::Unit(j);
        EXPECT_NEAR(c * gradient[j], c * (g.value<3>(Vec3(r + step)) - g.value<3>(Vec3(r - step))) / (2 * h),
                    1e-8 * g.value<3>(r));
        const Vec3 column = (g.gradient<3>(Vec3(r + step)) - g.gradient<3>(Vec3(r - step))) / (2 * h);
        EXPECT_LT(c * c * (column - hessian.col(j)).cwiseAbs().maxCoeff(), 1e-8 * g.value<3>(r));
      }
    }
  }
  // The inverse multiquadric of Luo-Liu-Huang: g = (r^2 + c^2)^(-1/2).
  EXPECT_DOUBLE_EQ(RadialBasisFunction(RadialBasisKind::InverseMultiquadric, 0.5).value<1>(Vec1(1.2)),
                   1 / std::sqrt(1.44 + 0.25));
  EXPECT_DOUBLE_EQ(RadialBasisFunction(RadialBasisKind::Multiquadric, 0.5).value<1>(Vec1(1.2)), std::sqrt(1.44 + 0.25));
  EXPECT_DOUBLE_EQ(RadialBasisFunction(RadialBasisKind::Gaussian, 0.5).value<1>(Vec1(1.2)), std::exp(-1.44 / 0.25));
}

TEST(RadialBasisShapeFunctions, InterpolateAtTheNodesIn1D) {
  // 21 nodes, h = 0.05, inverse multiquadric with c = 4 h (the paper's RBCM setting, in units
  // where the bar has length 1). psi_j(x_i) = delta_ij holds only to ~ eps * cond(G): the basis
  // functions are flat and overlap strongly, cond_2(G) = 5e5 here (1-norm estimate 1/1.6e-6), and
  // the measured error is 2.5e-12. The tolerance 1e-8 leaves room for other BLAS/rounding; it is
  // not 1e-14 because of that conditioning (a Gaussian with the same c has cond 1.7e12 and
  // interpolates only to 1e-5).
  const Coordinates<1> nodes = line(20);
  const Real h = 0.05;
  const RadialBasisShapeFunctions<1> rbf(nodes, RadialBasisFunction(RadialBasisKind::InverseMultiquadric, 4 * h));
  EXPECT_EQ(rbf.name(), "radial_basis(inverse_multiquadric, c=0.2)");
  EXPECT_LT(rbf.reciprocalCondition(), 1e-5);  // the reason for the tolerance
  ShapeFunctionValues<1> values;
  Real worst = 0;
  for (Index i = 0; i < rbf.nodeCount(); ++i) {
    rbf.evaluate(nodePosition<1>(nodes, i), 0, values);
    ASSERT_EQ(values.size(), 21);
    for (Index j = 0; j < 21; ++j)
      worst = std::max(worst, std::abs(values.value[static_cast<std::size_t>(j)] - (i == j ? 1.0 : 0.0)));
  }
  EXPECT_LT(worst, 1e-8);
}

TEST(RadialBasisShapeFunctions, InterpolateAtTheNodesIn2DForEveryKind) {
  const Coordinates<2> nodes = unitLattice<2>(6, 0.3);
  for (const RadialBasisKind kind : kKinds) {
    for (const int degree : {-1, 1}) {
      SCOPED_TRACE(std::string(radialBasisName(kind)) + ", p = " + std::to_string(degree));
      const RadialBasisShapeFunctions<2> rbf(nodes, RadialBasisFunction(kind, 0.3), degree);
      ShapeFunctionValues<2> values;
      Real worst = 0;
      for (Index i = 0; i < rbf.nodeCount(); ++i) {
        rbf.evaluate(nodePosition<2>(nodes, i), 0, values);
        for (Index j = 0; j < rbf.nodeCount(); ++j)
          worst = std::max(worst, std::abs(values.value[static_cast<std::size_t>(j)] - (i == j ? 1.0 : 0.0)));
      }
      EXPECT_LT(worst, 1e-8);
    }
  }
}

TEST(RadialBasisShapeFunctions, LinearAugmentationReproducesLinearFieldsExactly) {
  // u = 0.3 + 1.7 x - 0.9 y on a perturbed 7 x 7 cloud, c = 0.3, at random points between the
  // nodes (where plain RBF interpolation is only approximate): the augmented interpolant is u.
  const Coordinates<2> nodes = unitLattice<2>(6, 0.3);
  auto u = [](const Vec2& x) { return 0.3 + 1.7 * x[0] - 0.9 * x[1]; };
  const Vec2 gradientU(1.7, -0.9);
  const std::vector<Vec2> points = samplePoints<2>(30, 1.0 / 6, 5u);
  for (const RadialBasisKind kind : kKinds) {
    SCOPED_TRACE(radialBasisName(kind));
    for (const int degree : {1, -1}) {
      const RadialBasisShapeFunctions<2> rbf(nodes, RadialBasisFunction(kind, 0.3), degree);
      ShapeFunctionValues<2> values;
      Real worstValue = 0, worstGradient = 0, worstHessian = 0;
      for (const Vec2& x : points) {
        rbf.evaluate(x, 2, values);
        Real sum = 0;
        Vec2 gradient = Vec2::Zero();
        Mat2 hessian = Mat2::Zero();
        for (std::size_t k = 0; k < values.nodes.size(); ++k) {
          const Real uk = u(nodePosition<2>(nodes, values.nodes[k]));
          sum += values.value[k] * uk;
          gradient += values.gradient[k] * uk;
          hessian += values.hessian[k] * uk;
        }
        worstValue = std::max(worstValue, std::abs(sum - u(x)));
        worstGradient = std::max(worstGradient, (gradient - gradientU).cwiseAbs().maxCoeff());
        worstHessian = std::max(worstHessian, hessian.cwiseAbs().maxCoeff());
      }
      if (degree == 1) {
        // eps * cond(A) with cond(A) up to ~1e9 for these flat bases.
        EXPECT_LT(worstValue, 1e-8);
        EXPECT_LT(worstGradient, 1e-6);
        EXPECT_LT(worstHessian, 1e-4);
      } else {
        EXPECT_GT(worstValue, 1e-6);  // able to fail: without augmentation the field is not exact
      }
    }
  }
}

TEST(RadialBasisShapeFunctions, DerivativesAgreeWithFiniteDifferences) {
  // Central differences of the values (gradient) and exact gradients (Hessian), h = 1e-5: the
  // functions are smooth, truncation ~1e-10 psi''' and rounding ~eps cond / h.
  const Coordinates<2> nodes = unitLattice<2>(5, 0.3);
  for (const RadialBasisKind kind : kKinds) {
    SCOPED_TRACE(radialBasisName(kind));
    const RadialBasisShapeFunctions<2> rbf(nodes, RadialBasisFunction(kind, 0.35), 1);
    const Real h = 1e-5;
    ShapeFunctionValues<2> centre, plus, minus;
    Real worstGradient = 0, worstHessian = 0, largest = 0;
    for (const Vec2& x : samplePoints<2>(8, 0.2, 11u)) {
      rbf.evaluate(x, 2, centre);
      for (int j = 0; j < 2; ++j) {
        rbf.evaluate(x + h * Vec2::Unit(j), 1, plus);
        rbf.evaluate(x - h * Vec2::Unit(j), 1, minus);
        for (std::size_t k = 0; k < centre.nodes.size(); ++k) {
          worstGradient =
              std::max(worstGradient, std::abs((plus.value[k] - minus.value[k]) / (2 * h) - centre.gradient[k][j]));
          worstHessian = std::max(
              worstHessian,
              ((plus.gradient[k] - minus.gradient[k]) / (2 * h) - centre.hessian[k].col(j)).cwiseAbs().maxCoeff());
          largest = std::max(largest, centre.hessian[k].cwiseAbs().maxCoeff());
        }
      }
    }
    EXPECT_LT(worstGradient, 1e-5);
    EXPECT_LT(worstHessian, 1e-5 * largest);
    EXPECT_GT(largest, 1.0);
  }
}

TEST(RadialBasisShapeFunctions, NamesAndBadInput) {
  EXPECT_EQ(radialBasisNames(), (std::vector<std::string>{"inverse_multiquadric", "multiquadric", "gaussian"}));
  for (const std::string& name : radialBasisNames()) EXPECT_EQ(radialBasisName(radialBasisKind(name)), name);
  EXPECT_EQ(makeRadialBasisFunction("gaussian", 0.2).kind(), RadialBasisKind::Gaussian);
  try {
    radialBasisKind("thin_plate_spline");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method.basis");
    const std::string message = e.what();
    EXPECT_NE(message.find("unknown radial basis function 'thin_plate_spline'"), std::string::npos) << message;
    EXPECT_NE(message.find("valid: inverse_multiquadric, multiquadric, gaussian"), std::string::npos) << message;
  }
  EXPECT_EQ(inputErrorKey([] { makeRadialBasisFunction("multiquadric", 0.0); }), "method.shape_parameter");
  EXPECT_EQ(inputErrorKey([] { makeRadialBasisFunction("multiquadric", -1.0); }), "method.shape_parameter");
  EXPECT_EQ(inputErrorKey([] { makeRadialBasisFunction("multiquadric", INFINITY); }), "method.shape_parameter");

  const Coordinates<1> nodes = line(20);
  const RadialBasisFunction imq(RadialBasisKind::InverseMultiquadric, 0.2);
  EXPECT_EQ(inputErrorKey([&] { RadialBasisShapeFunctions<1>(nodes, imq, 4); }), "method.polynomial_degree");
  EXPECT_EQ(inputErrorKey([&] { RadialBasisShapeFunctions<1>(nodes, imq, -2); }), "method.polynomial_degree");
  EXPECT_EQ(inputErrorKey([&] { RadialBasisShapeFunctions<1>(nodes, imq, 3); }), "");
  // A very flat Gaussian (c = 400 node spacings) makes G singular in double precision.
  EXPECT_EQ(
      inputErrorKey([&] { RadialBasisShapeFunctions<1>(nodes, RadialBasisFunction(RadialBasisKind::Gaussian, 20.0)); }),
      "method.shape_parameter");
  // Nodes on a line do not determine a linear polynomial in 2-D.
  Coordinates<2> collinear;
  for (int i = 0; i <= 5; ++i) {
    collinear[0].push_back(0.2 * i);
    collinear[1].push_back(0.0);
  }
  EXPECT_EQ(inputErrorKey([&] {
              RadialBasisShapeFunctions<2>(collinear, RadialBasisFunction(RadialBasisKind::Multiquadric, 0.3), 1);
            }),
            "method.polynomial_degree");
  EXPECT_EQ(inputErrorKey([&] {
              RadialBasisShapeFunctions<2>(collinear, RadialBasisFunction(RadialBasisKind::Multiquadric, 0.3), 0);
            }),
            "");
  EXPECT_EQ(inputErrorKey([&] { RadialBasisShapeFunctions<1>(Coordinates<1>{}, imq); }), "method.nodes");
}
