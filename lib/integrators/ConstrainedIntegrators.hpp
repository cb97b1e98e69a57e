#pragma once
// The integrators a constrained system (ConstrainedSecondOrderSystem: strong-form collocation with
// its boundary rows) runs, chosen by name once: central_difference on its explicit form, and
// newmark, which with beta > 0 is the implicit ConstrainedNewmark (the constraint rows solved with
// every step) and with beta = 0 the explicit central difference it reduces to. bar1d and plane2d
// share it.

#include "integrators/Integrator.hpp"
#include "integrators/IntegratorFactory.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfwave {

// "central_difference", "newmark".
std::vector<std::string> constrainedIntegratorNames();

// Throws InputError("integrator.name") for any other name, naming the ones accepted.
std::unique_ptr<SecondOrderIntegrator> makeConstrainedIntegrator(const std::string& name,
                                                                 const IntegratorOptions& options);

}  // namespace mfwave
