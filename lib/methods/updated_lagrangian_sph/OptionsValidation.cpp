#include "methods/updated_lagrangian_sph/OptionsValidation.hpp"

#include "core/Error.hpp"
#include "kernels/KernelFactory.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mfwave {
namespace {

std::string text(Real x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

void requireFinite(const char* key, Real x) {
  if (!std::isfinite(x)) throw InputError(key, "must be a finite number, got " + text(x));
}

void requirePositive(const char* key, Real x) {
  requireFinite(key, x);
  if (!(x > 0)) throw InputError(key, "must be positive, got " + text(x));
}

void requireNonNegative(const char* key, Real x) {
  requireFinite(key, x);
  if (!(x >= 0)) throw InputError(key, "must be non-negative, got " + text(x));
}

}  // namespace

void validateUpdatedLagrangianSphOptions(const UpdatedLagrangianSphOptions& options) {
  const std::vector<std::string>& names = kernelNames();
  if (std::find(names.begin(), names.end(), options.kernel) == names.end()) {
    std::string valid;
    for (const std::string& n : names) valid += (valid.empty() ? "" : ", ") + n;
    throw InputError("method.kernel", "unknown kernel '" + options.kernel + "'; valid: " + valid);
  }
  requirePositive("method.smoothing_length_ratio", options.smoothingLengthRatio);
  requireFinite("method.gamma", options.gamma);
  if (!(options.gamma >= 1)) throw InputError("method.gamma", "must be at least 1, got " + text(options.gamma));
  if (options.density != DensityUpdate::Summation && options.density != DensityUpdate::Continuity)
    throw InputError("method.density", "must be 'summation' or 'continuity'");
  requireNonNegative("method.viscosity_alpha", options.viscosity.alpha);
  requireNonNegative("method.viscosity_beta", options.viscosity.beta);
  // eta^2 h^2 is what keeps mu_ij finite when two particles meet.
  requirePositive("method.viscosity_eta", options.viscosity.eta);
  if (options.artificialStress.enabled) {
    requireNonNegative("method.artificial_stress_epsilon", options.artificialStress.epsilon);
    requirePositive("method.artificial_stress_exponent", options.artificialStress.exponent);
  }
  requireNonNegative("method.artificial_stress_spacing", options.artificialStress.referenceSpacing);
  requireNonNegative("method.xsph", options.xsph);
  if (options.xsph > 1) throw InputError("method.xsph", "must lie in [0, 1], got " + text(options.xsph));
  for (Real g : options.bodyForce) requireFinite("method.body_force", g);
  requireNonNegative("method.neighbour_skin", options.neighbourSkin);
  requirePositive("method.courant", options.courant);
  requirePositive("method.force_factor", options.forceFactor);
}

}  // namespace mfwave
