#include "core/Error.hpp"
#include "core/Material.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace mfwave;

TEST(Material, LameAndYoungAgree) {
  const Material m = Material::fromYoung(2e6, 0.3975, 1000);
  const Material back = Material::fromLame(m.lambda(), m.mu(), m.density());
  EXPECT_NEAR(back.youngsModulus(), 2e6, 1e-6);
  EXPECT_NEAR(back.poissonRatio(), 0.3975, 1e-14);
  EXPECT_NEAR(m.mu(), 2e6 / (2 * 1.3975), 1e-8);
}

TEST(Material, WaveSpeedsOfThePoissonSolid) {
  // lambda = mu = rho = 1: nu = 1/4, c_p = sqrt(3), c_s = 1, and the Rayleigh speed of a Poisson
  // solid is c_s * sqrt(2 - 2/sqrt(3)) (Rayleigh's closed form for nu = 1/4).
  const Material m = Material::fromLame(1, 1, 1);
  EXPECT_DOUBLE_EQ(m.poissonRatio(), 0.25);
  EXPECT_NEAR(m.pWaveSpeed(), std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(m.sWaveSpeed(), 1.0, 1e-15);
  EXPECT_NEAR(m.rayleighSpeed(), std::sqrt(2 - 2 / std::sqrt(3.0)), 1e-12);
  EXPECT_NEAR(m.barSpeed(), std::sqrt(2.5), 1e-14);  // E = 2.5 for lambda = mu = 1
}

TEST(Material, RayleighSpeedApproximation) {
  // Viktorov's approximation c_R / c_s ~ (0.87 + 1.12 nu) / (1 + nu) is good to about 0.5 %.
  for (double nu : {0.0, 0.1, 0.2, 0.3, 0.4, 0.45}) {
    const Material m = Material::fromYoung(1, nu, 1);
    EXPECT_NEAR(m.rayleighSpeed() / m.sWaveSpeed(), (0.87 + 1.12 * nu) / (1 + nu), 5e-3) << "nu = " << nu;
  }
}

TEST(Material, RejectsNonPhysicalInputNamingTheKey) {
  auto expectKey = [](auto make, const std::string& key) {
    try {
      make();
      FAIL() << "expected an InputError for " << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key);
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos);
    }
  };
  expectKey([] { Material::fromYoung(1, 0.5, 1); }, "poisson_ratio");
  expectKey([] { Material::fromYoung(1, 0.7, 1); }, "poisson_ratio");
  expectKey([] { Material::fromYoung(1, -1.0, 1); }, "poisson_ratio");
  expectKey([] { Material::fromYoung(-1, 0.3, 1); }, "youngs_modulus");
  expectKey([] { Material::fromYoung(1, 0.3, 0); }, "density");
  expectKey([] { Material::fromLame(1, -1, 1); }, "mu");
  expectKey([] { Material::fromLame(-1, 1, 1); }, "lambda");
  expectKey([] { Material::fromLame(1, 1, std::nan("")); }, "density");
}
