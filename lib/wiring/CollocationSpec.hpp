#pragma once
// The [method] keys of strong-form collocation (Luo, Liu, Huang), typed once read: the shape
// functions (reproducing kernel or radial basis) and their parameters relative to the node
// spacing h, the shape functions they make on a set of nodes, and whether RK rows of that order and
// support have growing modes. Shared by the collocation studies (bar1d, plane2d, lamb2d, lamb3d).

#include "core/Material.hpp"
#include "io/scene/SceneReader.hpp"
#include "io/scene/SceneSchema.hpp"
#include "methods/collocation/ShapeFunctions.hpp"
#include "particles/ParticleSet.hpp"

#include <memory>
#include <string>

namespace mfwave {

enum class CollocationShapeKind { ReproducingKernel, RadialBasis };

struct CollocationSpec {
  CollocationShapeKind kind = CollocationShapeKind::ReproducingKernel;
  int order = 2;             // reproducing kernel: basis order m
  Real supportRatio = 3.3;   // reproducing kernel: cubic B-spline support radius a / h
  std::string radialBasis;   // radial basis: radialBasisNames()
  Real shapeRatio = 1;       // radial basis: shape parameter a_r / h

  // For messages: "reproducing kernel order 2, method.support_ratio = 3.3" or "radial basis
  // inverse_multiquadric, method.shape_ratio = 1".
  std::string describe() const;
};

// The one declaration of collocation's [method] keys, beside their reader: method.order and
// method.support_ratio ("reproducing_kernel"), and/or method.basis and
// method.shape_ratio ("radial_basis"); the method names join method.name's choices. A study gives its
// own defaults (bar1d the paper's a / h = 3.3 and a_r / h = 1; plane2d 2.5; lamb3d 2.2, the widest
// stable 3-D support); 0 leaves a default to `defaultNote` (the catalogue's listing: it depends on
// the study).
struct CollocationKeyDefaults {
  bool reproducingKernel = true;  // method.order, method.support_ratio
  Real supportRatio = 0;
  std::string supportNote;        // used when supportRatio is 0
  std::string supportAdvice;      // appended to method.support_ratio's description (where it grows)
  bool radialBasis = false;       // method.basis, method.shape_ratio
  Real shapeRatio = 0;
};
void addCollocationKeys(SceneSchema& schema, const CollocationKeyDefaults& defaults);

// The keys of the scene's method: method.order and method.support_ratio for
// "reproducing_kernel", method.basis and method.shape_ratio for "radial_basis"; another method
// name is refused at method.name ("<program> uses reproducing_kernel or radial_basis").
CollocationSpec readCollocationSpec(SceneReader& reader, const std::string& methodName, const std::string& program);

// The shape functions of `spec` on `nodes` at node spacing h.
template <int D>
std::unique_ptr<ShapeFunctions<D>> makeCollocationShapes(const CollocationSpec& spec, const Coordinates<D>& nodes,
                                                         Real h);

// Whether the interior rows of RK collocation in `dimension` (2: plane strain, or 3; basis order
// `order`, cubic B-spline support a = ratio h) have growing modes: the exact spectrum of the interior
// row on a periodic lattice (at h = 1: with a / h fixed the rows scale as 1 / h^2, so one spectrum
// serves every resolution). omega^2 < 0 or complex anywhere is a mode that grows at every time step,
// whatever the integrator: in 2-D from about a / h = 2.77 on, in 3-D from 2.5 on (m = 2), where the
// mass symbol psi-hat changes sign (docs/studies/spectra.md, docs/studies/stability-atlas.md). Each
// study decides what to do with it (plane2d: exit 3 through refuseGrowingModes; lamb2d and lamb3d:
// an input error at method.support_ratio).
struct CollocationGrowingModes {
  // "" when nothing grows; else "the RK collocation operator (method.order = 2, method.support_ratio
  // = 3) has growing modes: its interior <where omega^2 is smallest>; such a mode grows at every time step".
  std::string what;
  std::string advice;  // what to change
  bool growing() const { return !what.empty(); }
};
CollocationGrowingModes rkGrowingModes(int dimension, int order, Real ratio, const Material& material);
// rkGrowingModes in plane strain (plane2d, lamb2d).
inline CollocationGrowingModes rkPlaneStrainGrowingModes(int order, Real ratio, const Material& material) {
  return rkGrowingModes(2, order, ratio, material);
}

}  // namespace mfwave
