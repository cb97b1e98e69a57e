#include "geometry/SolidName.hpp"

#include "core/Error.hpp"

namespace mfwave {

std::string checkedSolidName(const std::string& name, const std::string& kind) {
  if (name.find('.') != std::string::npos)
    throw InputError(kind + ".name", "'" + name + "' contains '.', which separates a solid's name from its surface's");
  return name;
}

std::string qualifiedSurfaceName(const std::string& name, const std::string& surface) {
  return name.empty() ? surface : name + "." + surface;
}

std::string solidKey(const std::string& name, const std::string& kind, const std::string& field) {
  return (name.empty() ? kind : name) + "." + field;
}

}  // namespace mfwave
