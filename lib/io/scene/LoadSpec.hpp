#pragma once
// [[load]]: point forces (at a point inside the box, along a direction), body forces, and surface
// patches (a uniform traction on an axis-aligned rectangle of a box face, Ding-Long-Wu eq. (36)-(37)).

#include "core/TimeFunction.hpp"
#include "io/scene/GeometrySpec.hpp"
#include "io/scene/SceneReader.hpp"

#include <string>
#include <vector>

namespace mfwave {

enum class LoadType { PointForce, BodyForce, SurfacePatch };

std::string loadTypeName(LoadType type);  // "point_force", "body_force", "surface_patch"

struct LoadSpec {
  LoadType type = LoadType::PointForce;
  std::vector<Real> position;   // PointForce: m, inside the box
  std::vector<Real> direction;  // PointForce: unit vector
  Real amplitude = 1;           // PointForce: N
  std::vector<Real> value;      // BodyForce: N/m^3, one entry per axis
  int face = -1;                // SurfacePatch: BoxFace number
  std::vector<Real> centre;     // SurfacePatch: m, on the face
  std::vector<Real> halfWidth;  // SurfacePatch: m, 0 along the face normal
  std::vector<Real> traction;   // SurfacePatch: Pa, one entry per axis
  TimeFunction timeFunction = TimeFunction::constant(1);
};

std::vector<LoadSpec> readLoads(SceneReader& reader, const GeometrySpec& geometry);

}  // namespace mfwave
