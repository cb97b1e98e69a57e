#include "io/scene/StabilitySpec.hpp"

namespace mfwave {

StabilitySpec readStability(SceneReader& reader) {
  StabilitySpec s;
  s.growthFactor = reader.number("stability.growth_factor");
  s.window = static_cast<long>(reader.integer("stability.window"));
  s.absoluteLimit = reader.number("stability.absolute_limit");
  s.energyGrowthFactor = reader.number("stability.energy_growth_factor");
  s.energyBalanceLimit = reader.number("stability.energy_balance_limit");
  s.allowGrowth = reader.boolean("stability.allow_growth");
  return s;
}

void noteAllowedGrowth(std::vector<std::string>& notes, const std::string& where,
                       const std::vector<std::string>& messages) {
  for (const std::string& message : messages)
    if (!message.empty())
      notes.push_back((where.empty() ? "" : where + ": ") + "stability.allow_growth let the run go on through: " +
                      message);
}

}  // namespace mfwave
