#pragma once
// A lattice block with ghost layers on every face and its neighbour list (rows for the physical
// particles only), the setting of Ding-Long-Wu section 8.

#include "kernels/CubicSplineKernel.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

namespace mfwave::test {

template <int D>
struct Block {
  ParticleSet<D> particles;
  NeighbourList neighbours;
  CubicSplineKernel kernel;

  // Lattice of [lower, upper] at spacing dx, `ghostLayers` ghost layers on every face, cubic spline
  // with smoothing length h.
  Block(const Vec<D>& lower, const Vec<D>& upper, Real dx, int ghostLayers, Real h)
      : particles(makeLattice<D>(lower, upper, dx)), kernel(D, h) {
    if (ghostLayers > 0) addGhostLayers<D>(particles, lower, upper, dx, ghostLayers, allFaces(D));
    neighbours = buildNeighbourList(CellList<D>(particles, kernel.supportRadius()), particles.physicalCount());
  }

  // Index of the physical particle at x (lattice node), -1 if none.
  Index find(const Vec<D>& x) const {
    for (Index i = 0; i < particles.physicalCount(); ++i)
      if ((particles.position(i) - x).norm() < 1e-9) return i;
    return -1;
  }
};

}  // namespace mfwave::test
