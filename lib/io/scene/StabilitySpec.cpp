#include "io/scene/StabilitySpec.hpp"

namespace mfwave {

StabilitySpec readStability(SceneReader& reader) {
  StabilitySpec s;
  s.growthFactor = reader.number("stability.growth_factor");
  s.window = static_cast<long>(reader.integer("stability.window"));
  s.absoluteLimit = reader.number("stability.absolute_limit");
  return s;
}

}  // namespace mfwave
