// Observed order of accuracy of every integrator on oscillators with exact solutions.

#include "TestSystems.hpp"
#include "integrators/ArkodeSecondOrder.hpp"
#include "integrators/CentralDifference.hpp"
#include "integrators/Leapfrog.hpp"
#include "integrators/Newmark.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

using Factory = std::function<std::unique_ptr<SecondOrderIntegrator>()>;

struct Case {
  std::string name;
  Factory make;
  double expectedOrder;
  int coarsestSteps;  // steps over the interval on the coarsest grid
};

constexpr Real kOmega = 2 * M_PI;  // period 1
constexpr Real kEndTime = 2.0;

// Error at kEndTime, max of |u - u_exact| and |v - v_exact| / w.
Real errorAt(const Case& c, Real zeta, int steps) {
  auto system = test::oscillator(kOmega, zeta);
  auto integrator = c.make();
  Vector u0(1), v0(1);
  u0 << 1;
  v0 << 0;
  const Real dt = kEndTime / steps;
  integrator->initialise(*system, 0, u0, v0, dt);
  for (int i = 0; i < steps; ++i) integrator->step();
  EXPECT_NEAR(integrator->time(), kEndTime, 1e-12);
  const auto exact = test::oscillatorExact(kOmega, zeta, kEndTime);
  const auto state = integrator->state();
  return std::max(std::abs(state.displacement[0] - exact.u), std::abs(state.velocity[0] - exact.v) / kOmega);
}

std::vector<Real> observedOrders(const Case& c, Real zeta) {
  std::vector<Real> errors;
  for (int level = 0; level < 4; ++level) errors.push_back(errorAt(c, zeta, c.coarsestSteps << level));
  std::vector<Real> orders;
  for (size_t i = 1; i < errors.size(); ++i) orders.push_back(std::log2(errors[i - 1] / errors[i]));
  std::string line = c.name + " zeta=" + std::to_string(zeta) + " errors:";
  for (Real e : errors) line += " " + std::to_string(e);
  line += " orders:";
  for (Real p : orders) line += " " + std::to_string(p);
  std::printf("%s\n", line.c_str());
  return orders;
}

std::vector<Case> cases() {
  auto arkode = [](const std::string& table) {
    return [table]() {
      ArkodeOptions options;
      options.table = table;
      return std::make_unique<ArkodeSecondOrder>(options);
    };
  };
  return {
      {"central_difference", [] { return std::make_unique<CentralDifference>(); }, 2, 40},
      {"leapfrog", [] { return std::make_unique<Leapfrog>(); }, 2, 40},
      {"newmark_average", [] { return std::make_unique<Newmark>(0.25, 0.5); }, 2, 40},
      {"newmark_linear", [] { return std::make_unique<Newmark>(1.0 / 6, 0.5); }, 2, 40},
      {"newmark_gamma_0.6", [] { return std::make_unique<Newmark>(0.3025, 0.6); }, 1, 80},
      {"arkode_classic_rk4", arkode("classic_rk4"), 4, 20},
      {"arkode_heun_euler", arkode("heun_euler_2_1_2"), 2, 80},
  };
}

class Convergence : public ::testing::TestWithParam<Real> {};

TEST_P(Convergence, EveryIntegratorReachesItsOrder) {
  const Real zeta = GetParam();
  for (const auto& c : cases()) {
    SCOPED_TRACE(c.name);
    const auto orders = observedOrders(c, zeta);
    // The last two halvings are in the asymptotic range.
    EXPECT_NEAR(orders[1], c.expectedOrder, 0.15);
    EXPECT_NEAR(orders[2], c.expectedOrder, 0.15);
  }
}

INSTANTIATE_TEST_SUITE_P(Oscillators, Convergence, ::testing::Values(0.0, 0.1),
                         [](const ::testing::TestParamInfo<Real>& param) {
                           return param.param == 0 ? std::string("Undamped") : std::string("Damped");
                         });

}  // namespace
