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
    std::optional<VectorDistribution> distribution() const override { return VectorDistribution{&handle, 7, {}}; }
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

// A system's ordered sums (VectorDistribution::orderedSumOfSquares) carry over to [u; v]: the u
// half's sum, then the v half's, each over the system's own length.
TEST(SecondOrderAsFirstOrder, SumsTheHalvesInTheSystemsOrder) {
  struct Ordered : SecondOrderSystem {
    Index size() const override { return 3; }
    void acceleration(Real, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector>, Eigen::Ref<Vector> a) override { a = -u; }
    std::optional<VectorDistribution> distribution() const override {
      VectorDistribution d{nullptr, 3, {}};
      // Weighs each place by its index + 1 and counts calls, so a wrong split or length shows.
      d.orderedSumOfSquares = [this](const Real* z, Index count) {
        ++calls;
        Real s = 0;
        for (Index i = 0; i < count; ++i) s += static_cast<Real>(i + 1) * z[i] * z[i];
        return s + 1000 * static_cast<Real>(count);
      };
      return d;
    }
    mutable int calls = 0;
  } ordered;
  const std::optional<VectorDistribution> d = SecondOrderAsFirstOrder(ordered).distribution();
  ASSERT_TRUE(d.has_value() && d->orderedSumOfSquares);
  EXPECT_EQ(d->communicator, nullptr);
  EXPECT_EQ(d->globalSize, 6);
  const Real z[6] = {1, 2, 3, 4, 5, 6};
  // (1 + 8 + 27 + 3000) + (16 + 50 + 108 + 3000)
  EXPECT_EQ(d->orderedSumOfSquares(z, 6), 6210.0);
  EXPECT_EQ(ordered.calls, 2);
}
