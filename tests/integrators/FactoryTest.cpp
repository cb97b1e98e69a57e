#include "TestSystems.hpp"
#include "core/Error.hpp"
#include "integrators/FirstOrderIntegratorFactory.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "integrators/IntegratorKind.hpp"

#include <gtest/gtest.h>

using namespace mfwave;

TEST(IntegratorFactory, EveryNameConstructsAWorkingIntegrator) {
  auto system = test::oscillator(1.0, 0.1);
  for (const auto& name : secondOrderIntegratorNames()) {
    auto integrator = makeSecondOrderIntegrator(name);
    ASSERT_TRUE(integrator) << name;
    EXPECT_EQ(integrator->name(), name);
    integrator->initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), 0.01);
    integrator->advanceTo(1.0);
    EXPECT_NEAR(integrator->time(), 1.0, 1e-12) << name;
    const auto exact = test::oscillatorExact(1.0, 0.1, 1.0);
    EXPECT_NEAR(integrator->state().displacement[0], exact.u, 1e-4) << name;
  }
  EXPECT_EQ(secondOrderIntegratorNames().size(), 4u);
}

TEST(IntegratorFactory, SpecsInOneWordGiveNameAndOptions) {
  EXPECT_EQ(namedIntegrator("leapfrog").name, "leapfrog");
  const NamedIntegrator rk = namedIntegrator("arkode:classic_rk4");
  EXPECT_EQ(rk.name, "arkode");
  EXPECT_EQ(rk.options.arkode.table, "classic_rk4");
  EXPECT_DOUBLE_EQ(namedIntegrator("newmark:fox_goodwin").options.newmarkBeta, 1.0 / 12);
  EXPECT_DOUBLE_EQ(namedIntegrator("newmark:linear_acceleration").options.newmarkBeta, 1.0 / 6);
  const NamedIntegrator newmark = namedIntegrator("newmark:0.05");
  EXPECT_EQ(newmark.name, "newmark");
  EXPECT_DOUBLE_EQ(newmark.options.newmarkBeta, 0.05);
  EXPECT_DOUBLE_EQ(newmark.options.newmarkGamma, 0.5);
  EXPECT_DOUBLE_EQ(namedIntegrator("newmark").options.newmarkBeta, 0.25);
  for (const char* bad : {"euler", "newmark:", "newmark:0.1x", "newmark:-0.1", "arkode:nope", "leapfrog:1"}) {
    try {
      namedIntegrator(bad);
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key().rfind("integrator", 0), 0u) << bad << ": " << e.key();  // or integrator.table
    }
  }
}

TEST(IntegratorFactory, PassesOptionsThrough) {
  IntegratorOptions options;
  options.newmarkBeta = 0.7;
  try {
    makeSecondOrderIntegrator("newmark", options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "newmark.beta");
  }
  options = {};
  options.arkode.table = "nope";
  try {
    makeSecondOrderIntegrator("arkode", options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.table");
  }
}

TEST(IntegratorFactory, UnknownNameListsTheValidOnes) {
  try {
    makeSecondOrderIntegrator("euler");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator");
    const std::string what = e.what();
    EXPECT_NE(what.find("'euler'"), std::string::npos);
    EXPECT_NE(what.find("central_difference, leapfrog, newmark, arkode"), std::string::npos);
  }
}

TEST(IntegratorKind, EveryOfferedNameHasAKindAndBackAndNoOtherNameHasOne) {
  for (const auto& names : {secondOrderIntegratorNames(), firstOrderIntegratorNames()})
    for (const auto& name : names) EXPECT_EQ(integratorName(integratorKind(name)), name);
  EXPECT_EQ(integratorKind("central_difference"), IntegratorKind::CentralDifference);
  EXPECT_EQ(integratorKind("newmark"), IntegratorKind::Newmark);
  EXPECT_NE(integratorKind("leapfrog"), integratorKind("central_difference"));
  try {
    integratorKind("verlet");
    FAIL() << "an unknown name has no kind";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.name");
    EXPECT_NE(std::string(e.what()).find("verlet"), std::string::npos);
  }
}
