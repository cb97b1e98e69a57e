#include "systems/LinearSecondOrderSystem.hpp"

#include "core/Error.hpp"

#include <string>

namespace mfwave {
namespace {

bool isDiagonal(const SparseMatrix& m) {
  for (int k = 0; k < m.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(m, k); it; ++it)
      if (it.row() != it.col() && it.value() != 0) return false;
  return true;
}

}  // namespace

LinearSecondOrderSystem::LinearSecondOrderSystem(SparseMatrix mass, SparseMatrix damping,
                                                 SparseMatrix stiffness, ForceFunction force)
    : force_(std::move(force)) {
  // Eigen 3.4's SparseMatrix has no move constructor: std::move would deep-copy. swap hands the
  // storage over, so an assembled operator is never held twice.
  mass_.swap(mass);
  stiffness_.swap(stiffness);
  const Index n = stiffness_.rows();
  if (stiffness_.cols() != n) throw InputError("stiffness", "must be square");
  if (mass_.rows() != n || mass_.cols() != n)
    throw InputError("mass", "must be " + std::to_string(n) + " x " + std::to_string(n) + " like the stiffness");
  adoptDamping(damping);
  mass_.makeCompressed();
  stiffness_.makeCompressed();
  if (isDiagonal(mass_)) {
    Vector diagonal = mass_.diagonal();
    if ((diagonal.array() > 0).all()) inverseMassDiagonal_ = diagonal.cwiseInverse();
  }
  work_.resize(n);
}

void LinearSecondOrderSystem::setDamping(SparseMatrix damping) { adoptDamping(damping); }

void LinearSecondOrderSystem::adoptDamping(SparseMatrix& damping) {
  const Index n = stiffness_.rows();
  if (damping.size() != 0 && (damping.rows() != n || damping.cols() != n))
    throw InputError("damping", "must be empty or " + std::to_string(n) + " x " + std::to_string(n));
  damping_.swap(damping);
  if (damping_.size() == 0) damping_.resize(n, n);
  damping_.makeCompressed();
}

void LinearSecondOrderSystem::force(Real t, Vector& f) const {
  f.setZero(size());
  if (force_) force_(t, f);
}

void LinearSecondOrderSystem::acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v,
                                           Eigen::Ref<Vector> a) {
  if (inverseMassDiagonal_.size() == 0)
    throw InputError("mass", "explicit integration needs a diagonal (lumped) mass matrix with positive entries");
  force(t, work_);
  work_.noalias() -= stiffness_ * u;
  if (hasDamping()) work_.noalias() -= damping_ * v;
  a.noalias() = inverseMassDiagonal_.cwiseProduct(work_);
}

Real LinearSecondOrderSystem::kineticEnergy(const Vector& v) const { return 0.5 * v.dot(mass_ * v); }
Real LinearSecondOrderSystem::strainEnergy(const Vector& u) const { return 0.5 * u.dot(stiffness_ * u); }

}  // namespace mfwave
