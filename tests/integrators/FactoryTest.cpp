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
