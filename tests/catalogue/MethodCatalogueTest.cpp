// The catalogue: one entry per method, each complete, found by its one name.
#include "catalogue/MethodCatalogue.hpp"

#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <set>

namespace mfwave {
namespace {

TEST(MethodCatalogue, EveryMethodIsRegisteredOnceAndCompletely) {
  std::set<std::string> names;
  for (const MethodEntry& m : methodCatalogue()) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name << " registered twice";
    EXPECT_FALSE(m.title.empty()) << m.name;
    EXPECT_FALSE(m.supports.dimensions.empty()) << m.name;
    EXPECT_FALSE(m.supports.shapes.empty()) << m.name;
    EXPECT_FALSE(m.supports.integrators.empty()) << m.name;
    EXPECT_FALSE(m.programs.empty()) << m.name;
    EXPECT_FALSE(m.stepRule.empty()) << m.name;
    for (int d : m.supports.dimensions) {
      const std::size_t i = static_cast<std::size_t>(d - 1);
      EXPECT_GT(m.cost.bytesPerParticle[i] + m.cost.fillMiB[i], 0) << m.name << " in " << d << "-D has no measured memory";
      EXPECT_GT(m.cost.baseMiB[i], 0) << m.name << " in " << d << "-D has no measured base memory";
      EXPECT_GT(m.cost.particleStepsPerSecond[i], 0) << m.name << " in " << d << "-D has no measured rate";
    }
  }
  for (const char* name : {"finite_difference", "very_weak_sph", "reproducing_kernel", "radial_basis",
                           "spectral_element", "updated_lagrangian_sph", "total_lagrangian_sph"})
    EXPECT_EQ(names.count(name), 1u) << name;
}

TEST(MethodCatalogue, AnUnknownNameIsRefusedWithTheCatalogueAndTheClosestName) {
  EXPECT_EQ(findMethod("vwsph"), nullptr);
  try {
    methodNamed("very_weak_sp");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method.name");
    EXPECT_NE(std::string(e.what()).find("did you mean 'very_weak_sph'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("spectral_element"), std::string::npos) << e.what();
  }
}

TEST(MethodCatalogue, ASchemaHoldsTheMethodsOwnKeysAndEveryName) {
  const SceneSchema vw = catalogueSchema(methodNamed("very_weak_sph"));
  EXPECT_NE(vw.find("method.variant"), nullptr);
  EXPECT_EQ(vw.find("method.viscosity_alpha"), nullptr);  // the UL-SPH's, not this method's
  for (const std::string& name : methodNames()) {
    const auto& choices = vw.at("method.name").choices;
    EXPECT_NE(std::find(choices.begin(), choices.end(), name), choices.end()) << name;
  }
  // The first-order method reads first-order integrators.
  const SceneSchema ul = catalogueSchema(methodNamed("updated_lagrangian_sph"));
  EXPECT_EQ(ul.at("integrator.name").defaultLiteral, "\"leapfrog\"");
  EXPECT_NE(ul.find("method.viscosity_alpha"), nullptr);
}

}  // namespace
}  // namespace mfwave
