#include "EnergyLedger.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mfwave {

template <int D>
EnergyLedger<D>::EnergyLedger(UpdatedLagrangianSph<D>& system)
    : system_(system),
      series_("t [s]", {"kinetic [J]", "strain [J]", "internal [J]", "load_work [J]", "viscous_dissipation [J]",
                        "artificial_stress_work [J]", "balance [J]", "zigzag [-]", "min_spacing_ratio [-]"}) {}

template <int D>
void EnergyLedger<D>::observe(const StateView& state) {
  const Vector& y = state.displacement;  // a first-order integrator's view: the whole state
  const UpdatedLagrangianSphEnergy e = system_.energy(y);
  const ZeroEnergyModeIndicator z = system_.zeroEnergyModes(y);
  series_.append(state.time, {e.kinetic, e.strain, e.internal, e.loadWork, e.viscousDissipation,
                              e.artificialStressWork, e.balance(), z.zigzag, z.minimumSpacingRatio});
}

template <int D>
Real EnergyLedger<D>::largestBalanceDrift() const {
  if (series_.rows() == 0) return 0;
  const std::vector<Real> balance = series_.column(Balance);
  const Real scale = std::max(series_.column(Kinetic).front() + series_.column(Strain).front(),
                              std::numeric_limits<Real>::min());
  Real drift = 0;
  for (Real b : balance) drift = std::max(drift, std::abs(b - balance.front()));
  return drift / scale;
}

template <int D>
Real EnergyLedger<D>::largestZigzag() const {
  const std::vector<Real> z = series_.column(Zigzag);
  return z.empty() ? 0 : *std::max_element(z.begin(), z.end());
}

template <int D>
Real EnergyLedger<D>::firstTimeZigzagAbove(Real threshold) const {
  const std::vector<Real> z = series_.column(Zigzag);
  for (std::size_t k = 0; k < z.size(); ++k)
    if (z[k] > threshold) return series_.times()[k];
  return -1;
}

template class EnergyLedger<1>;
template class EnergyLedger<2>;
template class EnergyLedger<3>;

}  // namespace mfwave
