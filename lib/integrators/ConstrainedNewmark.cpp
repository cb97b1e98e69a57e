#include "integrators/ConstrainedNewmark.hpp"

#include "core/Error.hpp"

namespace mfwave {

ConstrainedNewmark::ConstrainedNewmark(Real beta, Real gamma) : beta_(beta), gamma_(gamma) {
  if (!(beta > 0 && beta <= 0.5))
    throw InputError("integrator.newmark_beta",
                     "Newmark on a constrained system needs 0 < beta <= 1/2 (beta = 0 is central_difference on its "
                     "explicit form)");
  if (!(gamma >= 0 && gamma <= 1)) throw InputError("integrator.newmark_gamma", "must lie in [0, 1]");
}

ConstrainedNewmark::~ConstrainedNewmark() = default;

void ConstrainedNewmark::initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) {
  constrained_ = dynamic_cast<ConstrainedSecondOrderSystem*>(&system);
  if (!constrained_) throw InputError("integrator", "this Newmark needs a constrained system (S d'' + A d = b)");
  bind(system, t0, u0, v0, dt);
  d_ = constrained_->coefficients(u0, t0);
  dv_ = constrained_->coefficientRates(v0, t0);
  da_ = constrained_->coefficientAccelerations(u0, t0);
  const SparseMatrix effective = constrained_->coefficientMass() + (beta_ * dt * dt) * constrained_->coefficientStiffness();
  solver_.factorise(effective, "constrained Newmark: S + beta dt^2 A");
  u_ = constrained_->observedValues(d_);
  v_ = constrained_->observedValues(dv_);
  a_ = constrained_->observedValues(da_);
}

void ConstrainedNewmark::step() {
  requireInitialised();
  dPredict_ = d_ + dt_ * dv_ + (dt_ * dt_ * (0.5 - beta_)) * da_;
  vPredict_ = dv_ + (dt_ * (1 - gamma_)) * da_;
  advanceClock();
  rhs_ = constrained_->coefficientLoad(time_);
  rhs_.noalias() -= constrained_->coefficientStiffness() * dPredict_;
  solver_.solve(rhs_, da_);
  d_ = dPredict_ + (beta_ * dt_ * dt_) * da_;
  dv_ = vPredict_ + (gamma_ * dt_) * da_;
  u_ = constrained_->observedValues(d_);
  v_ = constrained_->observedValues(dv_);
  a_ = constrained_->observedValues(da_);
}

void ConstrainedNewmark::saveHistory(StateArchive& archive) const {
  archive.put("d", d_);
  archive.put("d_rate", dv_);
  archive.put("d_acceleration", da_);
}

void ConstrainedNewmark::restoreHistory(const StateArchive& archive) {
  archive.get("d", d_);
  archive.get("d_rate", dv_);
  archive.get("d_acceleration", da_);
}

}  // namespace mfwave
