#include "integrators/PrescribedDisplacement.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {

PrescribedDisplacement::PrescribedDisplacement(std::vector<Index> dofs, Function g)
    : dofs_(std::move(dofs)), g_(std::move(g)) {
  if (!dofs_.empty() && !g_) throw InputError("prescribed_displacement", "g is empty but dofs are given");
  std::vector<Index> sorted = dofs_;
  std::sort(sorted.begin(), sorted.end());
  if (!sorted.empty() && sorted.front() < 0)
    throw InputError("prescribed_displacement", "dof " + std::to_string(sorted.front()) + " is negative");
  const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
  if (repeated != sorted.end())
    throw InputError("prescribed_displacement", "dof " + std::to_string(*repeated) + " is given twice");
}

void PrescribedDisplacement::evaluate(Real t, Vector& values) const {
  const Index count = static_cast<Index>(dofs_.size());
  values.setZero(count);
  g_(t, values);
  if (values.size() != count)
    throw InputError("prescribed_displacement", "g(t = " + std::to_string(t) + ") returned " +
                                                    std::to_string(values.size()) + " values for " +
                                                    std::to_string(count) + " dofs");
  if (!values.allFinite())
    throw InputError("prescribed_displacement", "g(t = " + std::to_string(t) + ") is not finite");
}

void PrescribedDisplacement::bind(Index systemSize, Real t0, Real dt, Vector& u0) {
  for (Index dof : dofs_)
    if (dof >= systemSize)
      throw InputError("prescribed_displacement", "dof " + std::to_string(dof) + " is out of range for a system of " +
                                                      std::to_string(systemSize) + " unknowns");
  evaluate(t0, current_);
  evaluate(t0 + dt, next_);
  Real scale = current_.lpNorm<Eigen::Infinity>(), mismatch = 0;
  for (size_t i = 0; i < dofs_.size(); ++i) {
    scale = std::max(scale, std::abs(u0[dofs_[i]]));
    mismatch = std::max(mismatch, std::abs(u0[dofs_[i]] - current_[static_cast<Index>(i)]));
  }
  if (mismatch > 1e-12 * scale)
    throw InputError("initial_displacement", "u0 differs from the prescribed g(t0) by " + std::to_string(mismatch) +
                                                 " at a prescribed dof (the motion would start with a jump)");
  scatter(current_, u0);
  acceleration_.setZero(current_.size());
  velocity_.setZero(current_.size());
}

void PrescribedDisplacement::imposeHalfStepVelocity(const Vector& u, Real dt, Vector& vHalf) const {
  for (size_t i = 0; i < dofs_.size(); ++i) vHalf[dofs_[i]] = (next_[static_cast<Index>(i)] - u[dofs_[i]]) / dt;
}

void PrescribedDisplacement::imposeDisplacement(Vector& u) const { scatter(next_, u); }

void PrescribedDisplacement::advance(Real tAfter, Real dt) {
  evaluate(tAfter, after_);
  acceleration_ = (after_ - 2 * next_ + current_) / (dt * dt);
  velocity_ = (after_ - current_) / (2 * dt);
  current_.swap(next_);
  next_.swap(after_);
}

void PrescribedDisplacement::scatter(const Vector& values, Vector& full) const {
  for (size_t i = 0; i < dofs_.size(); ++i) full[dofs_[i]] = values[static_cast<Index>(i)];
}

void PrescribedDisplacement::saveState(StateArchive& archive) const {
  archive.put("current", current_);
  archive.put("next", next_);
  archive.put("acceleration", acceleration_);
  archive.put("velocity", velocity_);
}

void PrescribedDisplacement::restoreState(const StateArchive& archive) {
  archive.get("current", current_);
  archive.get("next", next_);
  archive.get("acceleration", acceleration_);
  archive.get("velocity", velocity_);
}

}  // namespace mfwave
