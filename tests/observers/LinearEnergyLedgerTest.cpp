#include "core/Error.hpp"
#include "core/TimeFunction.hpp"
#include "integrators/CentralDifference.hpp"
#include "observers/LinearEnergyLedger.hpp"
#include "observers/TimeLoop.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace mfwave;

namespace {

SparseMatrix fromTriplets(Index n, const std::vector<Eigen::Triplet<Real>>& entries) {
  SparseMatrix m(n, n);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

// A free chain of n unit masses and unit springs, a dashpot c on the last mass, and a triangle
// load (0 to 2 s) on the first: symmetric K, passive C.
LinearSecondOrderSystem chain(int n, Real c, const TimeFunction& load) {
  std::vector<Eigen::Triplet<Real>> k, m;
  for (int i = 0; i < n; ++i) m.emplace_back(i, i, 1);
  for (int i = 0; i + 1 < n; ++i) {
    k.emplace_back(i, i, 1);
    k.emplace_back(i + 1, i + 1, 1);
    k.emplace_back(i, i + 1, -1);
    k.emplace_back(i + 1, i, -1);
  }
  LinearSecondOrderSystem system(fromTriplets(n, m), fromTriplets(n, {{n - 1, n - 1, c}}), fromTriplets(n, k));
  system.setForce([&load](Real t, Vector& f) { f[0] += load(t); });
  return system;
}

struct LedgerRun {
  Real drift, finalFraction;
  std::string growth;
};

LedgerRun runChain(Real dt, Real endTime) {
  const TimeFunction load = TimeFunction::triangle(0, 1, 1);
  LinearSecondOrderSystem system = chain(20, 0.5, load);
  LinearEnergyLedgerOptions options;
  options.quietAfter = load.quietAfter();
  options.checkEvery = 1;
  LinearEnergyLedger ledger(system, options);
  CentralDifference integrator;
  integrator.initialise(system, 0, Vector::Zero(20), Vector::Zero(20), dt);
  TimeLoop loop;
  loop.add(ledger);
  loop.run(integrator, endTime);
  return {ledger.largestBalanceDrift(), ledger.finalEnergyFraction(), ledger.growthMessage()};
}

}  // namespace

TEST(LinearEnergyLedger, BalanceOfASymmetricDampedChainClosesAtSecondOrder) {
  // Load work = kinetic + strain + dashpot loss, to the integrator's O(dt^2) error.
  const LedgerRun coarse = runChain(0.1, 60), fine = runChain(0.05, 60);
  EXPECT_LT(coarse.drift, 1e-2);
  EXPECT_GT(coarse.drift, 1e-5);  // a real, measured error: not identically zero
  EXPECT_NEAR(coarse.drift / fine.drift, 4, 0.8);
  // The dashpot drains the chain after the load: energy falls, nothing is flagged.
  EXPECT_LT(coarse.finalFraction, 0.5);
  EXPECT_TRUE(coarse.growth.empty());
}

TEST(LinearEnergyLedger, GrowthAfterTheLoadsEndedStopsTheRunNamingStepTimeAndParticle) {
  // K = [[1, a], [-a, 1]]: eigenvalues 1 -+ i a, a mode growing like exp(a t / 2) in amplitude.
  const Real a = 0.2;
  const TimeFunction load = TimeFunction::triangle(0, 1, 1);
  LinearSecondOrderSystem system(fromTriplets(2, {{0, 0, 1}, {1, 1, 1}}), SparseMatrix(),
                                 fromTriplets(2, {{0, 0, 1}, {0, 1, a}, {1, 0, -a}, {1, 1, 1}}));
  system.setForce([&load](Real t, Vector& f) { f[0] += load(t); });
  for (const bool stop : {true, false}) {
    LinearEnergyLedgerOptions options;
    options.quietAfter = load.quietAfter();
    options.balanceLimit = 0;  // judge the growth alone
    options.likelyCause = "the test's non-symmetric K";
    options.stop = stop;
    LinearEnergyLedger ledger(system, options);
    CentralDifference integrator;
    integrator.initialise(system, 0, Vector::Zero(2), Vector::Zero(2), 0.05);
    TimeLoop loop;
    loop.add(ledger);
    if (stop) {
      try {
        loop.run(integrator, 200);
        FAIL() << "the growing mode was not stopped";
      } catch (const InstabilityError& e) {
        // energy x 100 = amplitude x 10 at rate a / 2: about ln(10) / 0.1 = 23 s after the minimum
        EXPECT_GT(e.time(), 15);
        EXPECT_LT(e.time(), 60);
        EXPECT_GT(e.step(), 0);
        const std::string what = e.what();
        EXPECT_NE(what.find("grew after the loads ended"), std::string::npos) << what;
        // the measured rate, near Im sqrt(1 + 0.2 i) = 0.099
        const std::size_t at = what.find("growth rate ");
        ASSERT_NE(at, std::string::npos) << what;
        const Real rate = std::stod(what.substr(at + 12));
        EXPECT_GT(rate, 0.085);
        EXPECT_LT(rate, 0.11);
        EXPECT_NE(what.find("the test's non-symmetric K"), std::string::npos) << what;
      }
    } else {
      loop.run(integrator, 60);
      EXPECT_NE(ledger.growthMessage().find("grew after the loads ended"), std::string::npos);
      EXPECT_GT(ledger.finalEnergyFraction(), 0.99);  // still growing at the end
    }
  }
}

TEST(LinearEnergyLedger, RejectsMeaninglessOptions) {
  LinearSecondOrderSystem system(fromTriplets(1, {{0, 0, 1}}), SparseMatrix(), fromTriplets(1, {{0, 0, 1}}));
  LinearEnergyLedgerOptions options;
  options.growthFactor = 1;
  EXPECT_THROW(LinearEnergyLedger(system, options), InputError);
  options = {};
  options.checkEvery = 0;
  EXPECT_THROW(LinearEnergyLedger(system, options), InputError);
}
