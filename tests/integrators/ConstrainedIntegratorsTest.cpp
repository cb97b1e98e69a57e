// A constrained system's integrator choice (the collocation studies'): newmark is the implicit
// constrained solve only with beta > 0 (beta = 0 is the explicit central difference), and any
// other name is refused by key.

#include "core/Error.hpp"
#include "integrators/ConstrainedIntegrators.hpp"
#include "integrators/ConstrainedNewmark.hpp"

#include <gtest/gtest.h>

namespace mfwave {
namespace {

TEST(ConstrainedIntegrators, NewmarkIsImplicitOnlyWithPositiveBeta) {
  IntegratorOptions options;
  options.newmarkBeta = 0.25;
  const auto implicit = makeConstrainedIntegrator("newmark", options);
  EXPECT_NE(dynamic_cast<ConstrainedNewmark*>(implicit.get()), nullptr);
  options.newmarkBeta = 0;
  const auto explicitNewmark = makeConstrainedIntegrator("newmark", options);
  EXPECT_EQ(explicitNewmark->name(), "central_difference");
  EXPECT_EQ(makeConstrainedIntegrator("central_difference", options)->name(), "central_difference");
  EXPECT_EQ(constrainedIntegratorNames(), (std::vector<std::string>{"central_difference", "newmark"}));
}

TEST(ConstrainedIntegrators, OtherNamesAreRefusedByKey) {
  try {
    makeConstrainedIntegrator("leapfrog", IntegratorOptions());
    FAIL() << "leapfrog accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.name");
    EXPECT_NE(std::string(e.what()).find("leapfrog"), std::string::npos);
  }
}

}  // namespace
}  // namespace mfwave
