#include "analytic/LambStripLoad.hpp"

#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace mfwave;

namespace {
const double kStripCp = std::sqrt(3.0);  // lambda = mu = rho = 1

// Receivers of the 2-D study: (x, depth).
struct StripReceiver {
  double x, depth;
};
const StripReceiver kStripReceivers[] = {{0, 0}, {2, 0}, {0, 1}};

// Surface settlement of the half-plane under unit pressure on |x| < l up to a constant (Flamant's
// line load integrated over the strip): u(x) = -(1 - nu) / (pi mu) F(x) + C,
// F(x) = int_{-l}^{l} ln|x - x'| dx' = (x + l) ln|x + l| - (x - l) ln|x - l| - 2 l.
double flamantStripLog(double x, double l) {
  auto g = [](double u) { return u == 0 ? 0.0 : u * std::log(std::abs(u)); };
  return g(x + l) - g(x - l) - 2 * l;
}
}  // namespace

// For nu = 1/4 the Rayleigh speed is c_s sqrt(2 - 2 / sqrt 3) (Rayleigh's cubic in closed form).
TEST(LambStripLoad, RayleighSpeedForPoissonQuarter) {
  const LambStripLoad load = LambStripLoad::dingLongWu();
  EXPECT_NEAR(load.rayleighWaveSpeed(), std::sqrt(2 - 2 / std::sqrt(3.0)), 1e-13);
  EXPECT_NEAR(load.pWaveSpeed(), kStripCp, 1e-15);
}

// Until a wave from the strip's edges arrives, a receiver under the strip sees the 1-D plane P
// wave: v = p f(t - z / c_p) / (rho c_p). At the centre of the surface the edges are felt at
// l / c_p; at depth 1 the plane wave arrives at 1 / c_p and the edges' P waves at sqrt(1.25) / c_p.
TEST(LambStripLoad, FirstMotionIsThePlaneWave) {
  const LambStripLoad load = LambStripLoad::dingLongWu();
  for (double t = 0.01; t < 0.5 / kStripCp; t += 0.02)
    EXPECT_NEAR(load.velocity(0, 0, t), t / kStripCp, 1e-12) << t;
  const double arrival = 1 / kStripCp, edges = std::sqrt(1.25) / kStripCp;
  for (double t = 0.05; t < arrival; t += 0.05) EXPECT_EQ(load.velocity(0, 1, t), 0.0) << t;
  for (double t = arrival + 0.005; t < edges; t += 0.01)
    EXPECT_NEAR(load.velocity(0, 1, t), (t - arrival) / kStripCp, 1e-12) << t;
  // ... and the edges change it right after they arrive.
  EXPECT_GT(std::abs(load.velocity(0, 1, edges + 0.02) - (edges + 0.02 - arrival) / kStripCp), 1e-4);
}

// Nothing reaches a receiver before the P wave from the nearest loaded point.
TEST(LambStripLoad, NothingBeforeTheFirstArrival) {
  const LambStripLoad load = LambStripLoad::dingLongWu();
  const double arrival = 1.5 / kStripCp;
  for (double t = 0.05; t < arrival; t += 0.05) {
    EXPECT_EQ(load.velocity(2, 0, t), 0.0) << t;
    EXPECT_EQ(load.displacement(2, 0, t), 0.0) << t;
  }
  EXPECT_GT(std::abs(load.velocity(2, 0, arrival + 0.05)), 1e-4);
  // A receiver beside the strip at depth: the nearest loaded point is the edge.
  const double inside = std::hypot(1.5, 1.0) / kStripCp;
  EXPECT_EQ(load.velocity(2, 1, inside - 0.01), 0.0);
  EXPECT_GT(std::abs(load.velocity(2, 1, inside + 0.05)), 1e-5);
}

// The quadrature: 24 and 48 points per piece agree to about 1e-11 of the peak at every receiver
// (velocity and displacement, 0 <= t <= 8), including the head-wave receiver (2, 0.5).
TEST(LambStripLoad, QuadratureConverges) {
  LambStripLoad coarse = LambStripLoad::dingLongWu(), fine = LambStripLoad::dingLongWu();
  fine.setQuadraturePoints(48);
  for (const StripReceiver& r : {StripReceiver{0, 0}, StripReceiver{2, 0}, StripReceiver{0, 1},
                                 StripReceiver{2, 0.5}, StripReceiver{0.3, 0.05}}) {
    double peak = 0, worstV = 0, worstU = 0;
    for (double t = 0.0125; t <= 8; t += 0.05) {
      const double v = fine.velocity(r.x, r.depth, t);
      peak = std::max(peak, std::abs(v));
      worstV = std::max(worstV, std::abs(coarse.velocity(r.x, r.depth, t) - v));
      worstU = std::max(worstU, std::abs(coarse.displacement(r.x, r.depth, t) -
                                         fine.displacement(r.x, r.depth, t)));
    }
    EXPECT_LT(worstV, 1e-10 * peak) << r.x << " " << r.depth;
    EXPECT_LT(worstU, 1e-10 * peak) << r.x << " " << r.depth;
  }
}

// The displacement (ramp responses) and the velocity (step responses) come from different
// weights of the same kernel: the time integral of one must be the other.
TEST(LambStripLoad, VelocityIntegratesToTheDisplacement) {
  const LambStripLoad load = LambStripLoad::dingLongWu();
  for (const StripReceiver& r : kStripReceivers) {
    // Composite Simpson on a fine grid (the velocity is continuous, with kinks at the fronts).
    const int n = 6000;
    const double T = 6, h = T / n;
    double sum = load.velocity(r.x, r.depth, 0) + load.velocity(r.x, r.depth, T);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * load.velocity(r.x, r.depth, i * h);
    const double integral = sum * h / 3, u = load.displacement(r.x, r.depth, T);
    EXPECT_NEAR(integral, u, 2e-5 * std::abs(u) + 1e-7) << r.x << " " << r.depth;
  }
}

// Long after the fronts the step response is Flamant's static one plus a uniform logarithm in
// time: the difference between two surface points tends to the static difference, and the centre
// grows like (1 - nu) 2 l p ln(t) / (pi mu). Both approach like 1/t^2: at t = 400 the difference
// is 4e-6 from Flamant's (6e-5 at t = 100), the slopes 2e-7 and 5e-6 from the coefficient.
TEST(LambStripLoad, StepResponseTendsToFlamant) {
  const LambStripLoad load = LambStripLoad::dingLongWu();
  const double l = 0.5, coefficient = 0.75 / kPi;  // (1 - nu) / (pi mu), nu = 1/4
  const double staticDifference = coefficient * (flamantStripLog(2, l) - flamantStripLog(0, l));
  const double t = 400;
  const double difference = load.stepDisplacement(0, 0, t) - load.stepDisplacement(2, 0, t);
  EXPECT_NEAR(difference, staticDifference, 2e-5 * std::abs(staticDifference));
  const double slope = (load.stepDisplacement(0, 0, 2 * t) - load.stepDisplacement(0, 0, t)) / std::log(2.0);
  EXPECT_NEAR(slope, coefficient * 2 * l, 2e-6 * coefficient * 2 * l);
  // At depth: the same logarithm in time.
  const double deep = (load.stepDisplacement(0, 1, 2 * t) - load.stepDisplacement(0, 1, t)) / std::log(2.0);
  EXPECT_NEAR(deep, coefficient * 2 * l, 2e-5 * coefficient * 2 * l);
}

// Symmetric in x; linear in the pressure.
TEST(LambStripLoad, SymmetryAndLinearity) {
  const LambStripLoad load = LambStripLoad::dingLongWu();
  const LambStripLoad twice(1, 1, 1, 0.5, {0, 1, 2}, {0, 1, 0}, 2);
  for (double t : {0.7, 1.3, 2.9, 5.0}) {
    EXPECT_NEAR(load.velocity(1.2, 0.4, t), load.velocity(-1.2, 0.4, t), 1e-13);
    EXPECT_NEAR(twice.velocity(0, 1, t), 2 * load.velocity(0, 1, t), 1e-13);
  }
}

TEST(LambStripLoad, RejectsBadInputNamingTheKey) {
  using mfwave::testing::inputErrorKey;
  const std::vector<double> t = {0, 1, 2}, f = {0, 1, 0};
  EXPECT_EQ(inputErrorKey([&] { LambStripLoad(1, 1, 1, 0, t, f); }), "half_width");
  EXPECT_EQ(inputErrorKey([&] { LambStripLoad(1, 0, 1, 0.5, t, f); }), "shear_modulus");
  EXPECT_EQ(inputErrorKey([&] { LambStripLoad(1, 1, -1, 0.5, t, f); }), "density");
  EXPECT_EQ(inputErrorKey([&] { LambStripLoad(-1, 1, 1, 0.5, t, f); }), "lambda");
  EXPECT_EQ(inputErrorKey([&] { LambStripLoad(1, 1, 1, 0.5, {0, 2, 1}, f); }), "times");
  EXPECT_EQ(inputErrorKey([&] { LambStripLoad(1, 1, 1, 0.5, t, {1, 1, 0}); }), "values");
  EXPECT_EQ(inputErrorKey([&] { LambStripLoad::dingLongWu().velocity(0, -1, 1); }), "depth");
  EXPECT_EQ(inputErrorKey([&] { LambStripLoad::dingLongWu().setQuadraturePoints(1); }), "quadrature_points");
}

// The reference values of the 2-D test (printed for the report and the study).
TEST(LambStripLoad, ReferenceValues) {
  const LambStripLoad load = LambStripLoad::dingLongWu();
  for (double t : {0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 6.0})
    std::printf("t = %.1f  v(0,0) = %+.8f  v(2,0) = %+.8f  v(0,-1) = %+.8f  u(0,0) = %+.8f\n", t,
                load.velocity(0, 0, t), load.velocity(2, 0, t), load.velocity(0, 1, t),
                load.displacement(0, 0, t));
  SUCCEED();
}
