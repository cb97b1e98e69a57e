#pragma once
// Builds a second-order integrator by name, for drivers and scene files.

#include "integrators/ArkodeExplicit.hpp"
#include "integrators/CentralDifference.hpp"
#include "integrators/Integrator.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfwave {

struct IntegratorOptions {
  // "central_difference": dashpots implicit (Ding-Long-Wu eq. 32, the default) or through the
  // explicit predictor; see CentralDifference::Damping and dampingNames().
  CentralDifference::Damping centralDifferenceDamping = CentralDifference::Damping::implicit;
  // "newmark": Newmark parameters (default: average acceleration, unconditionally stable).
  Real newmarkBeta = 0.25;
  Real newmarkGamma = 0.5;
  // "arkode": table, fixed or adaptive, tolerances. The step comes from initialise(..., dt).
  ArkodeOptions arkode;
};

// The names makeSecondOrderIntegrator accepts.
std::vector<std::string> secondOrderIntegratorNames();

// "central_difference", "leapfrog", "newmark", "arkode"; anything else:
// InputError("integrator", "unknown integrator 'x'; valid: ...").
std::unique_ptr<SecondOrderIntegrator> makeSecondOrderIntegrator(const std::string& name,
                                                                 const IntegratorOptions& options = {});

// An integrator named in one word, as the stability atlas's confirmations list them:
// "central_difference", "leapfrog", "newmark" (average acceleration), "newmark:<beta>" with gamma =
// 1/2 and beta a number or linear_acceleration (1/6) or fox_goodwin (1/12), "arkode:<table>" (fixed
// step). Gives the factory name and its options; InputError("integrator") for a bad spec.
struct NamedIntegrator {
  std::string name;
  IntegratorOptions options;
};
NamedIntegrator namedIntegrator(const std::string& spec);

}  // namespace mfwave
