#include "analytic/PekerisPointLoad.hpp"
#include "core/Error.hpp"
#include "core/Material.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace mfwave;

namespace {
const double kS3 = std::sqrt(3.0);
const double kG = PekerisPointLoad::kRayleighTau;

// Gauss-Legendre (5 points) on n panels of [a, b], each mapped by a smoothstep so that square-root
// endpoint singularities of f are integrated accurately.
double integrate(const std::function<double(double)>& f, double a, double b, int n) {
  const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831,
                       0.9061798459386640};
  const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                       0.4786286704993665, 0.2369268850561891};
  double s = 0;
  for (int i = 0; i < 5; ++i) {
    const double u = 0.5 * (1 + x[i]);  // smoothstep over the whole interval, then panels in u
    for (int k = 0; k < n; ++k) {
      const double v = (k + u) / n;
      const double t = a + (b - a) * v * v * (3 - 2 * v);
      s += 0.5 * w[i] / n * (b - a) * 6 * v * (1 - v) * f(t);
    }
  }
  return s;
}
}  // namespace

TEST(PekerisPointLoad, RayleighRootsForPoissonRatioQuarter) {
  // Rationalised Rayleigh function in x = (c_s p)^2 for c_p^2 = 3 c_s^2.
  auto cubic = [](double x) { return 32 * x * x * x - 56 * x * x + 24 * x - 3; };
  for (double x : {0.25, (3 - kS3) / 4, (3 + kS3) / 4}) EXPECT_NEAR(cubic(x), 0, 1e-13) << x;
  // Only g^2 = (3 + sqrt3)/4 > 1 is a root of the unrationalised function (the Rayleigh pole).
  const double x = kG * kG;
  EXPECT_NEAR((2 * x - 1) * (2 * x - 1) - 4 * x * std::sqrt(x - 1.0 / 3) * std::sqrt(x - 1), 0,
              1e-13);
  EXPECT_NEAR(x, (3 + kS3) / 4, 1e-15);
  const Material m = Material::fromLame(1, 1, 1);
  EXPECT_NEAR(1 / kG, m.rayleighSpeed(), 1e-10);
  EXPECT_NEAR(1 / kG, std::sqrt(2 - 2 / kS3), 1e-15);
  const PekerisPointLoad load = PekerisPointLoad::fromMaterial(Material::fromLame(2, 2, 0.5));
  EXPECT_NEAR(load.rayleighSpeed(), Material::fromLame(2, 2, 0.5).rayleighSpeed(), 1e-9);
  EXPECT_NEAR(load.shearSpeed(), 2, 1e-15);
}

TEST(PekerisPointLoad, StaticLimitIsBoussinesq) {
  for (auto [mu, cs, P] : {std::tuple{1.0, 1.0, 1.0}, std::tuple{3.0, 2.0, -0.7}}) {
    const PekerisPointLoad load(mu, cs, P);
    for (double r : {0.1, 1.0, 7.5}) {
      const double boussinesq = 3 * P / (8 * M_PI * mu * r);  // P (1 - nu) / (2 pi mu r)
      EXPECT_NEAR(load.displacement(r, 1e3 * r / cs), boussinesq, 1e-10 * std::abs(boussinesq));
      EXPECT_NEAR(load.displacement(r, 1.0001 * load.rayleighArrival(r)), boussinesq,
                  1e-10 * std::abs(boussinesq));
    }
  }
}

TEST(PekerisPointLoad, ArrivalTimes) {
  const PekerisPointLoad load(1, 1, 1);
  const double r = 2;
  EXPECT_NEAR(load.pArrival(r), r / kS3, 1e-15);
  EXPECT_NEAR(load.sArrival(r), r, 1e-15);
  EXPECT_NEAR(load.rayleighArrival(r), r * kG, 1e-15);
  // Exactly zero up to the P arrival, continuous there (the bracket vanishes at tau = 1/sqrt3).
  for (double t : {0.0, 0.5, 1.0, 1.1547}) EXPECT_EQ(load.displacement(r, t), 0) << t;
  EXPECT_EQ(load.displacement(r, load.pArrival(r)), 0);
  EXPECT_NEAR(load.displacement(r, load.pArrival(r) * (1 + 1e-10)), 0, 1e-9);
  EXPECT_LT(load.displacement(r, load.pArrival(r) * 1.01), 0);  // first motion against the force
  // Continuous at the S arrival, with a change of slope (the P-S terms switch off).
  const double ts = load.sArrival(r), e = 1e-6;
  const double before = load.displacement(r, ts - e), after = load.displacement(r, ts + e);
  EXPECT_NEAR(before, after, 1e-5);
  const double slopeBefore = (before - load.displacement(r, ts - 2 * e)) / e;
  const double slopeAfter = (load.displacement(r, ts + 2 * e) - after) / e;
  EXPECT_GT(std::abs(slopeAfter - slopeBefore), 0.01);
  // Rayleigh arrival: -infinity like 1/sqrt(t_R - t) from before, the static value after.
  const double tr = load.rayleighArrival(r);
  const double a = load.displacement(r, tr * (1 - 1e-8)), b = load.displacement(r, tr * (1 - 4e-8));
  EXPECT_LT(a, -100);
  EXPECT_NEAR(a / b, 2, 1e-3);  // square-root singularity
  EXPECT_TRUE(std::isinf(load.displacement(r, tr)));
  EXPECT_NEAR(load.displacement(r, tr * (1 + 1e-12)), 3 / (8 * M_PI * r), 1e-14);
}

TEST(PekerisPointLoad, ClosedFormIntegralsMatchQuadrature) {
  auto G = [](double s) { return PekerisPointLoad::shape(s); };
  const double tp = 1 / kS3;
  for (double tau : {0.7, 0.95, 1.0, 1.05, kG, 1.3, 4.0}) {
    const double c1 = std::min(tau, 1.0), c2 = std::min(tau, kG);
    double m = integrate(G, tp, c1, 400);
    double h = integrate([&](double s) { return G(s) / (s * s); }, tp, c1, 400);
    if (tau > 1) {
      m += integrate(G, 1, c2, 400);
      h += integrate([&](double s) { return G(s) / (s * s); }, 1, c2, 400);
    }
    if (tau > kG) {
      m += 0.375 * (tau - kG);
      h += 0.375 * (1 / kG - 1 / tau);
    }
    EXPECT_NEAR(PekerisPointLoad::shapeIntegral(tau), m, 1e-10) << tau;
    EXPECT_NEAR(PekerisPointLoad::shapeOverTauSquaredIntegral(tau), h, 1e-10) << tau;
  }
  // Plane-wave limit: a uniform pressure on the whole surface, u = p t / (rho c_p), needs
  // H(infinity) = 1 / (2 sqrt3). An independent check of the whole closed form.
  EXPECT_NEAR(PekerisPointLoad::shapeOverTauSquaredIntegralAtInfinity(), 1 / (2 * kS3), 1e-14);
  EXPECT_NEAR(PekerisPointLoad::shapeOverTauSquaredIntegral(1e9), 1 / (2 * kS3), 1e-9);
}

// The Laplace transform of the step response equals the transform solution
//   wbar(r, s) = P / (2 pi mu c_s^2) int_0^inf p eta_a / D(p) J0(s p r) dp,
//   eta_a = sqrt(p^2 + 1/c_p^2), D = (2 p^2 + 1/c_s^2)^2 - 4 p^2 eta_a eta_b (no real zeros),
// an independent route to the same solution (mu = c_s = r = P = 1). (With mpmath, the two agree
// to 1e-12; here the Hankel integral is cut at p = 600 / s, which limits the agreement to ~3e-6.)
TEST(PekerisPointLoad, LaplaceTransformMatchesHankelIntegral) {
  for (double s : {0.5, 1.0, 2.0}) {
    // int_0^inf e^{-s tau} G d tau = s int_0^inf e^{-s tau} M(tau) d tau (M continuous).
    auto fm = [&](double tau) { return std::exp(-s * tau) * PekerisPointLoad::shapeIntegral(tau); };
    const double lhs = s / M_PI *
                       (integrate(fm, 1 / kS3, 1, 200) + integrate(fm, 1, kG, 200) +
                        integrate(fm, kG, kG + 80 / s, 2000));
    auto f = [&](double p) {
      const double ea = std::sqrt(p * p + 1.0 / 3), eb = std::sqrt(p * p + 1);
      const double d = (2 * p * p + 1) * (2 * p * p + 1) - 4 * p * p * ea * eb;
      return (p * ea / d - 0.75) * std::cyl_bessel_j(0.0, s * p);
    };
    const double pmax = 600 / s;
    double hankel = 0;
    const int panels = 12000;
    for (int k = 0; k < panels; ++k)
      hankel += integrate(f, pmax * k / panels, pmax * (k + 1) / panels, 1);
    const double rhs = (hankel + 0.75 / s) / (2 * M_PI);  // int_0^inf J0(s p) dp = 1 / s
    EXPECT_NEAR(lhs, rhs, 1e-5 * std::abs(rhs)) << s;  // truncation of the Hankel integral
  }
}

TEST(PekerisPointLoad, RejectsBadInput) {
  EXPECT_THROW(PekerisPointLoad(0, 1), InputError);
  EXPECT_THROW(PekerisPointLoad(1, -1), InputError);
  EXPECT_THROW(PekerisPointLoad::fromMaterial(Material::fromLame(2, 1, 1)), InputError);
  EXPECT_THROW(PekerisPointLoad(1, 1).displacement(0, 1), InputError);
}
