#include "wiring/VeryWeakSphSpec.hpp"

#include "kernels/KernelFactory.hpp"

namespace mfwave {

namespace {
// The condition of every option key: it also tells them apart in veryWeakSphOptionKeys.
const char* const kWhen = "name = very_weak_sph";
}  // namespace

void addVeryWeakSphKeys(SceneSchema& schema) {
  using T = ValueType;
  const std::string when = kWhen;
  schema.addChoice("method.name", "very_weak_sph");
  schema.add("method.variant", T::String).defaultsTo("\"galerkin\"").oneOf({"galerkin", "consistent", "published"}).when(when)
      .describedAs("galerkin: symmetric weak form with the lattice's tent kernel, stable without a filter (lattices "
                   "only; ignores method.kernel); consistent: rows corrected to reproduce quadratic fields, not "
                   "symmetric, grows in long 3-D runs without a filter; published: Ding-Long-Wu as printed");
  schema.add("method.kernel", T::String).defaultsTo("\"cubic_spline\"").oneOf(kernelNames()).when(when)
      .describedAs("SPH kernel W (Ding-Long-Wu use the cubic spline, eq. 38)");
  schema.add("method.smoothing_length_ratio", T::Number).withUnit("-").defaultsTo("1.0").positive().when(when)
      .describedAs("smoothing length h / geometry.spacing (the paper: h = dx)");
  schema.add("method.boundary_volume_correction", T::Boolean).defaultsTo("true").when(when)
      .describedAs("volume fractions FV of eqs. 24-25 (1/2, 1/4, 1/8 on faces, edges, corners)");
  schema.add("method.boundary_area_correction", T::Boolean).defaultsTo("true").when(when)
      .describedAs("area fractions FA of eqs. 26-27 (1/2 per facet at edges, 1/4 at corners)");
  schema.add("method.kernel_correction", T::Boolean).defaultsTo("true").when(when)
      .describedAs("boundary kernel correction alpha of eqs. 28-29 (a lumped mass rho / alpha)");
  schema.add("method.boundary_integral", T::Boolean).defaultsTo("true").when(when)
      .describedAs("the boundary integral of eq. 22 (Gamma terms)");
  schema.add("method.dashpot_lumping", T::String).defaultsTo("\"particle\"").oneOf({"particle", "consistent"})
      .when(when)
      .describedAs("transmitting dashpots: on the particle's own velocity (eq. 32) or through the traction sum");
  schema.add("method.smoothing_rate", T::Number).withUnit("1/s").defaultsTo("0.0").nonNegative().when(when)
      .describedAs("conservative smoothing of the velocity (eq. 33), per unit time: alpha = 1 - exp(-rate dt) per step");
  schema.add("method.smoothing_order", T::Integer).withUnit("-").defaultsTo("1").between(1, 2).when(when)
      .describedAs("1: eq. 33, v += alpha (S v - v); 2: v -= alpha (I - S)^2 v (spares resolved waves)");
  schema.add("method.smoothing_rate_scales_with_spacing", T::Boolean).defaultsTo("false").when(when)
      .describedAs("the rate is given at geometry.spacing and scales as 1 / dx in resolution studies");
  schema.add("method.operator", T::String).defaultsTo("\"auto\"").oneOf({"auto", "lattice", "sparse"}).when(when)
      .describedAs("operator storage: per-row-type stencils on the box lattice (nothing per particle), assembled "
                   "sparse matrices (any particles; the reference), or auto (the stencils where they can run the scene)");
  schema.add("method.deconvolution", T::Boolean).defaultsTo("false").when(when)
      .describedAs("report probe values sharpened by the deconvolution of eq. 35 (the raw values are kept too)");
}

std::vector<std::string> veryWeakSphOptionKeys(const SceneSchema& schema) {
  std::vector<std::string> keys;
  for (const KeySpec& key : schema.keys())
    if (key.condition == kWhen) keys.push_back(key.path);
  return keys;
}

VeryWeakSphSpec readVeryWeakSph(SceneReader& reader, const Material& material) {
  const SceneTable method = reader.section("method");
  VeryWeakSphSpec spec;
  const std::string variant = method.string("variant");  // one of the three (the schema's oneOf)
  spec.options.variant = variant == "galerkin"     ? VeryWeakSphVariant::Galerkin
                         : variant == "consistent" ? VeryWeakSphVariant::Consistent
                                                   : VeryWeakSphVariant::Published;
  spec.kernel = method.string("kernel");
  spec.smoothingLengthRatio = method.number("smoothing_length_ratio");
  spec.options.material = material;
  spec.options.boundaryVolumeCorrection = method.boolean("boundary_volume_correction");
  spec.options.boundaryAreaCorrection = method.boolean("boundary_area_correction");
  spec.options.boundaryKernelCorrection = method.boolean("kernel_correction");
  spec.options.boundaryIntegral = method.boolean("boundary_integral");
  spec.dashpotLumping =
      method.string("dashpot_lumping") == "consistent" ? DashpotLumping::Consistent : DashpotLumping::Particle;
  spec.smoothingRate = method.number("smoothing_rate");
  spec.smoothingOrder = static_cast<int>(method.integer("smoothing_order"));
  spec.smoothingScalesWithSpacing = method.boolean("smoothing_rate_scales_with_spacing");
  spec.deconvolution = method.boolean("deconvolution");
  spec.operatorStorage = method.string("operator");
  return spec;
}

}  // namespace mfwave
