#include "observers/EnergyObserver.hpp"

#include "core/Error.hpp"

#include "systems/LinearOperatorSystem.hpp"

#include <algorithm>
#include <cmath>

namespace mfwave {

EnergyObserver::EnergyObserver(EnergyFunction energy)
    : energy_(std::move(energy)), series_("time", {"kinetic", "strain", "total"}) {}

EnergyObserver::EnergyFunction EnergyObserver::ofLinearSystem(const LinearOperatorSystem& system) {
  return [&system](const StateView& state) {
    return EnergyTerms{system.kineticEnergy(state.velocity), system.strainEnergy(state.displacement)};
  };
}

void EnergyObserver::observe(const StateView& state) {
  const EnergyTerms terms = energy_(state);
  if (series_.rows() == 0) initialTotal_ = terms.total();
  const Real scale = initialTotal_ != 0 ? std::abs(initialTotal_) : 1;
  maxDrift_ = std::max(maxDrift_, std::abs(terms.total() - initialTotal_) / scale);
  series_.append(state.time, {terms.kinetic, terms.strain, terms.total()});
}

void EnergyObserver::saveState(StateArchive& archive) const {
  series_.saveState(archive);
  archive.put("reference", std::vector<Real>{initialTotal_, maxDrift_});
}

void EnergyObserver::restoreState(const StateArchive& archive) {
  series_.restoreState(archive);
  const std::vector<Real>& reference = archive.numbers("reference", 2);
  initialTotal_ = reference[0];
  maxDrift_ = reference[1];
}

}  // namespace mfwave
