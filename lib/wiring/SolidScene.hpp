#pragma once
// The solid a scene describes (issue 48): cracks ([[crack]]: a segment in 2-D, a rectangle in 3-D,
// inside the box), named shapes ([[shape]]: box, half_space, ball, cylinder,
// polygon, extruded_polygon, mesh), the solid as a CSG expression over them within the scene's box
// (geometry.solid; the box itself is 'box'), and materials by region ([[region]]: an expression and
// a material; where no region covers the solid, [material]). Overlapping regions are refused unless
// geometry.region_overlap = "last" (the later region wins). Checked before any work: a shape or a
// region wholly outside the box, an empty solid, an open surface mesh, overlaps without the rule,
// each a named key and exit 2.
//
// What reads it: the solid study (drivers/solid) and `mfwave check`. A program that runs boxes only
// does not register these keys, so a scene with them is refused there by its unknown keys.

#include "core/Material.hpp"
#include "geometry/Cracks.hpp"
#include "geometry/Csg.hpp"
#include "io/scene/Scene.hpp"
#include "io/scene/SceneSchema.hpp"

#include <functional>
#include <string>
#include <vector>

namespace mfwave {

// Registers geometry.solid, geometry.region_overlap, [[shape]] and [[region]] in `schema`.
void addSolidKeys(SceneSchema& schema);

template <int D>
struct SceneSolid {
  SolidPtr<D> box;        // the scene's box
  SolidPtr<D> solid;      // the expression, within the box
  SolidPtr<D> expression; // the expression alone
  // The expression with 'box' read as all space: its surfaces are the solid's own, not the box's
  // faces (which are the lattice's boundary, where a cut-cell method needs no cut).
  SolidPtr<D> unbounded;
  std::vector<Material> materials;   // [material] first, then each region's
  std::vector<std::string> regionNames;
  std::vector<SolidPtr<D>> regions;  // region i's solid (material i + 1)
  std::vector<std::vector<Real>> initialVelocity;      // per region (empty: at rest)
  std::vector<std::vector<Real>> initialDisplacement;  // per region (empty: none)
  bool lastRegionWins = false;
  Cracks<D> cracks;  // [[crack]]: the particle methods' visibility criterion
  // The share of the box's lattice nodes (at geometry.spacing) inside the solid.
  Real latticeFraction = 0;

  // Index into `materials` at a point of the solid: the last region holding it, else 0.
  int materialAt(const Vec<D>& x) const;
  // The region holding x (-1 for none).
  int regionAt(const Vec<D>& x) const;
  // A bound on the distance to the nearest region surface (infinite without regions).
  Real interfaceDistance(const Vec<D>& x) const;
};

// Reads and checks the solid of `scene` (whose common sections are read). The solid is sampled on
// the scene's lattice (geometry.spacing) for the checks.
template <int D>
SceneSolid<D> readSceneSolid(SceneReader& reader, const Scene& scene);

}  // namespace mfwave
