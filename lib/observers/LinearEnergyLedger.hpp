#pragma once
// The energy ledger of a linear system M u'' + C u' + K u = f(t), and the run's guard against
// growth: kinetic 1/2 v^T M v, strain 1/2 u^T K u, the work of the loads int f . du, the energy
// the dashpots took (int v^T C v dt) and the energy a velocity filter took (reported by the
// filter), and their balance  kinetic + strain - load work + dashpot loss + filter loss, which a
// stable method with a symmetric K keeps at its initial value to the integrator's error.
//
// Two stops, both InstabilityError (exit 3) naming the step, the time, the fastest particle and
// the cause:
// - growth after the loads went quiet: from then on a passive system (symmetric positive K,
//   dashpots, filters) can only lose energy, so an energy envelope above `growthFactor` times its
//   smallest value since then is an instability, however slow. The message gives the growth rate.
//   The envelope is the largest kinetic + |strain| over the last `envelopeWindow` seconds: for a
//   non-symmetric K the pair exchanges energy with the antisymmetric part within a period and can
//   dip far below its envelope at one instant. Values below `floor` times the largest energy seen
//   are round-off and are not judged.
// - a balance that moved by more than `balanceLimit` times the largest energy, judged once the
//   loads are quiet: energy created by the discretisation itself (a non-symmetric K exchanges
//   energy through its antisymmetric part, which 1/2 u^T K u does not see).
//
// Add it to the TimeLoop with every = 1: the load work and the dashpot loss are integrated over
// every step (trapezoidal rule, second order like the integrators). The energies themselves cost
// one product with K and are evaluated every `checkEvery` observations.

#include "observers/Observer.hpp"
#include "observers/TimeSeries.hpp"

#include <deque>
#include <limits>
#include <string>

namespace mfwave {

class LinearOperatorSystem;

struct LinearEnergyLedgerOptions {
  // Every load is zero after this time (TimeFunction::quietAfter). Both stops are judged only
  // after it: +infinity (a load that never ends) records the ledger and stops nothing.
  Real quietAfter = std::numeric_limits<Real>::infinity();
  Real growthFactor = 100;
  // Seconds over which the envelope is taken: at least half the slowest period that matters
  // (0: the energy at each check).
  Real envelopeWindow = 0;
  Real floor = 1e-24;
  // <= 0 turns the balance check off (e.g. prescribed displacements whose reactions do work the
  // ledger does not see).
  Real balanceLimit = 1;
  long checkEvery = 10;
  int components = 1;  // unknowns per particle, to name the particle
  // Appended to the stop message: what in this method is the likely cause of growth.
  std::string likelyCause;
  // false: record the first stop message (growthMessage()) and run on, to show a blow-up on purpose.
  bool stop = true;
};

class LinearEnergyLedger : public Observer {
 public:
  enum Column : std::size_t { Kinetic, Strain, LoadWork, DashpotLoss, FilterLoss, Balance };

  LinearEnergyLedger(const LinearOperatorSystem& system, LinearEnergyLedgerOptions options);

  void begin(const StateView& state) override;
  void observe(const StateView& state) override;
  void end(const StateView& state) override;

  // 1/2 v^T M v, for a filter to report what it removes.
  Real kineticEnergy(const Vector& v) const;
  // Energy a velocity filter removed in the last step (before minus after).
  void addFilterLoss(Real energy) { filterLoss_ += energy; }

  // One row per check: t, kinetic, strain, load work, dashpot loss, filter loss, balance.
  const TimeSeries& series() const { return series_; }
  // Largest kinetic + |strain| over the checks.
  Real largestEnergy() const { return largestEnergy_; }
  // The last check's kinetic + |strain| over the largest.
  Real finalEnergyFraction() const;
  // Largest |balance - balance at the start| over the largest energy, over the checks so far.
  Real largestBalanceDrift() const;
  // With options.stop = false: the message the run would have stopped with (empty if none).
  const std::string& growthMessage() const { return growthMessage_; }

  // The rows, the integrals, the previous observation and the envelope's history.
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

 private:
  void integrate(const StateView& state);
  void check(const StateView& state);
  // Throws InstabilityError, or records the message when options.stop is false.
  void stop(const StateView& state, const std::string& why);

  const LinearOperatorSystem& system_;
  LinearEnergyLedgerOptions options_;
  TimeSeries series_;
  // previous observation: time, displacement, load, dashpot power v^T C v
  Real previousTime_ = 0;
  Vector previousDisplacement_, previousForce_, force_;
  Real previousDashpotPower_ = 0;
  Real loadWork_ = 0, dashpotLoss_ = 0, filterLoss_ = 0;
  Real initialBalance_ = 0;
  Real largestEnergy_ = 0, largestAbsoluteDrift_ = 0, lastEnergy_ = 0;
  // checks since the loads went quiet within the envelope window: (time, energy)
  std::deque<std::pair<Real, Real>> recent_;
  // smallest envelope since the loads went quiet, and when
  Real quietMinimum_ = std::numeric_limits<Real>::infinity(), quietMinimumTime_ = 0;
  long observations_ = 0;
  long lastCheckedStep_ = -1;
  std::string growthMessage_;
};

}  // namespace mfwave
