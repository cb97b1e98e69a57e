// Shape-function matrices over evaluation points: the collocation matrices M_ij = psi_j(xi_i) and
// A_ij = psi_j,xx(xi_i) of Luo-Liu-Huang eqs. (34), (35).

#include <gtest/gtest.h>

#include <string>

#include "CollocationTestSupport.hpp"
#include "core/Error.hpp"
#include "methods/collocation/RadialBasisShapeFunctions.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"
#include "methods/collocation/ShapeFunctionMatrix.hpp"
#include "support/InputErrorKey.hpp"

using namespace mfwave;
using namespace mfwave::testing;

TEST(ShapeFunctionMatrix, ReproducesAQuadraticAtTheNodesWithOrderTwoRk) {
  // q(x, y) = 0.5 - x + 2 y + 3 x^2 - 1.5 x y + 0.7 y^2 on a perturbed 13 x 13 cloud, m = 2,
  // a = 3.5 dx: M q_nodes = q at the nodes, and the derivative matrices give q's derivatives.
  const Real dx = 1.0 / 12;
  const Coordinates<2> nodes = unitLattice<2>(12, 0.3);
  const ReproducingKernelShapeFunctions<2> rk(nodes, 2, 3.5 * dx);
  auto q = [](const Vec2& x) {
    return 0.5 - x[0] + 2 * x[1] + 3 * x[0] * x[0] - 1.5 * x[0] * x[1] + 0.7 * x[1] * x[1];
  };
  const std::vector<Vec2> points = pointsOf<2>(nodes);
  Vector nodal(rk.nodeCount()), qx(rk.nodeCount());
  for (Index i = 0; i < rk.nodeCount(); ++i) {
    nodal[i] = q(points[static_cast<std::size_t>(i)]);
    qx[i] = -1 + 6 * points[static_cast<std::size_t>(i)][0] - 1.5 * points[static_cast<std::size_t>(i)][1];
  }

  const SparseMatrix m = shapeFunctionMatrix<2>(rk, points, ShapeDerivative::value());
  ASSERT_EQ(m.rows(), rk.nodeCount());
  ASSERT_EQ(m.cols(), rk.nodeCount());
  EXPECT_LT((m * nodal - nodal).cwiseAbs().maxCoeff(), 1e-12);
  // RK functions do not interpolate: M is not the identity (able to fail).
  EXPECT_GT((Eigen::MatrixXd(m) - Eigen::MatrixXd::Identity(m.rows(), m.cols())).cwiseAbs().maxCoeff(), 0.1);

  const std::vector<SparseMatrix> d = shapeFunctionMatrices<2>(
      rk, points,
      {ShapeDerivative::gradient(0), ShapeDerivative::hessian(0, 0), ShapeDerivative::hessian(0, 1),
       ShapeDerivative::hessian(1, 1), ShapeDerivative::value()});
  ASSERT_EQ(d.size(), 5u);
  EXPECT_LT((d[0] * nodal - qx).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((d[1] * nodal - Vector::Constant(rk.nodeCount(), 6.0)).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT((d[2] * nodal - Vector::Constant(rk.nodeCount(), -1.5)).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT((d[3] * nodal - Vector::Constant(rk.nodeCount(), 1.4)).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_EQ((Eigen::MatrixXd(d[4]) - Eigen::MatrixXd(m)).cwiseAbs().maxCoeff(), 0.0);

  // Row i holds exactly the nodes within the support of node i.
  ShapeFunctionValues<2> values;
  for (const Index row : {Index(0), Index(84), Index(168)}) {
    rk.evaluate(points[static_cast<std::size_t>(row)], 0, values);
    const Eigen::SparseMatrix<Real, Eigen::RowMajor, int> rows(m);
    EXPECT_EQ(rows.outerIndexPtr()[row + 1] - rows.outerIndexPtr()[row], static_cast<int>(values.size()));
  }
}

TEST(ShapeFunctionMatrix, DenseAndSparseAgreeForRadialBasisFunctions) {
  const Coordinates<1> nodes = unitLattice<1>(20, 0.0);
  const RadialBasisShapeFunctions<1> rbf(nodes, RadialBasisFunction(RadialBasisKind::InverseMultiquadric, 0.2));
  std::vector<Vec1> points;
  for (int i = 0; i <= 40; ++i) points.emplace_back(0.025 * i);
  const Eigen::MatrixXd dense = denseShapeFunctionMatrix<1>(rbf, points, ShapeDerivative::hessian(0, 0));
  const SparseMatrix sparse = shapeFunctionMatrix<1>(rbf, points, ShapeDerivative::hessian(0, 0));
  ASSERT_EQ(dense.rows(), 41);
  ASSERT_EQ(dense.cols(), 21);
  EXPECT_EQ(sparse.nonZeros(), 41 * 21);  // dense RBF fills every entry
  EXPECT_EQ((dense - Eigen::MatrixXd(sparse)).cwiseAbs().maxCoeff(), 0.0);
  // Values at the nodes: the identity (interpolation), to the conditioning-limited tolerance.
  const Eigen::MatrixXd atNodes = denseShapeFunctionMatrix<1>(rbf, pointsOf<1>(nodes), ShapeDerivative::value());
  EXPECT_LT((atNodes - Eigen::MatrixXd::Identity(21, 21)).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(ShapeFunctionMatrix, ErrorsNameTheKeyAndTheFirstFailingPoint) {
  const Coordinates<1> nodes = unitLattice<1>(10, 0.0);
  const ReproducingKernelShapeFunctions<1> rk(nodes, 1, 0.25);
  const std::vector<Vec1> points = {Vec1(0.5), Vec1(3.0), Vec1(0.2), Vec1(5.0)};
  try {
    shapeFunctionMatrix<1>(rk, points, ShapeDerivative::value());
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method.support");
    EXPECT_NE(std::string(e.what()).find("x = (3)"), std::string::npos) << e.what();
  }
  EXPECT_EQ(inputErrorKey([&] { shapeFunctionMatrix<1>(rk, {Vec1(0.5)}, ShapeDerivative::gradient(1)); }),
            "method.derivative");
  EXPECT_EQ(inputErrorKey([&] {
              shapeFunctionMatrix<1>(rk, {Vec1(0.5)}, ShapeDerivative{3, 0, 0});
            }),
            "method.derivative");
  EXPECT_EQ(shapeFunctionMatrix<1>(rk, {}, ShapeDerivative::value()).rows(), 0);
}
