#pragma once
// Where a plane cuts a cube, in closed form: the volume of the unit cube [-1/2, 1/2]^D on the
// side n . y <= s of a plane (n unit) and the area of the plane inside it. A fill uses it on the
// smallest sub-cells the surface cuts, with the plane tangent at the surface point nearest the
// sub-cell's centre, which makes a flat surface exact and leaves a curved one an error of the
// order of (curvature * side)^2 per sub-cell.
//
// The volume is the classic inclusion-exclusion over the cube's corners: with a_i = |n_i| and
// t = s + sum(a) / 2, V(t) = sum over subsets S of (-1)^|S| (t - sum_S a)_+^D / (D! prod a). Axes
// along which n is (nearly) zero are dropped first: the cut does not depend on them, and keeping
// them would divide by a vanishing product. The area is |n| dV/dt, taken from below (the area a
// shrinking solid loses), so a plane lying on a face of the cube is counted in the cube on the
// solid's side, once.

#include "core/Types.hpp"

namespace mfwave {

struct PlaneCut {
  Real volume;  // fraction of the unit cube, in [0, 1]
  Real area;    // area of the plane inside the unit cube
};

template <int D>
PlaneCut planeCutOfUnitCube(const Vec<D>& unitNormal, Real offset);

}  // namespace mfwave
