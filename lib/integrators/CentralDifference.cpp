#include "integrators/CentralDifference.hpp"

#include "core/Error.hpp"
#include "systems/LinearOperatorSystem.hpp"
#include "systems/ParallelVector.hpp"
#include "integrators/PrescribedDisplacement.hpp"

namespace mfwave {

CentralDifference::CentralDifference(Damping damping) : damping_(damping) {}
CentralDifference::~CentralDifference() = default;

void CentralDifference::setDamping(Damping damping) {
  if (system_) throw InputError("damping", "must be chosen before initialise()");
  damping_ = damping;
}

void CentralDifference::setPrescribedDisplacement(std::vector<Index> dofs, std::function<void(Real t, Vector& values)> g) {
  if (system_) throw InputError("prescribed_displacement", "must be set before initialise()");
  if (dofs.empty())
    prescribed_.reset();
  else
    prescribed_ = std::make_unique<PrescribedDisplacement>(std::move(dofs), std::move(g));
}

std::vector<std::string> CentralDifference::dampingNames() { return {"implicit", "predictor"}; }

CentralDifference::Damping CentralDifference::dampingFromName(const std::string& name) {
  if (name == "implicit") return Damping::implicit;
  if (name == "predictor") return Damping::predictor;
  throw InputError("integrator.damping", "unknown central-difference damping '" + name + "'; valid: implicit, predictor");
}

void CentralDifference::initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0,
                                   Real dt) {
  system_ = nullptr;  // a failed initialise leaves the integrator unbound
  Vector start = u0;
  if (prescribed_) {
    checkInitialState(system, t0, u0, v0, dt);  // sizes first, so that the dofs can be checked
    prescribed_->bind(system.size(), t0, dt, start);
  }
  const auto* linear = dynamic_cast<const LinearOperatorSystem*>(&system);
  dampingSolver_.reset();
  if (damping_ == Damping::implicit && linear && linear->hasDamping())
    dampingSolver_ = linear->centredDamping(dt, prescribed_ ? prescribed_->dofs() : std::vector<Index>{});
  bind(system, t0, start, v0, dt);
  // v0 is exact here: a_0 needs neither the predictor nor the solve (a_0 also satisfies
  // (M + dt/2 C) a_0 = f_0 - K u_0 - C v_{-1/2}, so both damping paths start alike).
  system.acceleration(t0, u_, v_, a_);
  // Half a step back, so that the first full step is the Taylor start u_1 = u_0 + dt v_0 + dt^2/2 a_0.
  vHalf_ = v_ - 0.5 * dt_ * a_;
  if (system.dependsOnVelocity() && !dampingSolver_) vPredict_.resize(u0.size());
}

void CentralDifference::step() {
  requireInitialised();
  const Index n = vHalf_.size();
  addScaled(vHalf_, dt_, a_);  // v_{n+1/2} = v_{n-1/2} + dt a_n (Ding-Long-Wu eq. 23 / 32)
  if (filter_) {
    filter_(dt_, vHalf_);  // conservative smoothing, Ding-Long-Wu eq. (33)
    if (vHalf_.size() != n)
      throw InputError("velocity_filter", "changed the velocity's size from " + std::to_string(n) + " to " +
                                              std::to_string(vHalf_.size()));
  }
  if (prescribed_) prescribed_->imposeHalfStepVelocity(u_, dt_, vHalf_);  // Ding-Long-Wu eq. (30)
  addScaled(u_, dt_, vHalf_);  // u_{n+1} = u_n + dt v_{n+1/2}
  if (prescribed_) prescribed_->imposeDisplacement(u_);  // exactly g_{n+1}, not g_{n+1} + round-off
  advanceClock();
  closeStep();
}

void CentralDifference::saveHistory(StateArchive& archive) const {
  archive.put("v_half", vHalf_);
  if (prescribed_) {
    StateArchive section = archive.section("prescribed");
    prescribed_->saveState(section);
  }
}

void CentralDifference::restoreHistory(const StateArchive& archive) {
  archive.get("v_half", vHalf_);
  if (prescribed_) prescribed_->restoreState(archive.section("prescribed"));
}

void CentralDifference::closeStep() {
  // g_{n+2} at t0 + (n+2) dt, on the grid like advanceClock's times
  if (prescribed_) prescribed_->advance(t0_ + static_cast<Real>(steps_ + 1) * dt_, dt_);
  if (dampingSolver_) {
    // Ding-Long-Wu eq. (32): (M + dt/2 C) a_{n+1} = f_{n+1} - K u_{n+1} - C v_{n+1/2}
    dampingSolver_->acceleration(time_, u_, vHalf_, prescribed_ ? prescribed_->acceleration() : noPrescribedAcceleration_,
                                 a_);
    assignSum(v_, vHalf_, 0.5 * dt_, a_);
  } else {
    closeHalfStep(vHalf_, vPredict_);  // predictor (if needed), a_{n+1}, v_{n+1}
  }
  if (prescribed_) {
    prescribed_->scatter(prescribed_->acceleration(), a_);
    prescribed_->scatter(prescribed_->velocity(), v_);
  }
}

}  // namespace mfwave
