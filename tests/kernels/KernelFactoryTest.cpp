// makeKernel: every name builds the right kernel; bad input names its key.

#include "KernelCases.hpp"
#include "core/Error.hpp"
#include "kernels/KernelFactory.hpp"

#include <cmath>
#include <limits>

namespace mfwave {
namespace {

// Runs `build` and returns the InputError it throws (fails the test if it does not).
template <class F>
InputError inputErrorOf(F&& build) {
  try {
    build();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected InputError";
  return InputError("<none>", "no error thrown");
}

TEST(KernelFactory, BuildsEveryNamedKernel) {
  const struct {
    const char* name;
    Real supportFactor;
  } table[] = {{"cubic_spline", 2.0}, {"gaussian", 3.0},    {"quintic_spline", 3.0},
               {"wendland_c2", 2.0},  {"wendland_c4", 2.0}, {"cubic_b_spline", 1.0}};
  EXPECT_EQ(kernelNames(), test::allKernelNames());
  for (const auto& row : table) {
    for (int d = 1; d <= 3; ++d) {
      const auto kernel = makeKernel(row.name, d, 0.4);
      ASSERT_NE(kernel, nullptr);
      EXPECT_STREQ(kernel->name(), row.name);
      EXPECT_EQ(kernel->dimension(), d);
      EXPECT_DOUBLE_EQ(kernel->smoothingLength(), 0.4);
      EXPECT_DOUBLE_EQ(kernel->supportRadius(), row.supportFactor * 0.4) << row.name;
    }
  }
}

TEST(KernelFactory, UnknownNameListsTheValidOnes) {
  const InputError e = inputErrorOf([] { (void)makeKernel("x", 3, 1.0); });
  EXPECT_EQ(e.key(), "kernel");
  const std::string message = e.what();
  EXPECT_NE(message.find("unknown kernel 'x'"), std::string::npos) << message;
  for (const std::string& name : kernelNames()) EXPECT_NE(message.find(name), std::string::npos) << message;
}

TEST(KernelFactory, BadLengthNamesItsKey) {
  const Real bad[] = {0.0, -0.5, std::numeric_limits<Real>::quiet_NaN(), std::numeric_limits<Real>::infinity()};
  for (const Real h : bad) {
    for (const std::string& name : kernelNames()) {
      const InputError e = inputErrorOf([&] { (void)makeKernel(name, 2, h); });
      EXPECT_EQ(e.key(), name == "cubic_b_spline" ? "support_radius" : "smoothing_length") << name << ", h = " << h;
    }
  }
}

TEST(KernelFactory, BadDimensionNamesItsKey) {
  for (const int d : {0, 4, -1}) {
    for (const std::string& name : kernelNames()) {
      EXPECT_EQ(inputErrorOf([&] { (void)makeKernel(name, d, 1.0); }).key(), "dimension") << name << ", d = " << d;
    }
  }
}

}  // namespace
}  // namespace mfwave
