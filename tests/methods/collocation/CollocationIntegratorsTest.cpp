// The collocation studies' integrator choice: newmark is the implicit constrained solve only with
// beta > 0 (beta = 0 is the explicit central difference), and any other name is refused by key.

#include "core/Error.hpp"
#include "methods/collocation/CollocationIntegrators.hpp"
#include "methods/collocation/CollocationNewmark.hpp"

#include <gtest/gtest.h>

namespace mfwave {
namespace {

TEST(CollocationIntegrators, NewmarkIsImplicitOnlyWithPositiveBeta) {
  IntegratorOptions options;
  options.newmarkBeta = 0.25;
  const auto implicit = makeCollocationIntegrator("newmark", options);
  EXPECT_NE(dynamic_cast<CollocationNewmark*>(implicit.get()), nullptr);
  options.newmarkBeta = 0;
  const auto explicitNewmark = makeCollocationIntegrator("newmark", options);
  EXPECT_EQ(explicitNewmark->name(), "central_difference");
  EXPECT_EQ(makeCollocationIntegrator("central_difference", options)->name(), "central_difference");
  EXPECT_EQ(collocationIntegratorNames(), (std::vector<std::string>{"central_difference", "newmark"}));
}

TEST(CollocationIntegrators, OtherNamesAreRefusedByKey) {
  try {
    makeCollocationIntegrator("leapfrog", IntegratorOptions());
    FAIL() << "leapfrog accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.name");
    EXPECT_NE(std::string(e.what()).find("leapfrog"), std::string::npos);
  }
}

}  // namespace
}  // namespace mfwave
