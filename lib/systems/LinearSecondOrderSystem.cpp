#include "systems/LinearSecondOrderSystem.hpp"

#include "core/Error.hpp"
#include "solvers/FactorisedMatrix.hpp"
#include "systems/ImplicitDampingSolver.hpp"

#include <cmath>
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
  diagonalMass_ = isDiagonal(mass_);
  if (diagonalMass_) {
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

void LinearSecondOrderSystem::prepareMassSolve() {
  if (diagonalMass_ && inverseMassDiagonal_.size() == 0)
    throw InputError("mass", "explicit integration needs a lumped mass matrix with positive entries");
  if (!diagonalMass_ && !massSolver_) {
    auto solver = std::make_shared<FactorisedMatrix>();
    solver->factorise(mass_, "the consistent mass matrix M (explicit integration solves M a = f - C v - K u)");
    massSolver_ = std::move(solver);
  }
}

Vector LinearSecondOrderSystem::solveMass(const Vector& b) {
  if (b.size() != size()) throw InputError("mass", "solveMass: the vector has " + std::to_string(b.size()) +
                                                       " entries, the system " + std::to_string(size()));
  prepareMassSolve();
  return diagonalMass_ ? Vector(inverseMassDiagonal_.cwiseProduct(b)) : massSolver_->solve(b);
}

void LinearSecondOrderSystem::acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v,
                                           Eigen::Ref<Vector> a) {
  prepareMassSolve();
  force(t, work_);
  subtractStiffnessProduct(u, work_);
  if (hasDamping()) work_.noalias() -= damping_ * v;
  if (diagonalMass_) {
    a.noalias() = inverseMassDiagonal_.cwiseProduct(work_);
  } else {
    massSolver_->solve(work_, massSolution_);
    a = massSolution_;
  }
}

Real LinearSecondOrderSystem::kineticEnergy(const Vector& v) const { return 0.5 * v.dot(mass_ * v); }
void LinearSecondOrderSystem::subtractStiffnessProduct(Eigen::Ref<const Vector> u, Vector& out) {
  // Row-major rows are independent dot products: one thread per block of rows, each row summed in
  // the same order whatever the thread count, so the result is bitwise the same on 1 or 16 threads
  // (a column-major product scatters into shared rows and cannot be split that way). The copy is
  // made on the first explicit step, so implicit integrators never pay for it.
  if (stiffnessRows_.rows() != stiffness_.rows() || stiffnessRows_.nonZeros() != stiffness_.nonZeros()) {
    stiffnessRows_ = stiffness_;
    stiffnessRows_.makeCompressed();
  }
  const auto rows = static_cast<long>(stiffnessRows_.rows());
  const int* outer = stiffnessRows_.outerIndexPtr();
  const int* inner = stiffnessRows_.innerIndexPtr();
  const Real* values = stiffnessRows_.valuePtr();
  const Real* x = u.data();
  Real* y = out.data();
#pragma omp parallel for schedule(static) if (stiffnessRows_.nonZeros() > 100000)
  for (long r = 0; r < rows; ++r) {
    Real sum = 0;
    for (int k = outer[r]; k < outer[r + 1]; ++k) sum += values[k] * x[inner[k]];
    y[r] -= sum;
  }
}

Real LinearSecondOrderSystem::strainEnergy(const Vector& u) const { return 0.5 * u.dot(stiffness_ * u); }

Real LinearSecondOrderSystem::dampingPower(const Vector& v) const {
  return hasDamping() ? v.dot(damping_ * v) : 0.0;
}

Vector LinearSecondOrderSystem::lumpedMass() const {
  if (!diagonalMass_ || mass_.nonZeros() != size())
    throw InputError("mass", "needs a diagonal (lumped) mass matrix");
  return mass_.diagonal();
}

Vector LinearSecondOrderSystem::stiffnessAbsoluteRowSums() const {
  Vector sums = Vector::Zero(size());
  for (int c = 0; c < stiffness_.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(stiffness_, c); it; ++it) sums[it.row()] += std::abs(it.value());
  return sums;
}

std::unique_ptr<CentredDampingSolve> LinearSecondOrderSystem::centredDamping(
    Real dt, const std::vector<Index>& prescribedDofs) const {
  auto solver = std::make_unique<ImplicitDampingSolver>();
  solver->factorise(*this, dt, prescribedDofs);
  return solver;
}

}  // namespace mfwave
