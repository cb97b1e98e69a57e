// Bad input names its key; the initial state has the documented layout; a blown-up state is
// reported as an InstabilityError naming the particle, its position and the time.

#include "UlsphTestSupport.hpp"

#include "core/Error.hpp"
#include "particles/GhostLayers.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace mfwave;
using mfwave::testing::inputErrorKey;

namespace {

ParticleSet<2> square() { return makeLattice<2>(Vec2::Zero(), Vec2::Ones(), 0.25); }

std::string keyFor(void (*change)(UpdatedLagrangianSphOptions&)) {
  UpdatedLagrangianSphOptions options;
  change(options);
  return inputErrorKey([&] { UpdatedLagrangianSph<2> system(square(), options); });
}

}  // namespace

TEST(UlsphOptions, BadOptionsNameTheirKey) {
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.kernel = "tophat"; }), "method.kernel");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.smoothingLengthRatio = 0; }),
            "method.smoothing_length_ratio");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.smoothingLengthRatio = std::nan(""); }),
            "method.smoothing_length_ratio");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.gamma = 0.5; }), "method.gamma");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.density = static_cast<DensityUpdate>(7); }),
            "method.density");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.viscosity.alpha = -1; }), "method.viscosity_alpha");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.viscosity.beta = -1; }), "method.viscosity_beta");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.viscosity.eta = 0; }), "method.viscosity_eta");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) {
              o.artificialStress.enabled = true;
              o.artificialStress.epsilon = -0.1;
            }),
            "method.artificial_stress_epsilon");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) {
              o.artificialStress.enabled = true;
              o.artificialStress.exponent = 0;
            }),
            "method.artificial_stress_exponent");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) {
              o.artificialStress.enabled = true;
              o.artificialStress.referenceSpacing = 10;  // outside the support: W(dp) = 0
            }),
            "method.artificial_stress_spacing");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.xsph = 1.5; }), "method.xsph");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.bodyForce[1] = std::nan(""); }), "method.body_force");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.neighbourSkin = -0.1; }), "method.neighbour_skin");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.courant = 0; }), "method.courant");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions& o) { o.forceFactor = -1; }), "method.force_factor");
  EXPECT_EQ(keyFor([](UpdatedLagrangianSphOptions&) {}), "");  // the defaults are valid
}

TEST(UlsphOptions, GhostsEmptySetsAndBadConstraintsAreRejected) {
  ParticleSet<2> withGhosts = square();
  addGhostLayers<2>(withGhosts, Vec2::Zero(), Vec2::Ones(), 0.25, 1, 1);
  EXPECT_EQ(inputErrorKey([&] { UpdatedLagrangianSph<2> s(withGhosts, {}); }), "particles");
  EXPECT_EQ(inputErrorKey([&] { UpdatedLagrangianSph<2> s(ParticleSet<2>{}, {}); }), "particles");
  UpdatedLagrangianSph<2> system(square(), {});
  EXPECT_EQ(inputErrorKey([&] { system.fixParticles({0, 25}); }), "particles");
  EXPECT_EQ(inputErrorKey([&] { system.addTraction({0}, Vec2(1, 0), TimeFunction::constant(1), 0); }), "area");
  EXPECT_EQ(inputErrorKey([&] { system.initialState(Vector::Zero(3)); }), "velocity");
}

TEST(UlsphOptions, InitialStateHasTheDocumentedLayout) {
  const ParticleSet<2> set = square();
  UpdatedLagrangianSphOptions options;
  options.material = Material::fromLame(1, 1, 2.5);
  UpdatedLagrangianSph<2> system(set, options);
  const Index n = 25;
  ASSERT_EQ(system.particleCount(), n);
  EXPECT_EQ(system.size(), n * (2 + 1 + 3 + 2 + 1) + 3);
  EXPECT_EQ(system.configurationSize(), n * 6);
  EXPECT_NEAR(system.initialSpacing(), 0.25, 1e-15);
  EXPECT_NEAR(system.smoothingLength(), 1.3 * 0.25, 1e-15);
  EXPECT_NEAR(system.masses()[7], 2.5 * 0.0625, 1e-15);
  Vector v(2 * n);
  for (Index k = 0; k < 2 * n; ++k) v[k] = 0.1 * static_cast<Real>(k);
  system.prescribeVelocity({3}, Vec2(1, -2), TimeFunction::constant(0.5));
  system.fixParticles({4});
  const Vector y = system.initialState(v);
  const auto& layout = system.layout();
  EXPECT_EQ(y[layout.position(6, 1)], set.position(6)[1]);
  EXPECT_EQ(y[layout.density(6)], 2.5);
  EXPECT_EQ(y[layout.stress(6, 2)], 0.0);
  EXPECT_EQ(y[layout.velocity(6, 1)], v[13]);
  EXPECT_EQ(y[layout.velocity(3, 0)], 0.5);
  EXPECT_EQ(y[layout.velocity(3, 1)], -1.0);
  EXPECT_EQ(y[layout.velocity(4, 0)], 0.0);
  EXPECT_EQ(y[layout.energy(6)], 0.0);
  EXPECT_EQ(y.tail(3).norm(), 0.0);
  // Accessors: at rest p = 0 and sigma = s.
  EXPECT_EQ(system.pressure(y, 6), 0.0);
  EXPECT_EQ(system.stress(y, 6).norm(), 0.0);
}

TEST(UlsphOptions, NonFiniteStateIsAnInstabilityNamingParticleAndTime) {
  UpdatedLagrangianSph<2> system(square(), {});
  Vector y = system.initialState();
  y[system.layout().stress(12, 0)] = std::numeric_limits<Real>::infinity();
  Vector pdot(system.size() - system.configurationSize());
  try {
    system.momentumRate(1.5, y, pdot);
    FAIL() << "no InstabilityError";
  } catch (const InstabilityError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("non-finite acceleration at particle"), std::string::npos) << what;
    EXPECT_NE(what.find("(x = "), std::string::npos) << what;
    EXPECT_NE(what.find("t = 1.5"), std::string::npos) << what;
    EXPECT_EQ(e.time(), 1.5);
    EXPECT_GE(e.particle(), 0);
  }
  y = system.initialState();
  y[system.layout().velocity(12, 0)] = std::numeric_limits<Real>::quiet_NaN();
  Vector qdot(system.configurationSize());
  try {
    system.configurationRate(0.25, y, qdot);
    FAIL() << "no InstabilityError";
  } catch (const InstabilityError& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite stress rate at particle"), std::string::npos) << e.what();
  }
}
