#include "wiring/UpdatedLagrangianSphSpec.hpp"

#include "io/scene/Format.hpp"
#include "kernels/KernelFactory.hpp"

namespace mfwave {

void addUpdatedLagrangianSphViscosityKeys(SceneSchema& schema, const UpdatedLagrangianSphKeyDefaults& defaults) {
  using T = ValueType;
  const std::string when = "name = updated_lagrangian_sph";
  schema.add("method.viscosity_alpha", T::Number).withUnit("-").defaultsTo(scene::tomlNumber(defaults.viscosityAlpha))
      .nonNegative().when(when)
      .describedAs("Monaghan artificial viscosity, linear term alpha (approaching pairs only)" + defaults.alphaNote);
  schema.add("method.viscosity_beta", T::Number).withUnit("-").defaultsTo(scene::tomlNumber(defaults.viscosityBeta))
      .nonNegative().when(when).describedAs("Monaghan artificial viscosity, quadratic term beta");
  schema.add("method.kernel_gradient_correction", T::Boolean)
      .defaultsTo(defaults.kernelGradientCorrection ? "true" : "false").when(when)
      .describedAs("correct grad W so linear velocity fields give exact strain rates (also at free surfaces)");
}

UpdatedLagrangianSphKeyDefaults smallAmplitudeWaveDefaults() {
  UpdatedLagrangianSphKeyDefaults d;
  d.viscosityAlpha = 1;
  d.kernelGradientCorrection = true;
  d.alphaNote = "; 1 in the Lamb study, measured best on lamb2d.toml (0 and 0.1 ring, 2 is no better)";
  return d;
}

UpdatedLagrangianSphOptions smallAmplitudeWaveOptions(const Material& material) {
  UpdatedLagrangianSphOptions options;
  options.material = material;
  const UpdatedLagrangianSphKeyDefaults keys = smallAmplitudeWaveDefaults();
  options.viscosity.alpha = keys.viscosityAlpha;
  options.viscosity.beta = keys.viscosityBeta;
  options.kernelGradientCorrection = keys.kernelGradientCorrection;
  return options;
}

void addUpdatedLagrangianSphKeys(SceneSchema& schema) {
  using T = ValueType;
  const std::string when = "name = updated_lagrangian_sph";
  schema.addChoice("method.name", "updated_lagrangian_sph");
  schema.add("method.kernel", T::String).defaultsTo("\"cubic_spline\"").oneOf(kernelNames()).when(when)
      .describedAs("SPH kernel W");
  schema.add("method.smoothing_length_ratio", T::Number).withUnit("-").defaultsTo("1.3").positive().when(when)
      .describedAs("smoothing length h / initial particle spacing dp");
  schema.add("method.gamma", T::Number).withUnit("-").defaultsTo("1.0").atLeast(1).when(when)
      .describedAs("stiffened-gas EOS p = c0^2 (rho - rho0) + (gamma - 1) rho e, c0 = sqrt(K / rho0); 1: isothermal");
  schema.add("method.density", T::String).defaultsTo("\"continuity\"").oneOf({"continuity", "summation"}).when(when)
      .describedAs("density from the continuity equation, or by summation (loses support at free surfaces)");
  addUpdatedLagrangianSphViscosityKeys(schema, {});
  schema.add("method.viscosity_eta", T::Number).withUnit("-").defaultsTo("0.1").positive().when(when)
      .describedAs("eta in mu_ij = h v_ij.x_ij / (|x_ij|^2 + eta^2 h^2): keeps mu finite for close pairs");
  schema.add("method.artificial_stress", T::Boolean).defaultsTo("false").when(when)
      .describedAs("Monaghan-Gray artificial stress against the tensile instability");
  schema.add("method.artificial_stress_epsilon", T::Number).withUnit("-").defaultsTo("0.3").nonNegative().when(when)
      .describedAs("artificial stress factor: R = -epsilon sigma' / rho^2 on tensile principal stresses");
  schema.add("method.artificial_stress_exponent", T::Number).withUnit("-").defaultsTo("4.0").positive().when(when)
      .describedAs("n in f_ij^n, f_ij = W(r_ij) / W(dp)");
  schema.add("method.artificial_stress_spacing", T::Number).withUnit("m").defaultsTo("0.0").nonNegative().when(when)
      .describedAs("dp in f_ij = W(r_ij) / W(dp); 0: the initial particle spacing (volume^(1/D))");
  schema.add("method.xsph", T::Number).withUnit("-").defaultsTo("0.0").between(0, 1).when(when)
      .describedAs("XSPH epsilon: dx/dt = v + epsilon sum_j m_j / rhobar_ij (v_j - v_i) W_ij; 0 is off");
  schema.add("method.neighbour_skin", T::Number).withUnit("-").defaultsTo("0.2").nonNegative().when(when)
      .describedAs("neighbour lists reach (1 + skin) times the support; rebuilt when a particle moved skin/2 of it");
  schema.add("method.courant", T::Number).withUnit("-").defaultsTo("0.3").positive().when(when)
      .describedAs("CFL criterion dt <= courant h / (c + 1.2 (alpha c + beta max mu))");
  schema.add("method.force_factor", T::Number).withUnit("-").defaultsTo("0.25").positive().when(when)
      .describedAs("force criterion dt <= force_factor sqrt(h / max |a|)");
  schema.add("method.body_force", T::NumberArray).withUnit("m/s^2").defaultsToNote("zeros").when(when)
      .describedAs("body force per unit mass g: one entry per axis, or 3 (the entries beyond the dimension 0)");
}

UpdatedLagrangianSphOptions readUpdatedLagrangianSph(SceneReader& reader, const Material& material) {
  const int dimension = static_cast<int>(reader.integer("scene.dimension"));
  const SceneTable method = reader.section("method");
  UpdatedLagrangianSphOptions o;
  o.material = material;
  o.kernel = method.string("kernel");
  o.smoothingLengthRatio = method.number("smoothing_length_ratio");
  o.gamma = method.number("gamma");
  o.density = method.string("density") == "summation" ? DensityUpdate::Summation : DensityUpdate::Continuity;
  o.viscosity.alpha = method.number("viscosity_alpha");
  o.viscosity.beta = method.number("viscosity_beta");
  o.viscosity.eta = method.number("viscosity_eta");
  o.artificialStress.enabled = method.boolean("artificial_stress");
  o.artificialStress.epsilon = method.number("artificial_stress_epsilon");
  o.artificialStress.exponent = method.number("artificial_stress_exponent");
  o.artificialStress.referenceSpacing = method.number("artificial_stress_spacing");
  o.kernelGradientCorrection = method.boolean("kernel_gradient_correction");
  o.xsph = method.number("xsph");
  o.neighbourSkin = method.number("neighbour_skin");
  o.courant = method.number("courant");
  o.forceFactor = method.number("force_factor");

  const std::string bodyForce = method.path("body_force");
  const std::vector<Real> g =
      reader.numbers(bodyForce, 0, std::vector<Real>(static_cast<std::size_t>(dimension), 0.0));
  if (g.size() != static_cast<std::size_t>(dimension) && g.size() != 3)
    reader.fail(bodyForce, "has " + std::to_string(g.size()) + " entries; give " + std::to_string(dimension) +
                               " (one per axis) or 3");
  for (std::size_t a = 0; a < g.size(); ++a) {
    if (static_cast<int>(a) >= dimension && g[a] != 0)
      reader.fail(bodyForce, "entry " + std::to_string(a + 1) + " is " + scene::formatNumber(g[a]) +
                                 " but the scene is " + std::to_string(dimension) +
                                 "-D: entries beyond the dimension must be 0");
    o.bodyForce[a] = g[a];
  }
  return o;
}

}  // namespace mfwave
