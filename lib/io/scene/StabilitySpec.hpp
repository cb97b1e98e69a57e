#pragma once
// [stability]: the StabilityMonitor's thresholds.

#include "io/scene/SceneReader.hpp"
#include "observers/StabilityMonitor.hpp"

#include <string>
#include <vector>

namespace mfwave {

struct StabilitySpec {
  Real growthFactor = 1e3;
  long window = 50;
  Real absoluteLimit = std::numeric_limits<Real>::infinity();
  // The energy ledger's stops for linear systems (LinearEnergyLedger).
  Real energyGrowthFactor = 100;
  Real energyBalanceLimit = 1;
  bool allowGrowth = false;  // record growth instead of stopping

  // `components`: unknowns per particle of the state the monitor watches; `quietAfter`: the time
  // after which no load acts (0: free vibration; +infinity: a load that never ends), from which
  // the monitor stops growth at any frequency.
  StabilityMonitorOptions options(int components, Real quietAfter) const {
    StabilityMonitorOptions o;
    o.growthFactor = growthFactor;
    o.window = window;
    o.absoluteLimit = absoluteLimit;
    o.components = components;
    o.quietAfter = quietAfter;
    o.stopGrowthAfterLoads = !allowGrowth;
    return o;
  }
};

StabilitySpec readStability(SceneReader& reader);

// Appends to `notes` what a run went on through under stability.allow_growth: each non-empty
// message (the stability monitor's, an energy ledger's), after `where` (a case name, or empty).
void noteAllowedGrowth(std::vector<std::string>& notes, const std::string& where,
                       const std::vector<std::string>& messages);

}  // namespace mfwave
