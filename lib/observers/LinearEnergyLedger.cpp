#include "observers/LinearEnergyLedger.hpp"

#include "core/Error.hpp"
#include "systems/LinearOperatorSystem.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mfwave {

LinearEnergyLedger::LinearEnergyLedger(const LinearOperatorSystem& system, LinearEnergyLedgerOptions options)
    : system_(system),
      options_(std::move(options)),
      series_("t [s]", {"kinetic [J]", "strain [J]", "load_work [J]", "dashpot_loss [J]", "filter_loss [J]",
                        "balance [J]"}) {
  if (!(options_.growthFactor > 1)) throw InputError("stability.energy_growth_factor", "must be greater than 1");
  if (!(options_.floor >= 0 && options_.floor < 1)) throw InputError("stability.energy_floor", "must be in [0, 1)");
  if (!(options_.envelopeWindow >= 0)) throw InputError("stability.energy_envelope_window", "must be >= 0");
  if (options_.checkEvery < 1) throw InputError("stability.energy_check_every", "must be at least 1");
  if (options_.components < 1) throw InputError("components", "must be at least 1");
}

Real LinearEnergyLedger::kineticEnergy(const Vector& v) const { return system_.kineticEnergy(v); }

Real LinearEnergyLedger::largestBalanceDrift() const {
  return largestEnergy_ > 0 ? largestAbsoluteDrift_ / largestEnergy_ : 0;
}

Real LinearEnergyLedger::finalEnergyFraction() const {
  return largestEnergy_ > 0 ? lastEnergy_ / largestEnergy_ : 0;
}

void LinearEnergyLedger::begin(const StateView& state) {
  previousTime_ = state.time;
  previousDisplacement_ = state.displacement;
  system_.force(state.time, previousForce_);
  previousDashpotPower_ = system_.dampingPower(state.velocity);
  observations_ = 0;
  check(state);
}

void LinearEnergyLedger::integrate(const StateView& state) {
  const Real dt = state.time - previousTime_;
  // Load work, trapezoidal: 1/2 (f_prev + f_now) . (u_now - u_prev); nothing once the loads are quiet.
  const bool quiet = previousTime_ > options_.quietAfter;
  if (!quiet) {
    system_.force(state.time, force_);
    // In place, no displacement-sized temporary: f_prev + f_now into previousForce_ and u - u_prev
    // into previousDisplacement_ (reset to u below while the loads act, unused once they are quiet).
    // The system's dot fixes the order of the sum (a distributed system's is its serial one).
    previousForce_ += force_;
    previousDisplacement_ = state.displacement - previousDisplacement_;
    loadWork_ += 0.5 * system_.dot(previousForce_, previousDisplacement_);
    previousForce_.swap(force_);
  }
  if (system_.hasDamping()) {
    const Real power = system_.dampingPower(state.velocity);
    dashpotLoss_ += 0.5 * dt * (previousDashpotPower_ + power);
    previousDashpotPower_ = power;
  }
  // The next step needs this displacement only while the loads still act.
  if (state.time <= options_.quietAfter) previousDisplacement_ = state.displacement;
  previousTime_ = state.time;
}

void LinearEnergyLedger::observe(const StateView& state) {
  integrate(state);
  if (++observations_ % options_.checkEvery == 0) check(state);
}

void LinearEnergyLedger::end(const StateView& state) {
  if (state.time > previousTime_) integrate(state);
  if (state.step != lastCheckedStep_) check(state);
}

void LinearEnergyLedger::check(const StateView& state) {
  lastCheckedStep_ = state.step;
  const Real kinetic = system_.kineticEnergy(state.velocity);
  const Real strain = system_.strainEnergy(state.displacement);
  const Real balance = kinetic + strain - loadWork_ + dashpotLoss_ + filterLoss_;
  series_.append(state.time, {kinetic, strain, loadWork_, dashpotLoss_, filterLoss_, balance});
  if (series_.rows() == 1) initialBalance_ = balance;
  const Real energy = kinetic + std::abs(strain);
  if (!std::isfinite(energy) || !std::isfinite(balance))
    stop(state, "the energy is not finite (kinetic " + std::to_string(kinetic) + ", strain " +
                    std::to_string(strain) + ")");
  lastEnergy_ = energy;
  largestEnergy_ = std::max(largestEnergy_, energy);
  const Real drift = std::abs(balance - initialBalance_);
  largestAbsoluteDrift_ = std::max(largestAbsoluteDrift_, drift);

  if (state.time > options_.quietAfter) {
    recent_.emplace_back(state.time, energy);
    while (recent_.front().first < state.time - options_.envelopeWindow) recent_.pop_front();
    Real envelope = 0;
    for (const auto& sample : recent_) envelope = std::max(envelope, sample.second);
    // The envelope is judged once its window lies wholly after the loads.
    const bool windowFull = state.time - options_.envelopeWindow >= options_.quietAfter;
    if (windowFull && envelope < quietMinimum_) {
      quietMinimum_ = envelope;
      quietMinimumTime_ = state.time;
    }
    if (windowFull && envelope > options_.floor * largestEnergy_ && envelope > options_.growthFactor * quietMinimum_) {
      const Real ratio = envelope / quietMinimum_;
      std::ostringstream why;
      why.precision(4);
      why << "the energy grew after the loads ended (t = " << options_.quietAfter
          << "): its envelope (largest kinetic + |strain| over " << options_.envelopeWindow << " s) = " << envelope
          << " is " << ratio << " times its minimum " << quietMinimum_ << " at t = " << quietMinimumTime_
          << " (amplitude growth rate " << std::log(ratio) / (2 * (state.time - quietMinimumTime_))
          << " per unit time; largest energy of the run " << largestEnergy_ << ")";
      stop(state, why.str());
    }
  }
  // Judged once the loads are quiet: while a load starts from rest the energy is tiny and the
  // balance's O(dt^2) start-up error is not small against it.
  if (state.time > options_.quietAfter && options_.balanceLimit > 0 && drift > options_.balanceLimit * largestEnergy_) {
    std::ostringstream why;
    why.precision(4);
    why << "the energy balance (kinetic + strain - load work + dashpot and filter losses) moved by "
        << drift / largestEnergy_ << " times the largest energy of the run (limit " << options_.balanceLimit
        << "): the discretisation creates energy";
    stop(state, why.str());
  }
}

void LinearEnergyLedger::stop(const StateView& state, const std::string& why) {
  if (!growthMessage_.empty()) return;
  const Vector& v = state.velocity;
  const int c = options_.components;
  Index fastest = 0;
  Real largest = -1;
  for (Index i = 0; i < v.size() / c; ++i) {
    const Real speed = v.segment(i * c, c).norm();
    if (!(speed <= largest)) {
      largest = speed;
      fastest = i;
      if (std::isnan(speed)) break;
    }
  }
  std::ostringstream message;
  message.precision(6);
  message << "energy growth at step " << state.step << ", t = " << state.time << ": " << why << "; fastest particle "
          << fastest << " (|v| = " << largest << ")";
  if (!options_.likelyCause.empty()) message << ". Likely cause: " << options_.likelyCause;
  growthMessage_ = message.str();
  if (options_.stop) throw InstabilityError(growthMessage_, state.step, state.time, static_cast<long>(fastest));
}

void LinearEnergyLedger::saveState(StateArchive& archive) const {
  series_.saveState(archive);
  archive.put("previous_displacement", previousDisplacement_);
  archive.put("previous_force", previousForce_);
  archive.put("force", force_);
  archive.put("scalars", std::vector<Real>{previousTime_, previousDashpotPower_, loadWork_, dashpotLoss_, filterLoss_,
                                           initialBalance_, largestEnergy_, largestAbsoluteDrift_, lastEnergy_,
                                           quietMinimum_, quietMinimumTime_, static_cast<Real>(observations_),
                                           static_cast<Real>(lastCheckedStep_)});
  std::vector<Real> recent;
  for (const auto& [time, energy] : recent_) {
    recent.push_back(time);
    recent.push_back(energy);
  }
  archive.put("recent", std::move(recent));
  archive.putText("growth_message", growthMessage_);
}

void LinearEnergyLedger::restoreState(const StateArchive& archive) {
  series_.restoreState(archive);
  archive.getResized("previous_displacement", previousDisplacement_);
  archive.getResized("previous_force", previousForce_);
  archive.getResized("force", force_);
  const std::vector<Real>& s = archive.numbers("scalars", 13);
  previousTime_ = s[0];
  previousDashpotPower_ = s[1];
  loadWork_ = s[2];
  dashpotLoss_ = s[3];
  filterLoss_ = s[4];
  initialBalance_ = s[5];
  largestEnergy_ = s[6];
  largestAbsoluteDrift_ = s[7];
  lastEnergy_ = s[8];
  quietMinimum_ = s[9];
  quietMinimumTime_ = s[10];
  observations_ = static_cast<long>(s[11]);
  lastCheckedStep_ = static_cast<long>(s[12]);
  const std::vector<Real>& recent = archive.get("recent");
  if (recent.size() % 2 != 0) throw InputError("--restart", "the checkpoint's energy envelope is not (time, energy) pairs");
  recent_.clear();
  for (std::size_t i = 0; i < recent.size(); i += 2) recent_.emplace_back(recent[i], recent[i + 1]);
  growthMessage_ = archive.text("growth_message");
}

}  // namespace mfwave
