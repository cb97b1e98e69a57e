// [method] of the updated-Lagrangian SPH and [integrator] of first-order drivers: the scene's
// defaults are the options struct's defaults, every key reaches its option, the body force takes
// one entry per axis or 3, and the first-order integrator names replace the second-order ones.

#include "SceneTestSupport.hpp"

#include "integrators/FirstOrderIntegratorFactory.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/Scene.hpp"
#include "wiring/UpdatedLagrangianSphSpec.hpp"
#include "wiring/VeryWeakSphSpec.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace mfwave {
namespace {

using testing::sceneErrorOf;

const std::string kPlate = R"(
[scene]
name = "plate"
dimension = 2
[geometry]
shape = "rectangle"
lower = [0.0, 0.0]
upper = [0.2, 0.02]
spacing = 0.002
[material]
density = 1000.0
youngs_modulus = 2.0e6
poisson_ratio = 0.3975
[method]
name = "updated_lagrangian_sph"
)";

SceneSchema ulSchema() {
  SceneSchema schema = SceneSchema::common();
  addUpdatedLagrangianSphKeys(schema);
  useFirstOrderIntegrators(schema);
  return schema;
}

struct Read {
  Scene scene;
  UpdatedLagrangianSphOptions options;
  IntegratorSpec integrator;
  std::string resolved;
};

// The plate scene with extra [method] lines and an [integrator] section, read as a driver reads it.
Read readPlate(const std::string& methodLines, const std::string& integrator = "end_time = 1.0\n") {
  SceneReader reader =
      parseScene(kPlate + methodLines + "\n[integrator]\n" + integrator, "plate.toml", {}, ulSchema());
  Read r;
  r.scene = readScene(reader);
  r.options = readUpdatedLagrangianSph(reader, r.scene.material.material());
  r.integrator = readFirstOrderIntegrator(reader);
  reader.checkAllKeysRead();
  r.resolved = reader.resolvedToml();
  return r;
}

TEST(UpdatedLagrangianSphSpec, DefaultsAreTheOptionsDefaults) {
  const Read r = readPlate("");
  const UpdatedLagrangianSphOptions& o = r.options;
  const UpdatedLagrangianSphOptions d;
  EXPECT_EQ(o.kernel, d.kernel);
  EXPECT_EQ(o.smoothingLengthRatio, d.smoothingLengthRatio);
  EXPECT_EQ(o.gamma, d.gamma);
  EXPECT_EQ(o.density, d.density);
  EXPECT_EQ(o.viscosity.alpha, d.viscosity.alpha);
  EXPECT_EQ(o.viscosity.beta, d.viscosity.beta);
  EXPECT_EQ(o.viscosity.eta, d.viscosity.eta);
  EXPECT_EQ(o.artificialStress.enabled, d.artificialStress.enabled);
  EXPECT_EQ(o.artificialStress.epsilon, d.artificialStress.epsilon);
  EXPECT_EQ(o.artificialStress.exponent, d.artificialStress.exponent);
  EXPECT_EQ(o.artificialStress.referenceSpacing, d.artificialStress.referenceSpacing);
  EXPECT_EQ(o.xsph, d.xsph);
  EXPECT_EQ(o.kernelGradientCorrection, d.kernelGradientCorrection);
  EXPECT_EQ(o.bodyForce, d.bodyForce);
  EXPECT_EQ(o.neighbourSkin, d.neighbourSkin);
  EXPECT_EQ(o.courant, d.courant);
  EXPECT_EQ(o.forceFactor, d.forceFactor);
  // The material is the scene's: E = 2e6, nu = 0.3975.
  EXPECT_NEAR(o.material.youngsModulus(), 2e6, 1e-6);
  EXPECT_NEAR(o.material.poissonRatio(), 0.3975, 1e-12);
  EXPECT_EQ(o.material.density(), 1000);
  // Defaults land in the resolved scene; the body force with one entry per axis.
  EXPECT_NE(r.resolved.find("courant = 0.3"), std::string::npos) << r.resolved;
  EXPECT_NE(r.resolved.find("density = \"continuity\""), std::string::npos) << r.resolved;
  EXPECT_NE(r.resolved.find("body_force = [0.0, 0.0]"), std::string::npos) << r.resolved;
}

TEST(UpdatedLagrangianSphSpec, EveryKeyReachesItsOption) {
  const Read r = readPlate(R"(
kernel = "wendland_c2"
smoothing_length_ratio = 1.5
gamma = 1.4
density = "summation"
viscosity_alpha = 1.0
viscosity_beta = 2.0
viscosity_eta = 0.05
artificial_stress = true
artificial_stress_epsilon = 0.2
artificial_stress_exponent = 3.0
artificial_stress_spacing = 0.001
xsph = 0.5
kernel_gradient_correction = true
neighbour_skin = 0.3
courant = 0.4
force_factor = 0.2
body_force = [0.0, -9.81]
)");
  const UpdatedLagrangianSphOptions& o = r.options;
  EXPECT_EQ(o.kernel, "wendland_c2");
  EXPECT_EQ(o.smoothingLengthRatio, 1.5);
  EXPECT_EQ(o.gamma, 1.4);
  EXPECT_EQ(o.density, DensityUpdate::Summation);
  EXPECT_EQ(o.viscosity.alpha, 1.0);
  EXPECT_EQ(o.viscosity.beta, 2.0);
  EXPECT_EQ(o.viscosity.eta, 0.05);
  EXPECT_TRUE(o.artificialStress.enabled);
  EXPECT_EQ(o.artificialStress.epsilon, 0.2);
  EXPECT_EQ(o.artificialStress.exponent, 3.0);
  EXPECT_EQ(o.artificialStress.referenceSpacing, 0.001);
  EXPECT_EQ(o.xsph, 0.5);
  EXPECT_TRUE(o.kernelGradientCorrection);
  EXPECT_EQ(o.neighbourSkin, 0.3);
  EXPECT_EQ(o.courant, 0.4);
  EXPECT_EQ(o.forceFactor, 0.2);
  EXPECT_EQ(o.bodyForce, (std::array<Real, 3>{0, -9.81, 0}));
}

TEST(UpdatedLagrangianSphSpec, BodyForceTakesOneEntryPerAxisOrThree) {
  EXPECT_EQ(readPlate("body_force = [1.0, -9.81, 0.0]").options.bodyForce, (std::array<Real, 3>{1, -9.81, 0}));
  for (const char* bad : {"body_force = [1.0]", "body_force = [0.0, 0.0, 0.0, 0.0]", "body_force = [0.0, -9.81, 2.0]"})
    EXPECT_EQ(sceneErrorOf([&] { readPlate(bad); }).key(), "method.body_force") << bad;
  EXPECT_EQ(sceneErrorOf([&] { readPlate("body_force = [0.0, nan]"); }).key(), "method.body_force[1]");
}

TEST(UpdatedLagrangianSphSpec, RangesNameTheKey) {
  const struct {
    const char* line;
    const char* key;
  } cases[] = {{"courant = 0.0", "method.courant"},
               {"force_factor = -1.0", "method.force_factor"},
               {"gamma = 0.5", "method.gamma"},
               {"viscosity_eta = 0.0", "method.viscosity_eta"},
               {"viscosity_alpha = -0.1", "method.viscosity_alpha"},
               {"artificial_stress_exponent = 0.0", "method.artificial_stress_exponent"},
               {"artificial_stress_spacing = -0.001", "method.artificial_stress_spacing"},
               {"neighbour_skin = -0.1", "method.neighbour_skin"},
               {"smoothing_length_ratio = 0.0", "method.smoothing_length_ratio"},
               {"kernel = \"cubic\"", "method.kernel"},
               {"artificial_stress = 1", "method.artificial_stress"}};
  for (const auto& c : cases) EXPECT_EQ(sceneErrorOf([&] { readPlate(c.line); }).key(), c.key) << c.line;
}

TEST(UpdatedLagrangianSphSpec, SharesNoSchemaWithTheVeryWeakSph) {
  SceneSchema schema = SceneSchema::common();
  addVeryWeakSphKeys(schema);
  EXPECT_THROW(addUpdatedLagrangianSphKeys(schema), std::logic_error);
}

TEST(FirstOrderIntegratorSpec, NamesDefaultAndCfl) {
  const SceneSchema schema = ulSchema();
  EXPECT_TRUE(usesFirstOrderIntegrators(schema));
  EXPECT_FALSE(usesFirstOrderIntegrators(SceneSchema::common()));
  EXPECT_EQ(schema.at("integrator.name").choices, firstOrderIntegratorNames());

  const Read defaults = readPlate("");
  EXPECT_EQ(defaults.integrator.name, "leapfrog");
  EXPECT_EQ(defaults.integrator.cfl, 1.0);  // a factor on the method's own criteria
  EXPECT_FALSE(defaults.integrator.timeStep);
  EXPECT_EQ(defaults.integrator.endTime, 1.0);
  EXPECT_EQ(defaults.scene.integrator.name, "leapfrog");  // readScene reads the same

  EXPECT_EQ(defaults.integrator.kind, IntegratorKind::Leapfrog);
  for (const std::string& name : firstOrderIntegratorNames()) {
    const IntegratorSpec read = readPlate("", "name = \"" + name + "\"\nend_time = 1.0\n").integrator;
    EXPECT_EQ(read.name, name);
    EXPECT_EQ(read.kind, integratorKind(name));  // the name is typed once read
  }
  EXPECT_EQ(readPlate("", "name = \"predictor_corrector\"\nend_time = 1.0\n").integrator.kind,
            IntegratorKind::PredictorCorrector);
  const Read fixed = readPlate("", "name = \"predictor_corrector\"\nend_time = 1.0\ntime_step = 0.001\n");
  EXPECT_EQ(*fixed.integrator.timeStep, 0.001);
  const Read cfl = readPlate("", "end_time = 1.0\ncfl = 0.5\n");
  EXPECT_EQ(cfl.integrator.cfl, 0.5);
  const Read arkode =
      readPlate("", "name = \"arkode\"\nend_time = 1.0\narkode_table = \"heun_euler_2_1_2\"\narkode_adaptive = true\n");
  EXPECT_EQ(arkode.integrator.options.arkode.table, "heun_euler_2_1_2");
  EXPECT_TRUE(arkode.integrator.options.arkode.adaptive);

  EXPECT_EQ(sceneErrorOf([&] { readPlate("", "name = \"newmark\"\nend_time = 1.0\n"); }).key(), "integrator.name");
  EXPECT_EQ(sceneErrorOf([&] { readPlate("", "end_time = 1.0\narkode_table = \"classic_rk4\"\n"); }).key(),
            "integrator.arkode_table");
}

TEST(FirstOrderIntegratorSpec, SecondOrderSchemaIsRejected) {
  SceneSchema schema = SceneSchema::common();
  addUpdatedLagrangianSphKeys(schema);
  SceneReader reader = parseScene(kPlate + "[integrator]\nend_time = 1.0\n", "plate.toml", {}, schema);
  EXPECT_EQ(readScene(reader).integrator.cfl, 0.5);  // second-order default unchanged
  EXPECT_THROW(readFirstOrderIntegrator(reader), std::logic_error);
}

}  // namespace
}  // namespace mfwave
