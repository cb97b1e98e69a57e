#include "systems/LinearSecondOrderSystem.hpp"
#include "systems/SecondOrderAsFirstOrder.hpp"

#include <gtest/gtest.h>

using namespace mfwave;

TEST(SecondOrderAsFirstOrder, StacksVelocityAndAcceleration) {
  SparseMatrix m(1, 1), k(1, 1), c(1, 1);
  m.insert(0, 0) = 2;
  k.insert(0, 0) = 8;
  c.insert(0, 0) = 1;
  LinearSecondOrderSystem oscillator(m, c, k);
  SecondOrderAsFirstOrder first(oscillator);
  ASSERT_EQ(first.size(), 2);
  Vector u(1), v(1);
  u << 0.5;
  v << -1;
  const Vector y = first.pack(u, v);
  Vector ydot(2);
  first.rhs(0, y, ydot);
  EXPECT_DOUBLE_EQ(ydot[0], -1);
  EXPECT_DOUBLE_EQ(ydot[1], (-8 * 0.5 - 1 * -1) / 2.0);
  Vector u2, v2;
  first.unpack(y, u2, v2);
  EXPECT_EQ(u2, u);
  EXPECT_EQ(v2, v);
}

// The first-order view of a rank's share holds [u; v] of the rank's dofs: the same communicator,
// twice the global length (what ARKODE's MPI vectors are made with). A serial system has none.
TEST(SecondOrderAsFirstOrder, PassesOnTheDistributionWithTwiceTheLength) {
  struct Share : SecondOrderSystem {
    Index size() const override { return 3; }
    void acceleration(Real, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector>, Eigen::Ref<Vector> a) override { a = -u; }
    std::optional<VectorDistribution> distribution() const override { return VectorDistribution{&handle, 7}; }
    int handle = 0;  // stands for a communicator
  } share;
  const std::optional<VectorDistribution> d = SecondOrderAsFirstOrder(share).distribution();
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->communicator, &share.handle);
  EXPECT_EQ(d->globalSize, 14);

  SparseMatrix m(1, 1), k(1, 1);
  m.insert(0, 0) = 1;
  k.insert(0, 0) = 1;
  LinearSecondOrderSystem serial(m, SparseMatrix(1, 1), k);
  EXPECT_FALSE(SecondOrderAsFirstOrder(serial).distribution().has_value());
}
