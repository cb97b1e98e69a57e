#pragma once
// Which integrator a scene names, as a value: the drivers and the scene layer decide by kind (is
// it the central difference that takes a velocity filter and prescribed faces? Newmark, which has
// no explicit limit?) instead of comparing names after the scene is read.

#include <string>

namespace mfwave {

enum class IntegratorKind { CentralDifference, Leapfrog, Newmark, Arkode, ForwardEuler, PredictorCorrector };

// The kind of a name of secondOrderIntegratorNames() or firstOrderIntegratorNames(); any other
// name: InputError("integrator.name", "unknown integrator '<name>'").
IntegratorKind integratorKind(const std::string& name);

// The scene name of a kind ("central_difference", ...).
const char* integratorName(IntegratorKind kind);

}  // namespace mfwave
