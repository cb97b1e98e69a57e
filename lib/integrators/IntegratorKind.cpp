#include "integrators/IntegratorKind.hpp"

#include "core/Error.hpp"

#include <array>
#include <utility>

namespace mfwave {
namespace {

constexpr std::array<std::pair<IntegratorKind, const char*>, 6> kNames{{
    {IntegratorKind::CentralDifference, "central_difference"},
    {IntegratorKind::Leapfrog, "leapfrog"},
    {IntegratorKind::Newmark, "newmark"},
    {IntegratorKind::Arkode, "arkode"},
    {IntegratorKind::ForwardEuler, "forward_euler"},
    {IntegratorKind::PredictorCorrector, "predictor_corrector"},
}};

}  // namespace

IntegratorKind integratorKind(const std::string& name) {
  for (const auto& [kind, known] : kNames)
    if (name == known) return kind;
  throw InputError("integrator.name", "unknown integrator '" + name + "'");
}

const char* integratorName(IntegratorKind kind) {
  for (const auto& [known, name] : kNames)
    if (kind == known) return name;
  return "unknown";
}

}  // namespace mfwave
