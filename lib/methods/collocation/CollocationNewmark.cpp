#include "methods/collocation/CollocationNewmark.hpp"


#include "core/Error.hpp"

namespace mfwave {

CollocationNewmark::CollocationNewmark(Real beta, Real gamma) : beta_(beta), gamma_(gamma) {
  if (!(beta > 0 && beta <= 0.5))
    throw InputError("integrator.newmark_beta",
                     "collocation Newmark needs 0 < beta <= 1/2 (beta = 0 is central_difference on the constrained "
                     "system)");
  if (!(gamma >= 0 && gamma <= 1)) throw InputError("integrator.newmark_gamma", "must lie in [0, 1]");
}

CollocationNewmark::~CollocationNewmark() = default;

void CollocationNewmark::initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) {
  constrained_ = dynamic_cast<ConstrainedCollocationSystem*>(&system);
  if (!constrained_) throw InputError("integrator", "collocation Newmark needs a ConstrainedCollocationSystem");
  bind(system, t0, u0, v0, dt);
  d_ = constrained_->coefficients(u0, t0);
  dv_ = constrained_->coefficientRates(v0, t0);
  da_ = constrained_->coefficientAccelerations(u0, t0);
  const CollocationSystem& s = constrained_->system();
  const SparseMatrix effective = s.S + (beta_ * dt * dt) * s.A;
  solver_.factorise(effective, "collocation Newmark: S + beta dt^2 A");
  u_ = constrained_->interiorValues(d_);
  v_ = constrained_->interiorValues(dv_);
  a_ = constrained_->interiorValues(da_);
}

void CollocationNewmark::step() {
  requireInitialised();
  const CollocationSystem& s = constrained_->system();
  dPredict_ = d_ + dt_ * dv_ + (dt_ * dt_ * (0.5 - beta_)) * da_;
  vPredict_ = dv_ + (dt_ * (1 - gamma_)) * da_;
  advanceClock();
  rhs_ = s.rhs(time_);
  rhs_.noalias() -= s.A * dPredict_;
  solver_.solve(rhs_, da_);
  d_ = dPredict_ + (beta_ * dt_ * dt_) * da_;
  dv_ = vPredict_ + (gamma_ * dt_) * da_;
  u_ = constrained_->interiorValues(d_);
  v_ = constrained_->interiorValues(dv_);
  a_ = constrained_->interiorValues(da_);
}

}  // namespace mfwave
