#include "geometry/CellShare.hpp"

#include "geometry/PlaneCut.hpp"

#include <cmath>

namespace mfwave {
namespace {

template <int D>
void accumulateCellShare(const Solid<D>& solid, const Vec<D>& centre, Real side, int depth, CellShare<D>& share) {
  const Real halfDiagonal = 0.5 * side * std::sqrt(static_cast<Real>(D));
  const Real d = solid.signedDistance(centre);
  if (d > halfDiagonal) return;
  const Real measure = std::pow(side, D);
  if (d < -halfDiagonal) {
    share.volume += measure;
    share.moment += measure * centre;
    return;
  }
  if (depth == 0) {
    const PlaneCut cut = planeCutOfUnitCube<D>(solid.normal(centre), -d / side);
    share.volume += cut.volume * measure;
    share.moment += (cut.volume * measure) * centre;
    share.area += cut.area * std::pow(side, D - 1);
    return;
  }
  const Real quarter = 0.25 * side;
  for (unsigned child = 0; child < (1u << D); ++child) {
    Vec<D> c = centre;
    for (int a = 0; a < D; ++a) c[a] += (child & (1u << a)) ? quarter : -quarter;
    accumulateCellShare(solid, c, 0.5 * side, depth - 1, share);
  }
}

}  // namespace

template <int D>
CellShare<D> cellShare(const Solid<D>& solid, const Vec<D>& centre, Real side, int depth) {
  CellShare<D> share;
  accumulateCellShare(solid, centre, side, depth, share);
  return share;
}

template CellShare<2> cellShare<2>(const Solid<2>&, const Vec2&, Real, int);
template CellShare<3> cellShare<3>(const Solid<3>&, const Vec3&, Real, int);

}  // namespace mfwave
