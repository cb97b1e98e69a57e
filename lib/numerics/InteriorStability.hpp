#pragma once
// Does a lattice method's interior row have growing modes? From the exact spectrum of the row on
// a periodic lattice (DispersionSpectrum: every wavenumber of the grid), before any step is taken.
// omega^2 < 0 (or complex) anywhere is a mode that grows like exp(sqrt(-omega^2) t) at every time
// step: no integrator or step size can hold it, so a driver refuses such a scene (exit 3) instead
// of running it into overflow. The same spectrum gives the central-difference limit of the
// interior, 2 / omega_max.

#include "numerics/DispersionSpectrum.hpp"
#include "numerics/LatticeDispersion.hpp"

#include <string>

namespace mfwave {

template <int D>
struct InteriorStability {
  int cells = 0;                    // lattice cells per axis the spectrum was taken on
  Real largestOmegaSquared = 0;
  Real smallestOmegaSquared = 0;
  Vec<D> smallestAtKdx = Vec<D>::Zero();  // k dx where omega^2 is smallest
  Real largestImaginaryRatio = 0;   // largest |Im omega^2| / largest |omega^2|

  // omega^2 below -tolerance omega^2_max, or an imaginary part above tolerance.
  bool growing(Real tolerance = 1e-10) const;
  Real smallestOverLargest() const { return smallestOmegaSquared / largestOmegaSquared; }
  // "omega^2 reaches -0.0224 of omega^2_max at k dx = (2.26, 3.14, 3.14)" or the imaginary part.
  std::string describe() const;
};

// Lattice cells per axis for a periodic operator of these stencils: `cells` rounded up to even and
// doubled until the stencils (a global method's block may be wide) reach less than half of it.
// Throws InputError("cells") for cells < 4.
template <int D>
int periodicLatticeCells(const LatticeStencil<D>& acceleration, const LatticeStencil<D>& mass, Real spacing, int cells);

// The smallest even number of cells per axis, at least `atLeast`, in which the stencils reach less
// than half: the cheapest periodic lattice on which runs of the operator are faithful (the
// stability atlas's confirmations). Throws InputError("cells") for atLeast < 4.
template <int D>
int smallestPeriodicLatticeCells(const LatticeStencil<D>& acceleration, const LatticeStencil<D>& mass, Real spacing,
                                 int atLeast);

// The verdict from a spectrum already taken (spacing: the lattice's, to report k dx).
template <int D>
InteriorStability<D> interiorStability(const DispersionSpectrum<D>& spectrum, Real spacing, int cells);

// The row's acceleration stencil (and its mass stencil, empty when lumped) on a periodic lattice of
// periodicLatticeCells(..., cells) per axis.
template <int D>
InteriorStability<D> interiorStability(const LatticeStencil<D>& acceleration, const LatticeStencil<D>& mass,
                                       Real spacing, int cells);

}  // namespace mfwave
