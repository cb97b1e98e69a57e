#include "PlateLattice.hpp"

#include <cmath>

namespace mfwave::plate {

PlateLattice cellCentredPlate(Real length, Real thickness, Real lowerY, Index rows, Index clampLayers) {
  PlateLattice p;
  p.rows = rows;
  p.spacing = thickness / static_cast<Real>(rows);
  p.columns = static_cast<Index>(std::llround(length / p.spacing));
  const Real dp = p.spacing;
  p.particles.reserve((p.columns + clampLayers) * rows);
  for (Index j = 0; j < rows; ++j) {
    const Real y = lowerY + (static_cast<Real>(j) + 0.5) * dp;
    for (Index i = -clampLayers; i < p.columns; ++i) {
      const Real x = (static_cast<Real>(i) + 0.5) * dp;
      const Index index = p.particles.add(Vec2(x, y), dp * dp);
      if (i < 0) p.clamp.push_back(index);
      if (i == p.columns - 1) p.tip.push_back(index);
    }
  }
  return p;
}

}  // namespace mfwave::plate
