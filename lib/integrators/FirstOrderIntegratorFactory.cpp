#include "integrators/FirstOrderIntegratorFactory.hpp"

#include "core/Error.hpp"
#include "integrators/ArkodeFirstOrder.hpp"
#include "integrators/ForwardEuler.hpp"
#include "integrators/PredictorCorrector.hpp"
#include "integrators/SplitLeapfrog.hpp"

namespace mfwave {

std::vector<std::string> firstOrderIntegratorNames() {
  return {"forward_euler", "predictor_corrector", "leapfrog", "arkode"};
}

std::unique_ptr<FirstOrderIntegrator> makeFirstOrderIntegrator(const std::string& name, const ArkodeOptions& arkode) {
  if (name == "forward_euler") return std::make_unique<ForwardEuler>();
  if (name == "predictor_corrector") return std::make_unique<PredictorCorrector>();
  if (name == "leapfrog") return std::make_unique<SplitLeapfrog>();
  if (name == "arkode") return std::make_unique<ArkodeFirstOrder>(arkode);
  std::string valid;
  for (const auto& known : firstOrderIntegratorNames()) valid += (valid.empty() ? "" : ", ") + known;
  throw InputError("integrator.name", "unknown integrator '" + name + "'; valid: " + valid);
}

}  // namespace mfwave
