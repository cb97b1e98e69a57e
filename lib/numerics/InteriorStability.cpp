#include "numerics/InteriorStability.hpp"

#include "numerics/PeriodicLattice.hpp"
#include "core/Error.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace mfwave {

template <int D>
bool InteriorStability<D>::growing(Real tolerance) const {
  return smallestOmegaSquared < -tolerance * largestOmegaSquared || largestImaginaryRatio > tolerance;
}

template <int D>
std::string InteriorStability<D>::describe() const {
  std::ostringstream s;
  s << std::setprecision(3);
  if (smallestOmegaSquared < 0) {
    s << "omega^2 reaches " << smallestOverLargest() << " of omega^2_max at k dx = (";
    for (int a = 0; a < D; ++a) s << (a ? ", " : "") << smallestAtKdx[a];
    s << ")";
  } else {
    s << "omega^2 has an imaginary part of " << largestImaginaryRatio << " of its largest value";
  }
  return s.str();
}

namespace {

template <int D>
int largestReach(const LatticeStencil<D>& acceleration, const LatticeStencil<D>& mass, Real spacing) {
  return std::max(stencilReach(acceleration, spacing), mass.size() > 0 ? stencilReach(mass, spacing) : 0);
}

int evenAtLeast(int cells) {
  if (cells < 4) throw InputError("cells", "the periodic lattice needs at least 4 cells per axis");
  return cells % 2 ? cells + 1 : cells;  // the periodic operator wants an even lattice
}

}  // namespace

template <int D>
int smallestPeriodicLatticeCells(const LatticeStencil<D>& acceleration, const LatticeStencil<D>& mass, Real spacing,
                                 int atLeast) {
  return std::max(evenAtLeast(atLeast), 2 * (largestReach(acceleration, mass, spacing) + 1));
}

template <int D>
int periodicLatticeCells(const LatticeStencil<D>& acceleration, const LatticeStencil<D>& mass, Real spacing, int cells) {
  cells = evenAtLeast(cells);
  const int reach = largestReach(acceleration, mass, spacing);
  while (2 * reach >= cells) cells *= 2;
  return cells;
}

template <int D>
InteriorStability<D> interiorStability(const DispersionSpectrum<D>& spectrum, Real spacing, int cells) {
  const auto e = spectrum.extremes();
  InteriorStability<D> result;
  result.cells = cells;
  result.largestOmegaSquared = e.largestOmegaSquared;
  result.smallestOmegaSquared = e.smallestOmegaSquared;
  result.smallestAtKdx = e.smallestAt * spacing;
  result.largestImaginaryRatio = e.largestImaginaryRatio;
  return result;
}

template <int D>
InteriorStability<D> interiorStability(const LatticeStencil<D>& acceleration, const LatticeStencil<D>& mass,
                                       Real spacing, int cells) {
  cells = periodicLatticeCells(acceleration, mass, spacing, cells);
  const DispersionSpectrum<D> spectrum(makePeriodicLatticeOperator<D>(acceleration, spacing, cells, mass));
  return interiorStability(spectrum, spacing, cells);
}

template struct InteriorStability<1>;
template struct InteriorStability<2>;
template struct InteriorStability<3>;
#define MFWAVE_INSTANTIATE(D)                                                                                    \
  template int periodicLatticeCells<D>(const LatticeStencil<D>&, const LatticeStencil<D>&, Real, int);          \
  template int smallestPeriodicLatticeCells<D>(const LatticeStencil<D>&, const LatticeStencil<D>&, Real, int);  \
  template InteriorStability<D> interiorStability<D>(const DispersionSpectrum<D>&, Real, int);                   \
  template InteriorStability<D> interiorStability<D>(const LatticeStencil<D>&, const LatticeStencil<D>&, Real, int);
MFWAVE_INSTANTIATE(1)
MFWAVE_INSTANTIATE(2)
MFWAVE_INSTANTIATE(3)
#undef MFWAVE_INSTANTIATE

}  // namespace mfwave
