#pragma once
// [[load]]: point forces (at a point inside the box, along a direction) and body forces.

#include "core/TimeFunction.hpp"
#include "io/scene/GeometrySpec.hpp"
#include "io/scene/SceneReader.hpp"

#include <string>
#include <vector>

namespace mfwave {

enum class LoadType { PointForce, BodyForce };

std::string loadTypeName(LoadType type);  // "point_force", "body_force"

struct LoadSpec {
  LoadType type = LoadType::PointForce;
  std::vector<Real> position;   // PointForce: m, inside the box
  std::vector<Real> direction;  // PointForce: unit vector
  Real amplitude = 1;           // PointForce: N
  std::vector<Real> value;      // BodyForce: N/m^3, one entry per axis
  TimeFunction timeFunction = TimeFunction::constant(1);
};

std::vector<LoadSpec> readLoads(SceneReader& reader, const GeometrySpec& geometry);

}  // namespace mfwave
