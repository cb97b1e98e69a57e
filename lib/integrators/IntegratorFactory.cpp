#include "integrators/IntegratorFactory.hpp"

#include "core/Error.hpp"
#include "integrators/ArkodeSecondOrder.hpp"
#include "integrators/CentralDifference.hpp"
#include "integrators/Leapfrog.hpp"
#include "integrators/Newmark.hpp"

namespace mfwave {

std::vector<std::string> secondOrderIntegratorNames() {
  return {"central_difference", "leapfrog", "newmark", "arkode"};
}

std::unique_ptr<SecondOrderIntegrator> makeSecondOrderIntegrator(const std::string& name,
                                                                 const IntegratorOptions& options) {
  if (name == "central_difference") return std::make_unique<CentralDifference>(options.centralDifferenceDamping);
  if (name == "leapfrog") return std::make_unique<Leapfrog>();
  if (name == "newmark") return std::make_unique<Newmark>(options.newmarkBeta, options.newmarkGamma);
  if (name == "arkode") return std::make_unique<ArkodeSecondOrder>(options.arkode);
  std::string valid;
  for (const auto& known : secondOrderIntegratorNames()) valid += (valid.empty() ? "" : ", ") + known;
  throw InputError("integrator", "unknown integrator '" + name + "'; valid: " + valid);
}

}  // namespace mfwave
