#include "integrators/SplitLeapfrog.hpp"

#include "core/Error.hpp"

#include <string>

namespace mfwave {

void SplitLeapfrog::initialise(FirstOrderSystem& system, Real t0, const Vector& y0, Real dt) {
  auto* split = dynamic_cast<SplitFirstOrderSystem*>(&system);
  if (!split)
    throw InputError("integrator.name",
                     "leapfrog needs a system split into configuration and momentum (SplitFirstOrderSystem)");
  const Index nq = split->configurationSize();
  if (nq < 0 || nq > split->size())
    throw Error("leapfrog: the system's configuration size " + std::to_string(nq) + " is outside [0, " +
                std::to_string(split->size()) + "]");
  checkInitialState(system, t0, y0, dt);  // before rebinding anything
  split_ = split;
  nq_ = nq;
  ExplicitFirstOrderIntegrator::initialise(system, t0, y0, dt);  // calls start()
}

void SplitLeapfrog::start() {
  const Index np = y_.size() - nq_;
  configurationRate_.resize(nq_);
  pHalf_.resize(np);
  momentumRate_.resize(np);
  qStart_.resize(nq_);
  haveConfigurationRate_ = false;  // the first drift evaluates Q at q_0
  split_->momentumRate(time_, y_, momentumRate_);  // P_0
  evaluations_ += 0.5;
}

void SplitLeapfrog::advance(Real dt) {
  const Index np = y_.size() - nq_;
  const Real half = 0.5 * dt;
  auto q = y_.head(nq_);
  auto p = y_.tail(np);
  pHalf_ = p + half * momentumRate_;  // kick
  p = pHalf_;
  qStart_ = q;
  if (haveConfigurationRate_) q += half * configurationRate_;       // q* = q_n + dt/2 Q_{n-1/2}
  split_->configurationRate(time_ + half, y_, configurationRate_);  // at [q*; p_{n+1/2}]
  q = qStart_ + dt * configurationRate_;                             // drift
  haveConfigurationRate_ = true;
  p = pHalf_ + half * momentumRate_;                                 // predictor p*
  split_->momentumRate(time_ + dt, y_, momentumRate_);               // P_{n+1} at [q_{n+1}; p*]
  p = pHalf_ + half * momentumRate_;                                 // kick
  evaluations_ += 1;
}

void SplitLeapfrog::saveHistory(StateArchive& archive) const {
  archive.put("momentum_rate", momentumRate_);
  archive.put("configuration_rate", configurationRate_);
  archive.putScalar("have_configuration_rate", haveConfigurationRate_ ? 1 : 0);
}

void SplitLeapfrog::restoreHistory(const StateArchive& archive) {
  archive.get("momentum_rate", momentumRate_);
  archive.get("configuration_rate", configurationRate_);
  haveConfigurationRate_ = archive.scalar("have_configuration_rate") != 0;
}

}  // namespace mfwave
