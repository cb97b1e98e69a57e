#pragma once
// Records the energy ledger over time and the largest relative drift of the total.

#include "observers/Observer.hpp"
#include "observers/TimeSeries.hpp"

#include <functional>

namespace mfwave {

class LinearOperatorSystem;

struct EnergyTerms {
  Real kinetic = 0;
  Real strain = 0;
  Real total() const { return kinetic + strain; }
};

class EnergyObserver : public Observer {
 public:
  using EnergyFunction = std::function<EnergyTerms(const StateView&)>;
  explicit EnergyObserver(EnergyFunction energy);
  // 1/2 v^T M v and 1/2 u^T K u of a linear system.
  static EnergyFunction ofLinearSystem(const LinearOperatorSystem& system);

  void observe(const StateView& state) override;

  const TimeSeries& series() const { return series_; }
  // max over observations of |E(t) - E(0)| / |E(0)| (absolute when E(0) = 0).
  Real maxRelativeDrift() const { return maxDrift_; }
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

 private:
  EnergyFunction energy_;
  TimeSeries series_;
  Real initialTotal_ = 0;
  Real maxDrift_ = 0;
};

}  // namespace mfwave
