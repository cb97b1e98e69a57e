#include "analytic/LambSquareLoad.hpp"
#include "analytic/PekerisPointLoad.hpp"
#include "core/Error.hpp"
#include "core/TimeFunction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

using namespace mfwave;

namespace {
const double kRoot3 = std::sqrt(3.0);

// int_{x1}^{x2} int_{y1}^{y2} dx dy / sqrt(x^2 + y^2) from the corner antiderivative
// G(x, y) = x asinh(y / |x|) + y asinh(x / |y|) (odd in x and in y, 0 on the axes).
double inverseDistanceIntegral(double x1, double x2, double y1, double y2) {
  auto g = [](double x, double y) {
    double v = 0;
    if (x != 0 && y != 0) v = x * std::asinh(y / std::abs(x)) + y * std::asinh(x / std::abs(y));
    return v;
  };
  return g(x2, y2) - g(x1, y2) - g(x2, y1) + g(x1, y1);
}

// Boussinesq settlement of the surface point (x, y) under unit pressure on |x|,|y| < l (nu = 1/4).
double boussinesqSquare(double x, double y, double l, double mu) {
  return 3 / (8 * M_PI * mu) * inverseDistanceIntegral(-l - x, l - x, -l - y, l - y);
}

double adaptiveSimpson(const std::function<double(double)>& f, double a, double b, double fa,
                       double fm, double fb, double whole, double tol, int depth) {
  const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15 * tol)
    return left + right + (left + right - whole) / 15;
  return adaptiveSimpson(f, a, m, fa, flm, fm, left, tol / 2, depth - 1) +
         adaptiveSimpson(f, m, b, fm, frm, fb, right, tol / 2, depth - 1);
}
double integrateToTolerance(const std::function<double(double)>& f, double a, double b, double tol) {
  const double fa = f(a), fb = f(b), fm = f(0.5 * (a + b));
  return adaptiveSimpson(f, a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), tol, 40);
}
}  // namespace

TEST(LambSquareLoad, StaticLimitIsTheBoussinesqSettlementOfTheSquare) {
  const double l = 0.5, mu = 1;
  // Centre of a square of side B = 2l: w = p B (1 - nu^2)/E (2/pi) 2 ln(1 + sqrt2)
  //                                      = 3 p l ln(1 + sqrt2) / (pi mu)        (nu = 1/4).
  const double centre = 3 * l * std::log(1 + std::sqrt(2.0)) / (M_PI * mu);
  EXPECT_NEAR(boussinesqSquare(0, 0, l, mu), centre, 1e-14);
  // Independent 2-D check of the corner formula: tensor Gauss-Legendre on a receiver outside.
  {
    const double x0 = 2, y0 = 0.3;
    double q = 0;
    const int n = 200;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double x = -l + (i + 0.5) * 2 * l / n, y = -l + (j + 0.5) * 2 * l / n;
        q += std::pow(2 * l / n, 2) / std::hypot(x - x0, y - y0);
      }
    EXPECT_NEAR(inverseDistanceIntegral(-l - x0, l - x0, -l - y0, l - y0), q, 1e-5);
  }
  const LambSquareLoad load(mu, 1, l, {0, 1}, {0, 1});
  for (auto [x, y] : {std::pair{0.0, 0.0}, std::pair{0.2, -0.3}, std::pair{0.5, 0.1},
                      std::pair{0.5, 0.5}, std::pair{2.0, 0.0}, std::pair{-1.3, 0.9}}) {
    const double expected = boussinesqSquare(x, y, l, mu);
    EXPECT_NEAR(load.stepDisplacement(x, y, 100), expected, 1e-10 * expected) << x << " " << y;
    EXPECT_NEAR(load.displacement(x, y, 100), expected, 1e-10 * expected) << x << " " << y;
    EXPECT_NEAR(load.velocity(x, y, 100), 0, 1e-12);
  }
}

TEST(LambSquareLoad, PlaneWaveBeforeTheEdgesAreFelt) {
  // At the centre, before the P wave from the nearest edge (t < l / c_p), the surface moves as
  // under a uniform pressure on the whole surface: u = p t / (rho c_p) for a step.
  const LambSquareLoad load(1, 1, 0.5, {0, 1}, {0, 1});
  for (double t : {0.05, 0.2, 0.28}) {
    EXPECT_NEAR(load.stepDisplacement(0, 0, t), t / kRoot3, 1e-13) << t;
    EXPECT_NEAR(load.rampDisplacement(0, 0, t), t * t / (2 * kRoot3), 1e-13) << t;
  }
  // mu = 4, rho = 1 (c_s = 2), p = 3: u = p t / (rho c_p) = 3 t / (2 sqrt3).
  const LambSquareLoad other(4, 2, 0.5, {0, 1}, {0, 1}, 3);
  EXPECT_NEAR(other.stepDisplacement(0, 0, 0.1), 3 * 0.1 / (2 * kRoot3), 1e-13);
}

TEST(LambSquareLoad, QuadratureConverges) {
  LambSquareLoad coarse = LambSquareLoad::dingLongWu(), fine = LambSquareLoad::dingLongWu();
  fine.setQuadraturePoints(48);
  for (double t : {0.3, 0.5, 0.6, 0.8, 1.0, 1.5, 2.2, 3.0, 4.0})
    for (auto [x, y] : {std::pair{0.0, 0.0}, std::pair{2.0, 0.0}, std::pair{0.3, 0.5}}) {
      EXPECT_NEAR(coarse.velocity(x, y, t), fine.velocity(x, y, t), 1e-11) << t;
      EXPECT_NEAR(coarse.displacement(x, y, t), fine.displacement(x, y, t), 1e-11) << t;
    }
}

TEST(LambSquareLoad, ArrivalsAndConsistencyOfVelocityAndDisplacement) {
  const LambSquareLoad load = LambSquareLoad::dingLongWu();
  const TimeFunction f = TimeFunction::triangle(0, 1, 1, 1);  // Ding-Long-Wu eq. (36)
  for (double t : {-1.0, 0.0, 0.3, 1.0, 1.7, 2.0, 3.0}) EXPECT_NEAR(load.loadHistory(t), f(t), 1e-15);
  // Zero before the P wave from the nearest loaded point (1.5 away from (2, 0)).
  const double tp = 1.5 / kRoot3;
  for (double t : {0.0, 0.5, 0.8, tp}) {
    EXPECT_EQ(load.velocity(2, 0, t), 0) << t;
    EXPECT_EQ(load.displacement(2, 0, t), 0) << t;
  }
  EXPECT_NE(load.velocity(2, 0, tp + 0.05), 0);
  EXPECT_NE(load.velocity(0, 0, 0.01), 0);
  for (auto [x, y] : {std::pair{0.0, 0.0}, std::pair{2.0, 0.0}}) {
    double maxV = 0;
    for (int i = 0; i <= 600; ++i) {
      const double v = load.velocity(x, y, 0.01 * i);
      EXPECT_TRUE(std::isfinite(v));
      maxV = std::max(maxV, std::abs(v));
    }
    EXPECT_LT(maxV, 1);
    // int_0^t v = u (the velocity is continuous; adaptive Simpson).
    double integral = 0, previous = 0;
    for (double t : {1.0, 2.0, 3.0, 4.5, 6.0}) {
      integral += integrateToTolerance([&](double s) { return load.velocity(x, y, s); }, previous, t, 1e-10);
      previous = t;
      EXPECT_NEAR(integral, load.displacement(x, y, t), 1e-6) << x << " " << t;
    }
  }
}

TEST(LambSquareLoad, Symmetry) {
  const LambSquareLoad load = LambSquareLoad::dingLongWu();
  for (double t : {0.4, 1.0, 1.7, 2.5, 4.0})
    for (auto [x, y] : {std::pair{0.2, 0.1}, std::pair{0.5, 0.3}, std::pair{1.2, 0.7},
                        std::pair{2.0, 0.0}, std::pair{0.5, 0.5}}) {
      const double v = load.velocity(x, y, t), u = load.displacement(x, y, t);
      for (auto [xx, yy] : {std::pair{y, x}, std::pair{-x, y}, std::pair{x, -y}, std::pair{-y, -x}}) {
        EXPECT_NEAR(load.velocity(xx, yy, t), v, 1e-12) << x << " " << y << " " << t;
        EXPECT_NEAR(load.displacement(xx, yy, t), u, 1e-12) << x << " " << y << " " << t;
      }
    }
}

TEST(LambSquareLoad, SmallSquareTendsToThePointLoad) {
  // Far from a small square the response is the Pekeris point response of the total force,
  // away from the Rayleigh singularity (here at t = 3 c_s / c_R = 3.263).
  const double l = 0.01;
  const LambSquareLoad square(1, 1, l, {0, 1}, {0, 1});
  const PekerisPointLoad point(1, 1, 4 * l * l);
  for (double t : {1.9, 2.5, 3.1, 3.5})
    EXPECT_NEAR(square.stepDisplacement(3, 0, t), point.displacement(3, t),
                2e-3 * std::abs(point.displacement(3, 0.5 * (t + 4)))) << t;
}

TEST(LambSquareLoad, RejectsBadInput) {
  EXPECT_THROW(LambSquareLoad(1, 1, 0, {0, 1}, {0, 1}), InputError);
  EXPECT_THROW(LambSquareLoad(1, 1, 1, {0, 1}, {1, 1}), InputError);  // jump at the start
  EXPECT_THROW(LambSquareLoad(1, 1, 1, {1, 0}, {0, 1}), InputError);
  EXPECT_THROW(LambSquareLoad(1, 1, 1, {0}, {0}), InputError);
}

// The reference values of the Ding-Long-Wu test (printed, for the report and the study).
TEST(LambSquareLoad, DingLongWuReferenceValues) {
  const LambSquareLoad load = LambSquareLoad::dingLongWu();
  for (double t : {0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 6.0})
    std::printf("t = %.1f  v(0,0) = %+.8f  v(2,0) = %+.8f  u(0,0) = %+.8f  u(2,0) = %+.8f\n", t,
                load.velocity(0, 0, t), load.velocity(2, 0, t), load.displacement(0, 0, t),
                load.displacement(2, 0, t));
  double peak = 0, tPeak = 0;
  for (int i = 0; i <= 6000; ++i) {
    const double t = 0.001 * i, v = load.velocity(0, 0, t);
    if (std::abs(v) > std::abs(peak)) { peak = v; tPeak = t; }
  }
  std::printf("centre peak velocity %+.6f at t = %.3f\n", peak, tPeak);
  // Between the Rayleigh wave from the far corner (t = l sqrt2 c_s / c_R = 0.769) and t = 1 the
  // step response at the centre is static, so the velocity there is the Boussinesq settlement
  // 3 l ln(1 + sqrt2) / (pi mu) = 0.420825: the peak (the prototype's "about 0.421").
  const double settlement = 3 * 0.5 * std::log(1 + std::sqrt(2.0)) / M_PI;
  EXPECT_NEAR(load.velocity(0, 0, 0.9), settlement, 1e-12);
  EXPECT_NEAR(load.velocity(0, 0, 1.9), -settlement, 1e-12);
  EXPECT_NEAR(peak, settlement, 1e-12);
}
