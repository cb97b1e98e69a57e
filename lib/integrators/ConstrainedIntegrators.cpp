#include "integrators/ConstrainedIntegrators.hpp"

#include "core/Error.hpp"
#include "integrators/CentralDifference.hpp"
#include "integrators/ConstrainedNewmark.hpp"

namespace mfwave {

std::vector<std::string> constrainedIntegratorNames() { return {"central_difference", "newmark"}; }

std::unique_ptr<SecondOrderIntegrator> makeConstrainedIntegrator(const std::string& name,
                                                                 const IntegratorOptions& options) {
  if (name != "central_difference" && name != "newmark")
    throw InputError("integrator.name", "a constrained system (collocation) runs central_difference or newmark, not '" +
                                            name + "'");
  if (name == "newmark" && options.newmarkBeta > 0)
    return std::make_unique<ConstrainedNewmark>(options.newmarkBeta, options.newmarkGamma);
  return std::make_unique<CentralDifference>();
}

}  // namespace mfwave
