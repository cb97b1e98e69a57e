#pragma once
// The energy ledger of an updated-Lagrangian SPH run, recorded every output step: kinetic, strain
// and internal energy, work done by loads and constraints, energy removed by the artificial
// viscosity and work of the artificial stress, the balance kinetic + internal - load work, and the
// zero-energy-mode indicators (zig-zag, smallest spacing), so a user sees when the tensile
// instability or hourglass modes start. It observes the integrator directly (the whole state y).
//
// It is also the run's blow-up guard: the method conserves kinetic + internal - load work (the
// ledger's balance) to the time integrator's error, so a balance that has moved by more than
// `blowUpLimit` times the initial kinetic + strain energy (default 1: all of it) is an instability,
// not an error to report at the end. observe() then throws InstabilityError with the step, the
// time and the fastest particle, and the driver stops at once with its outputs unwritten.

#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "observers/Observer.hpp"
#include "observers/TimeSeries.hpp"

namespace mfwave {

template <int D>
class EnergyLedger : public Observer {
 public:
  // Column indices of series() (time excluded).
  enum Column : std::size_t {
    Kinetic, Strain, Internal, LoadWork, ViscousDissipation, ArtificialStressWork, Balance, Zigzag,
    MinimumSpacingRatio
  };

  explicit EnergyLedger(UpdatedLagrangianSph<D>& system, Real blowUpLimit = 1);
  void observe(const StateView& state) override;
  // The rows so far and the first row's energy and balance (the blow-up guard's reference).
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

  const TimeSeries& series() const { return series_; }
  // Kinetic + strain energy of the first row (0 before it): the scale of every fraction reported.
  Real initialEnergy() const { return initialEnergy_; }
  // Largest |balance(t) - balance(0)| / max(kinetic + strain at t = 0, tiny), over the rows so far.
  Real largestBalanceDrift() const;
  // Largest zig-zag indicator and the time it was first above `threshold` (-1 if never).
  Real largestZigzag() const;
  Real firstTimeZigzagAbove(Real threshold) const;

 private:
  [[noreturn]] void throwBlowUp(const StateView& state, Real drift) const;

  UpdatedLagrangianSph<D>& system_;
  Real blowUpLimit_;
  Real initialEnergy_ = 0;   // kinetic + strain of the first row
  Real initialBalance_ = 0;  // balance of the first row
  TimeSeries series_;
};

extern template class EnergyLedger<1>;
extern template class EnergyLedger<2>;
extern template class EnergyLedger<3>;

}  // namespace mfwave
