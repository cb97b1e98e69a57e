#pragma once
// Shared test fixtures: every (kernel name, dimension) pair, and facts about each profile written
// down independently of lib/kernels (piece boundaries, f''(0)) so the tests can check the library.

#include "core/Types.hpp"

#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

namespace mfwave::test {

using KernelCase = std::tuple<std::string, int>;  // (factory name, dimension)

inline std::vector<std::string> allKernelNames() {
  return {"cubic_spline", "gaussian", "quintic_spline", "wendland_c2", "wendland_c4", "cubic_b_spline"};
}

inline auto allKernelCases() {
  return ::testing::Combine(::testing::ValuesIn(allKernelNames()), ::testing::Values(1, 2, 3));
}

inline std::string caseName(const ::testing::TestParamInfo<KernelCase>& info) {
  return std::get<0>(info.param) + "_" + std::to_string(std::get<1>(info.param)) + "d";
}

// Boundaries of the smooth pieces of f, in units of the kernel's length parameter.
inline std::vector<Real> pieceBoundaries(const std::string& name) {
  if (name == "cubic_spline") return {0.0, 1.0, 2.0};
  if (name == "quintic_spline") return {0.0, 1.0, 2.0, 3.0};
  if (name == "wendland_c2" || name == "wendland_c4") return {0.0, 2.0};
  if (name == "cubic_b_spline") return {0.0, 0.5, 1.0};
  return {0.0, 3.0};  // gaussian
}

// f''(0), worked out by hand from the profile formulas.
inline Real profileCurvatureAtZero(const std::string& name, int dimension) {
  if (name == "cubic_spline") return -3.0;
  if (name == "quintic_spline") return -120.0;
  if (name == "wendland_c2") return dimension == 1 ? -3.0 : -5.0;
  if (name == "wendland_c4") return dimension == 1 ? -3.5 : -14.0 / 3.0;
  if (name == "cubic_b_spline") return -8.0;
  return -2.0;  // gaussian
}

}  // namespace mfwave::test
