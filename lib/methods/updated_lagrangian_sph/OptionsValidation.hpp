#pragma once
// Checks UpdatedLagrangianSphOptions before a system is built, so a bad scene fails at once with
// the scene key of the offending option (method.smoothing_length_ratio, ...).

#include "methods/updated_lagrangian_sph/UpdatedLagrangianSphOptions.hpp"

namespace mfwave {

// Throws InputError naming the key ("method.<name>") of the first invalid option.
void validateUpdatedLagrangianSphOptions(const UpdatedLagrangianSphOptions& options);

}  // namespace mfwave
