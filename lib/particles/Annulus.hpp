#pragma once
// Particles filling an annulus (a ring) in 2-D, for bodies with curved boundaries such as the
// colliding rings of Gray, Monaghan and Swift. A lattice cut to the ring would leave a ragged,
// stair-stepped surface and particles of unequal share of the area; concentric circles follow both
// circular boundaries exactly, at an equal distance dr / 2 inside each of them.
//
// The width R - r holds n = round((R - r) / spacing) rings (at least one) of equal width dr, so the
// rings fit exactly; ring k sits at r_k = r + (k + 1/2) dr and carries m_k = round(2 pi r_k / spacing)
// equally spaced particles. Every particle of ring k gets the volume 2 pi r_k dr / m_k: the area of
// the ring's band [r_k - dr/2, r_k + dr/2] divided exactly among them, so the volumes add up to
// pi (R^2 - r^2). Odd rings are turned by half their angular step so that the particles do not line
// up along the radii (a radial seam would make one direction of the body special).

#include "core/Types.hpp"
#include "particles/ParticleSet.hpp"

namespace mfwave {

// Physical particles of the annulus r <= |x - centre| <= R, ring by ring from the inside, each ring
// counter-clockwise; face masks 0 (no box faces). Throws InputError "centre" (not finite),
// "inner_radius" (r < 0 or not finite), "outer_radius" (R <= r or not finite), "spacing" (<= 0 or
// not finite). r = 0 gives a disc.
ParticleSet<2> makeAnnulus(const Vec2& centre, Real innerRadius, Real outerRadius, Real spacing);

// Appends every particle of `from` to `into` (positions, volumes, kinds, face masks), with new
// global ids from into.nextGlobalId(), so that two bodies make one set. Throws Error when a
// physical particle of `from` would follow a ghost of `into` (ParticleSet's ordering invariant).
// (ParticleSet has no append of its own.)
template <int D>
void appendParticles(ParticleSet<D>& into, const ParticleSet<D>& from);

}  // namespace mfwave
