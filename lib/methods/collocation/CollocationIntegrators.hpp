#pragma once
// The integrators a collocation study runs, chosen by name once: central_difference, and newmark,
// which with beta > 0 is the implicit CollocationNewmark (its constrained solve of the boundary
// rows) and with beta = 0 the explicit central difference it reduces to. bar1d and plane2d share it.

#include "integrators/Integrator.hpp"
#include "integrators/IntegratorFactory.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfwave {

// "central_difference", "newmark".
std::vector<std::string> collocationIntegratorNames();

// Throws InputError("integrator.name") for any other name, naming the ones accepted.
std::unique_ptr<SecondOrderIntegrator> makeCollocationIntegrator(const std::string& name,
                                                                 const IntegratorOptions& options);

}  // namespace mfwave
