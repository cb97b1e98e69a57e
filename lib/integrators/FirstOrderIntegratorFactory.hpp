#pragma once
// Builds a first-order integrator (y' = F(t, y)) by name, for drivers and scene files.

#include "integrators/ArkodeExplicit.hpp"
#include "integrators/FirstOrderIntegrator.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfwave {

// The names makeFirstOrderIntegrator accepts: "forward_euler", "predictor_corrector",
// "leapfrog" (SplitLeapfrog: needs a SplitFirstOrderSystem), "arkode".
std::vector<std::string> firstOrderIntegratorNames();

// `arkode` is used by "arkode" only (table, fixed or adaptive, tolerances; the step comes from
// initialise(..., dt)). Anything else: InputError("integrator.name", "unknown integrator 'x';
// valid: ...").
std::unique_ptr<FirstOrderIntegrator> makeFirstOrderIntegrator(const std::string& name,
                                                               const ArkodeOptions& arkode = {});

}  // namespace mfwave
