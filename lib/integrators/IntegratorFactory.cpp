#include "integrators/IntegratorFactory.hpp"

#include "core/Error.hpp"
#include "integrators/ArkodeSecondOrder.hpp"
#include "integrators/CentralDifference.hpp"
#include "integrators/Leapfrog.hpp"
#include "integrators/Newmark.hpp"

#include <cstdlib>

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

NamedIntegrator namedIntegrator(const std::string& spec) {
  NamedIntegrator out;
  const auto colon = spec.find(':');
  out.name = spec.substr(0, colon);
  if (colon == std::string::npos) {
    makeSecondOrderIntegrator(out.name);  // names it or throws
    return out;
  }
  const std::string detail = spec.substr(colon + 1);
  if (out.name == "arkode") {
    ArkodeExplicit::coefficients(detail);  // throws for an unknown table
    out.options.arkode.table = detail;
    return out;
  }
  if (out.name == "newmark") {
    if (detail == "linear_acceleration") out.options.newmarkBeta = 1.0 / 6;
    else if (detail == "fox_goodwin") out.options.newmarkBeta = 1.0 / 12;
    else {
      char* end = nullptr;
      out.options.newmarkBeta = std::strtod(detail.c_str(), &end);
      if (detail.empty() || end != detail.c_str() + detail.size() || !(out.options.newmarkBeta >= 0 && out.options.newmarkBeta <= 0.5))
        throw InputError("integrator", "'" + spec + "': newmark:<beta> wants beta in [0, 0.5], linear_acceleration "
                                       "or fox_goodwin");
    }
    out.options.newmarkGamma = 0.5;
    return out;
  }
  throw InputError("integrator", "'" + spec + "': only newmark:<beta> and arkode:<table> take a detail");
}

}  // namespace mfwave
