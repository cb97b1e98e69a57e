#pragma once
// [stability]: the StabilityMonitor's thresholds.

#include "io/scene/SceneReader.hpp"
#include "observers/StabilityMonitor.hpp"

namespace mfwave {

struct StabilitySpec {
  Real growthFactor = 1e3;
  long window = 50;
  Real absoluteLimit = std::numeric_limits<Real>::infinity();
  // The energy ledger's stops for linear systems (LinearEnergyLedger).
  Real energyGrowthFactor = 100;
  Real energyBalanceLimit = 1;
  bool allowGrowth = false;  // record growth instead of stopping

  // `components`: unknowns per particle of the state the monitor watches.
  StabilityMonitorOptions options(int components) const {
    StabilityMonitorOptions o;
    o.growthFactor = growthFactor;
    o.window = window;
    o.absoluteLimit = absoluteLimit;
    o.components = components;
    return o;
  }
};

StabilitySpec readStability(SceneReader& reader);

}  // namespace mfwave
