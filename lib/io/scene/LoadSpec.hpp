#pragma once
// [[load]]: point forces (at a point inside the box, along a direction), body forces, surface
// patches (a uniform traction on an axis-aligned rectangle of a box face, Ding-Long-Wu eq. (36)-(37)),
// moment-tensor point sources (the seismologists' source: the body force -M grad delta) and surface
// tractions on a named surface of the scene's solid (the part within a radius of a centre, pressing
// along the inward normal or with a given vector; the solid program resolves the surface's name).

#include "core/TimeFunction.hpp"
#include "io/scene/GeometrySpec.hpp"
#include "io/scene/SceneReader.hpp"

#include <string>
#include <vector>

namespace mfwave {

enum class LoadType { PointForce, BodyForce, SurfacePatch, MomentTensor, SurfaceTraction };

// "point_force", "body_force", "surface_patch", "moment_tensor", "surface_traction".
std::string loadTypeName(LoadType type);

struct LoadSpec {
  LoadType type = LoadType::PointForce;
  std::vector<Real> position;   // PointForce: m, inside the box
  std::vector<Real> direction;  // PointForce: unit vector
  Real amplitude = 1;           // PointForce: N
  std::vector<Real> value;      // BodyForce: N/m^3, one entry per axis
  int face = -1;                // SurfacePatch: BoxFace number
  std::vector<Real> centre;     // SurfacePatch: m, on the face
  std::vector<Real> halfWidth;  // SurfacePatch: m, 0 along the face normal
  std::vector<Real> traction;   // SurfacePatch, SurfaceTraction: Pa, one entry per axis (empty: pressure)
  std::vector<Real> moment;     // MomentTensor: N m, xx, yy, xy (2-D) or xx, yy, zz, xy, xz, yz (3-D)
  std::string surface;          // SurfaceTraction: a named surface of the solid ("ground.plane")
  Real radius = 0;              // SurfaceTraction: m, the part of the surface within it of centre
  Real pressure = 0;            // SurfaceTraction: Pa, along the inward normal (when traction is empty)
  TimeFunction timeFunction = TimeFunction::constant(1);
};

std::vector<LoadSpec> readLoads(SceneReader& reader, const GeometrySpec& geometry);

}  // namespace mfwave
