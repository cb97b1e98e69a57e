#include "methods/collocation/CollocationIntegrators.hpp"

#include "core/Error.hpp"
#include "integrators/CentralDifference.hpp"
#include "methods/collocation/CollocationNewmark.hpp"

namespace mfwave {

std::vector<std::string> collocationIntegratorNames() { return {"central_difference", "newmark"}; }

std::unique_ptr<SecondOrderIntegrator> makeCollocationIntegrator(const std::string& name,
                                                                 const IntegratorOptions& options) {
  if (name != "central_difference" && name != "newmark")
    throw InputError("integrator.name", "collocation runs central_difference or newmark, not '" + name + "'");
  if (name == "newmark" && options.newmarkBeta > 0)
    return std::make_unique<CollocationNewmark>(options.newmarkBeta, options.newmarkGamma);
  return std::make_unique<CentralDifference>();
}

}  // namespace mfwave
