#include "core/Error.hpp"
#include "solvers/FactorisedMatrix.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

using namespace mfwave;

namespace {

SparseMatrix sparseOf(const Eigen::MatrixXd& dense) { return dense.sparseView(); }

}  // namespace

TEST(FactorisedMatrix, DiagonalSquareAndTallMatricesSolve) {
  FactorisedMatrix diagonal;
  diagonal.factorise(sparseOf(Eigen::Vector3d(2, 4, 8).asDiagonal()), "diagonal");
  EXPECT_TRUE(diagonal.isDiagonal());
  EXPECT_TRUE(diagonal.solve(Vector(Eigen::Vector3d(2, 4, 8))).isApprox(Vector::Ones(3), 1e-15));

  Eigen::MatrixXd square(3, 3);
  square << 4, 1, 0, 1, 3, 1, 0, 1, 2;
  FactorisedMatrix lu;
  lu.factorise(sparseOf(square), "square");
  const Vector x(Eigen::Vector3d(1, -2, 3));
  EXPECT_LT((lu.solve(Vector(square * x)) - x).norm(), 1e-13);
  EXPECT_LT((lu.solve(Eigen::MatrixXd(square * Eigen::MatrixXd::Identity(3, 3))) - Eigen::MatrixXd::Identity(3, 3)).norm(),
            1e-13);

  // Tall: 4 equations, 2 unknowns; the least-squares solution of the normal equations.
  Eigen::MatrixXd tall(4, 2);
  tall << 1, 0, 0, 1, 1, 1, 1, -1;
  const Vector b(Eigen::Vector4d(1, 2, 4, 0));
  FactorisedMatrix qr;
  qr.factorise(sparseOf(tall), "tall");
  EXPECT_TRUE(qr.isLeastSquares());
  EXPECT_EQ(qr.rows(), 4);
  EXPECT_EQ(qr.size(), 2);
  const Vector expected = (tall.transpose() * tall).ldlt().solve(tall.transpose() * b);
  EXPECT_LT((qr.solve(b) - expected).norm(), 1e-13);
}

TEST(FactorisedMatrix, SingularAndRankDeficientMatricesAreNamed) {
  Eigen::MatrixXd singular(2, 2);
  singular << 1, 2, 2, 4;
  FactorisedMatrix lu;
  try {
    lu.factorise(sparseOf(singular), "the test matrix");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the test matrix"), std::string::npos) << e.what();
  }
  Eigen::MatrixXd tall(3, 2);
  tall << 1, 2, 2, 4, 3, 6;  // rank 1
  FactorisedMatrix qr;
  EXPECT_THROW(qr.factorise(sparseOf(tall), "tall"), Error);
  Eigen::MatrixXd wide(2, 3);
  wide << 1, 0, 0, 0, 1, 0;
  EXPECT_THROW(qr.factorise(sparseOf(wide), "wide"), Error);
  // Nearly singular (condition ~ 1e16): the factorisation cannot be trusted and says so.
  Eigen::MatrixXd nearly(2, 2);
  nearly << 1, 1, 1, 1 + 1e-15;
  FactorisedMatrix bad;
  try {
    bad.factorise(sparseOf(nearly), "the nearly singular matrix");
    FAIL() << "accepted a matrix it cannot solve";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the nearly singular matrix"), std::string::npos) << e.what();
  }
  FactorisedMatrix fresh;
  EXPECT_THROW(fresh.solve(Vector(Vector::Ones(2))), Error);
}

TEST(FactorisedMatrix, BlockDiagonalMatricesAreSolvedBlockByBlock) {
  // Per-particle dashpot blocks M/dt + C/2: two particles of three components, then three of two.
  Eigen::MatrixXd threes = Eigen::MatrixXd::Zero(6, 6);
  threes.topLeftCorner(3, 3) << 4, 1, 0.5, 1, 3, -0.7, 0.5, -0.7, 5;
  threes.bottomRightCorner(3, 3) << 2, 0, 1, 0, 6, 0, 1, 0, 3;  // a zero inside a block is fine
  Eigen::MatrixXd twos = Eigen::MatrixXd::Zero(6, 6);
  for (int b = 0; b < 3; ++b) twos.block(2 * b, 2 * b, 2, 2) << 3 + b, 1, -1, 2;
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(6, 2);
  for (const auto& [matrix, size] : {std::pair{threes, 3}, std::pair{twos, 2}}) {
    FactorisedMatrix blocks;
    blocks.factorise(sparseOf(matrix), "blocks");
    EXPECT_EQ(blocks.blockSize(), size);
    EXPECT_FALSE(blocks.isDiagonal());
    const Eigen::MatrixXd expected = matrix.partialPivLu().solve(rhs);
    EXPECT_LT((blocks.solve(Vector(rhs.col(0))) - expected.col(0)).norm(), 1e-14);
    EXPECT_LT((blocks.solve(rhs) - expected).norm(), 1e-14);
  }
  // One entry across a block boundary: not block diagonal, UMFPACK.
  Eigen::MatrixXd coupled = threes;
  coupled(2, 3) = 0.1;
  FactorisedMatrix lu;
  lu.factorise(sparseOf(coupled), "coupled");
  EXPECT_EQ(lu.blockSize(), 0);
  // A singular block is named.
  Eigen::MatrixXd singular = threes;
  singular.bottomRightCorner(3, 3) << 1, 2, 3, 2, 4, 6, 0, 0, 1;
  FactorisedMatrix bad;
  try {
    bad.factorise(sparseOf(singular), "the block matrix");
    FAIL();
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("the block matrix"), std::string::npos) << what;
    EXPECT_NE(what.find("block 1"), std::string::npos) << what;
  }
}

// M + dt/2 C with dashpots coupling a few unknowns (a boundary layer): the decoupled unknowns are
// solved by reciprocals and UMFPACK sees only the coupled block; the result is the full solve.
TEST(FactorisedMatrix, DecoupledUnknownsAreSplitFromTheCoupledBlock) {
  const int n = 40;
  std::vector<Triplet> entries;
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, 2.0 + 0.1 * i);
  // Unknowns 3, 7, 8 and 30 coupled (not symmetrically), the rest diagonal.
  entries.emplace_back(3, 7, 0.5);
  entries.emplace_back(7, 8, -0.25);
  entries.emplace_back(8, 3, 0.3);
  entries.emplace_back(30, 8, 0.7);
  SparseMatrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  FactorisedMatrix f;
  f.factorise(a, "test matrix");
  Vector b(n);
  for (int i = 0; i < n; ++i) b[i] = std::sin(1.0 + i);
  const Vector x = f.solve(b);
  EXPECT_LT((a * x - b).norm(), 1e-13 * b.norm());
  const Eigen::MatrixXd dense = Eigen::MatrixXd(a);
  EXPECT_LT((x - dense.lu().solve(b)).norm(), 1e-13);
  Eigen::MatrixXd several(n, 2);
  several.col(0) = b;
  several.col(1) = 2 * b;
  const Eigen::MatrixXd xs = f.solve(several);
  EXPECT_LT((xs.col(1) - 2 * x).norm(), 1e-12);
  // A zero on a decoupled diagonal is named.
  SparseMatrix singular = a;
  singular.coeffRef(20, 20) = 0;
  EXPECT_THROW(f.factorise(singular, "singular test matrix"), Error);
}
