#include "integrators/Newmark.hpp"

#include "core/Error.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <string>

namespace mfwave {

Newmark::Newmark(Real beta, Real gamma) : beta_(beta), gamma_(gamma) {
  if (!(beta >= 0 && beta <= 0.5))
    throw InputError("newmark.beta", "must lie in [0, 0.5] (got " + std::to_string(beta) + ")");
  if (!(gamma >= 0 && gamma <= 1))
    throw InputError("newmark.gamma", "must lie in [0, 1] (got " + std::to_string(gamma) + ")");
}

void Newmark::initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) {
  auto* linear = dynamic_cast<LinearSecondOrderSystem*>(&system);
  if (!linear) throw InputError("integrator", "Newmark needs a linear system M u'' + C u' + K u = f");
  bind(system, t0, u0, v0, dt);
  const Index n = system.size();
  linear_ = linear;
  uPredict_.resize(n);
  vPredict_.resize(n);
  aNext_.resize(n);

  // Initial acceleration from the equation of motion at t0: M a_0 = f(t0) - C v0 - K u0.
  {
    FactorisedMatrix mass;
    mass.factorise(linear->mass(), "Newmark: the mass matrix M (for the initial acceleration)");
    linear->force(t0, rhs_);
    rhs_.noalias() -= linear->stiffness() * u_;
    if (linear->hasDamping()) rhs_.noalias() -= linear->damping() * v_;
    mass.solve(rhs_, a_);
  }

  // Effective matrix of eq. 27, constant for a linear system and a fixed step: factorise once.
  SparseMatrix effective = linear->mass();
  if (linear->hasDamping()) effective += (gamma_ * dt_) * linear->damping();
  if (beta_ != 0) effective += (beta_ * dt_ * dt_) * linear->stiffness();
  effective_.factorise(effective, "Newmark: the effective matrix M + gamma dt C + beta dt^2 K (beta = " +
                                      std::to_string(beta_) + ", gamma = " + std::to_string(gamma_) +
                                      ", dt = " + std::to_string(dt_) + ")");
}

void Newmark::step() {
  requireInitialised();
  const Real dt2 = dt_ * dt_;
  // Predictors, eqs. 28-29.
  uPredict_ = u_ + dt_ * v_ + (dt2 * (0.5 - beta_)) * a_;
  vPredict_ = v_ + (dt_ * (1 - gamma_)) * a_;
  advanceClock();
  // Effective right-hand side, eq. 27.
  linear_->force(time_, rhs_);
  rhs_.noalias() -= linear_->stiffness() * uPredict_;
  if (linear_->hasDamping()) rhs_.noalias() -= linear_->damping() * vPredict_;
  effective_.solve(rhs_, aNext_);
  a_.swap(aNext_);
  // Correctors, eqs. 30-31.
  u_ = uPredict_ + (beta_ * dt2) * a_;
  v_ = vPredict_ + (gamma_ * dt_) * a_;
}

}  // namespace mfwave
