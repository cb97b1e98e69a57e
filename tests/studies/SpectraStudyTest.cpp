// The spectra tool run as a user runs it (small lattices): the finite-difference reference gives
// its closed-form points per wavelength, the simulated peaks follow the symbol plus the
// integrator's relation, and bad input is refused with the key named.

#include "support/StudyRun.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

mfwave::testing::StudyOutcome run(const std::string& arguments, const std::string& name) {
  return mfwave::testing::runStudy(SPECTRA_EXECUTABLE, std::string(SCENES_FOLDER) + "/spectra.toml", arguments,
                                   "spectra-" + name);
}

long lines(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  long count = 0;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') ++count;
  return count;
}

}  // namespace

TEST(SpectraStudy, SmallLatticesReproduceTheReferenceAndTheSimulationsAgree) {
  const fs::path out = fs::temp_directory_path() / "mfwave-spectra-small";
  fs::remove_all(out);
  const auto outcome = run("--out " + out.string() +
                               " --set 'study.dimensions=[1, 2]' --set study.cells_1d=128 --set study.cells_2d=64"
                               " --set simulation.cells=16 --set simulation.steps=512",
                           "small");
  ASSERT_EQ(outcome.exitCode, 0) << outcome.log;
  const auto figures = mfwave::testing::summaryNumbers(out / "summary.json");
  // sin(x/2)/(x/2) = 0.99 at 12.806 points per wavelength; the 2-D axis line samples |k| dx every
  // 2 pi / 64 and interpolates the error linearly between samples.
  EXPECT_NEAR(figures.at("finite_difference_2d_P_points_per_wavelength"), 12.806, 0.1);
  // The consistent very weak SPH and the corrected UL-SPH need about twice and three times as many
  // (23.75 and 33.0 on 128 cells; 24.02 and 33.17 here, the interpolation between coarser samples).
  EXPECT_NEAR(figures.at("vwsph_consistent_2d_P_points_per_wavelength"), 23.9, 0.4);
  EXPECT_NEAR(figures.at("ulsph_corrected_2d_P_points_per_wavelength"), 33.1, 0.4);
  // The Galerkin very weak SPH along the axis is the finite-difference line (Q1 with lumped mass):
  // 12.81 like the reference, for P and S.
  EXPECT_NEAR(figures.at("vwsph_galerkin_2d_P_points_per_wavelength"), 12.81, 0.1);
  EXPECT_NEAR(figures.at("vwsph_galerkin_2d_S_points_per_wavelength"), 12.81, 0.1);
  EXPECT_EQ(figures.count("vwsph_published_2d_P_points_per_wavelength"), 0u);  // never: NaN is left out
  EXPECT_GT(figures.at("simulated_peaks"), 100);  // 132
  EXPECT_LT(figures.at("simulation_largest_relative_error"), 1e-5);  // 1.6e-6
  // 1-D: 8 methods x 64 samples; 2-D: 7 methods (no rbcm) x 2 directions x 2 polarisations
  // (the scalar finite difference has one) x 16 samples.
  EXPECT_EQ(lines(out / "spectra.csv"), 1 + 8 * 64 + (6 * 4 + 2) * 32);
  EXPECT_GT(lines(out / "anisotropy.csv"), 1);
}

TEST(SpectraStudy, BadInputIsRefusedWithTheKeyNamed) {
  const auto odd = run("--out " + (fs::temp_directory_path() / "mfwave-spectra-bad").string() +
                           " --set study.cells_2d=33",
                       "odd");
  EXPECT_EQ(odd.exitCode, 2) << odd.log;
  EXPECT_NE(odd.log.find("study.cells_2d"), std::string::npos) << odd.log;
  const auto method = run("--set 'study.methods=[\"fem\"]'", "method");
  EXPECT_EQ(method.exitCode, 2) << method.log;
  EXPECT_NE(method.log.find("study.methods"), std::string::npos) << method.log;
  const auto fraction = run("--set simulation.step_fraction=1.5", "fraction");
  EXPECT_EQ(fraction.exitCode, 2) << fraction.log;
  EXPECT_NE(fraction.log.find("simulation.step_fraction"), std::string::npos) << fraction.log;
}
