#pragma once
// The [method] keys of strong-form collocation (Luo, Liu, Huang), typed once read: the shape
// functions (reproducing kernel or radial basis) and their parameters relative to the node
// spacing h, and the shape functions they make on a set of nodes. Shared by the collocation
// studies (bar1d, plane2d).

#include "io/scene/SceneReader.hpp"
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

// The keys of the scene's method: method.order and method.support_ratio for
// "reproducing_kernel", method.basis and method.shape_ratio for "radial_basis"; another method
// name is refused at method.name ("<program> uses reproducing_kernel or radial_basis").
CollocationSpec readCollocationSpec(SceneReader& reader, const std::string& methodName, const std::string& program);

// The shape functions of `spec` on `nodes` at node spacing h.
template <int D>
std::unique_ptr<ShapeFunctions<D>> makeCollocationShapes(const CollocationSpec& spec, const Coordinates<D>& nodes,
                                                         Real h);

}  // namespace mfwave
