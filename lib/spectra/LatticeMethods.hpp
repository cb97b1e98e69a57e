#pragma once
// One name per linear(ised) method whose interior row the lattice tools use (the spectra tool,
// the planewave driver), and the builder that picks the right stencil for it, so that every tool
// offers the same methods with the same settings.

#include "spectra/MethodLatticeStencils.hpp"

#include <string>
#include <vector>

namespace mfwave {

struct LatticeMethodSettings {
  Material material = Material::fromLame(1, 1, 1);
  std::string kernel = "cubic_spline";  // very weak and updated-Lagrangian SPH
  Real smoothingLengthRatio = 1.3;      // SPH h / dx
  int rkOrder = 2;                      // RK collocation basis order
  Real rkSupportRatio = 2.5;            // RK a / dx
  Real rbShapeRatio = 3;                // RB a_r / dx
};

// "finite_difference", "vwsph_published", "vwsph_consistent", "vwsph_galerkin", "rkcm", "rbcm",
// "ulsph", "ulsph_corrected".
const std::vector<std::string>& latticeMethodNames();

// Whether the method is offered in D dimensions (rbcm: 1-D only, its global functions make a 2-D
// or 3-D row a dense solve over the whole block).
bool latticeMethodAvailable(const std::string& method, int dimension);

// The method's interior stencil at spacing dx. Throws InputError(key) for an unknown method or one
// not offered in D, and what the builders throw.
// The updated-Lagrangian options of "ulsph" / "ulsph_corrected" (the kernel-gradient correction).
UpdatedLagrangianSphOptions updatedLagrangianSphSettings(const std::string& method, const LatticeMethodSettings& settings);

template <int D>
MethodLatticeStencil<D> latticeMethodStencil(const std::string& method, const LatticeMethodSettings& settings,
                                             Real spacing, const std::string& key = "method");

}  // namespace mfwave
