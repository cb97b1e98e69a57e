#include "wiring/EnergyLedger.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace mfwave {

template <int D>
EnergyLedger<D>::EnergyLedger(UpdatedLagrangianSph<D>& system, Real blowUpLimit)
    : system_(system),
      blowUpLimit_(blowUpLimit),
      series_("t [s]", {"kinetic [J]", "strain [J]", "internal [J]", "load_work [J]", "viscous_dissipation [J]",
                        "artificial_stress_work [J]", "balance [J]", "zigzag [-]", "min_spacing_ratio [-]"}) {}

template <int D>
void EnergyLedger<D>::observe(const StateView& state) {
  const Vector& y = state.displacement;  // a first-order integrator's view: the whole state
  const UpdatedLagrangianSphEnergy e = system_.energy(y);
  const ZeroEnergyModeIndicator z = system_.zeroEnergyModes(y);
  series_.append(state.time, {e.kinetic, e.strain, e.internal, e.loadWork, e.viscousDissipation,
                              e.artificialStressWork, e.balance(), z.zigzag, z.minimumSpacingRatio});
  if (series_.rows() == 1) {
    initialEnergy_ = e.kinetic + e.strain;
    initialBalance_ = e.balance();
  }
  const Real drift = std::abs(e.balance() - initialBalance_);
  if (initialEnergy_ > 0 && !(drift <= blowUpLimit_ * initialEnergy_)) throwBlowUp(state, drift / initialEnergy_);
}

template <int D>
void EnergyLedger<D>::saveState(StateArchive& archive) const {
  StateArchive series = archive.section("series");
  series_.saveState(series);
  archive.put("initial", std::vector<Real>{initialEnergy_, initialBalance_});
}

template <int D>
void EnergyLedger<D>::restoreState(const StateArchive& archive) {
  series_.restoreState(archive.section("series"));
  const std::vector<Real>& initial = archive.numbers("initial", 2);
  initialEnergy_ = initial[0];
  initialBalance_ = initial[1];
}

template <int D>
void EnergyLedger<D>::throwBlowUp(const StateView& state, Real drift) const {
  const Vector& y = state.displacement;
  const auto& layout = system_.layout();
  Index fastest = 0;
  Real largest = -1;  // squared speed; a NaN speed is taken as the fastest
  for (Index i = 0; i < layout.particles; ++i) {
    Real v2 = 0;
    for (int a = 0; a < D; ++a) v2 += y[layout.velocity(i, a)] * y[layout.velocity(i, a)];
    if (!(v2 <= largest)) {
      largest = v2;
      fastest = i;
      if (std::isnan(v2)) break;
    }
  }
  const Real speed = std::sqrt(largest);
  std::ostringstream s;
  s << "updated-Lagrangian SPH blew up at step " << state.step << ", t = " << state.time
    << ": the energy balance (kinetic + internal - load work) has moved by " << drift
    << " times the initial energy (limit " << blowUpLimit_ << "); fastest particle " << fastest << " at (";
  for (int a = 0; a < D; ++a) s << (a > 0 ? ", " : "") << y[layout.position(fastest, a)];
  s << ") with speed " << speed
    << ". Usual causes: no artificial viscosity, the tensile instability (artificial stress off), or a fixed "
       "step above the method's criteria";
  throw InstabilityError(s.str(), state.step, state.time, static_cast<long>(fastest));
}

template <int D>
Real EnergyLedger<D>::largestBalanceDrift() const {
  if (series_.rows() == 0) return 0;
  const Real scale = std::max(initialEnergy_, std::numeric_limits<Real>::min());
  Real drift = 0;
  for (Real b : series_.column(Balance)) drift = std::max(drift, std::abs(b - initialBalance_));
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
