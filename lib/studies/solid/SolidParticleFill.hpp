#pragma once
// What the solid study's particle-method cases (the UL-SPH, TL-SPH) share: the body-fitted fill of
// the scene's solid, each load's traction on the surface particles of its named surface, and the
// probes' interpolation rows over the particles.

#include "geometry/ParticleFill.hpp"
#include "particles/ParticleSet.hpp"
#include "studies/solid/SolidCase.hpp"
#include "studies/solid/SolidStudy.hpp"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace mfwave::solid {

template <int D>
struct FilledSolid {
  SolidParticles<D> fill;     // positions, volumes, surface flags, normals and areas
  ParticleSet<D> particles;   // the same positions and volumes, for a method
  Real volume = 0;            // their total
  Index surfaceParticles = 0;
  // The smoothing-length ratio that gives h = ratio dx to a method measuring its spacing from the
  // mean volume (which the cut cells make smaller than dx^D).
  Real ratioFor(Real ratio, Real dx) const;
};

// One particle per lattice cell that meets the solid (geometry/ParticleFill), cells centred on the
// scene's lattice nodes at `spacing`; result's unknowns, volume and cutCells (its surface particles)
// are filled.
template <int D>
FilledSolid<D> fillSolid(const SolidPlan<D>& plan, Real spacing, SolidCaseResult& result);

// A load's traction per surface particle of its named surface: (particle, traction vector times the
// particle's share of the surface), the share its fill area times w = clamp((r - |p - c|) / s + 1/2,
// 0, 1), p the particle projected onto the surface, s its area (2-D) or the area's square root
// (3-D). Throws InputError("load[l].surface") when no particle carries any of it.
template <int D>
std::vector<std::pair<Index, Vec<D>>> surfaceForces(const SolidPlan<D>& plan, const FilledSolid<D>& filled,
                                                    std::size_t l, Real spacing);

// The pairs of particles the material connects: false where the segment between their initial
// positions crosses a [[crack]] (the visibility criterion); empty when the solid has no crack. It
// refers to `plan` and `filled`, which must outlive it.
template <int D>
std::function<bool(Index, Index)> crackFilter(const SolidPlan<D>& plan, const FilledSolid<D>& filled);

// runCase's `where` for a particle method: "<method> on the solid, case <name>: the particle starts at
// (x, y)" ("" for an index beyond the fill).
template <int D>
std::function<std::string(long)> particleWhere(const FilledSolid<D>& filled, const std::string& method,
                                               const std::string& caseName);

// The surface particles on the plan's fixed surfaces ([[surface_boundary]]), by the surface point
// nearest each.
template <int D>
std::vector<Index> fixedParticles(const SolidPlan<D>& plan, const FilledSolid<D>& filled);

// The probes' rows over the particles' D components: linear reproducing-kernel (moving least
// squares, m = 1, support 2.5 dx) interpolation at each probe over the particles' initial positions,
// along its direction, times `scale`.
template <int D>
std::vector<std::vector<std::pair<Index, Real>>> probeRows(const SolidPlan<D>& plan, const FilledSolid<D>& filled,
                                                           Real spacing, Real scale);

}  // namespace mfwave::solid
