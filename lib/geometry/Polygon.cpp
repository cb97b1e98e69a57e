#include "geometry/Polygon.hpp"

#include "geometry/SolidName.hpp"

#include <string>

namespace mfwave {

Polygon::Polygon(std::vector<Vec2> vertices, const std::string& name)
    : name_(checkedSolidName(name, "polygon")), shape_(std::move(vertices), solidKey(name_, "polygon", "vertices")) {}

std::string Polygon::surfaceName(const Vec2& x) const {
  return qualifiedSurfaceName(name_, "edge" + std::to_string(shape_.nearestEdge(x).edge));
}

}  // namespace mfwave
