#include "analysis/StableTimeStep.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <limits>
#include <random>

namespace mfwave {

Real StableTimeStep::estimate() const {
  return powerIterationOmegaSquared > 0 ? 2 / std::sqrt(powerIterationOmegaSquared)
                                        : std::numeric_limits<Real>::infinity();
}

Real StableTimeStep::safe() const {
  return gershgorinOmegaSquared > 0 ? 2 / std::sqrt(gershgorinOmegaSquared) : std::numeric_limits<Real>::infinity();
}

namespace {

Vector inverseLumpedMass(const LinearSecondOrderSystem& system) {
  const Vector mass = system.mass().diagonal();
  if (system.mass().nonZeros() != system.size() || !(mass.array() > 0).all())
    throw InputError("mass", "the stable-step estimate needs a diagonal mass matrix with positive entries");
  return mass.cwiseInverse();
}

// Gershgorin: every eigenvalue of M^{-1} K lies in a disc around a row's diagonal.
Real gershgorinOmegaSquared(const LinearSecondOrderSystem& system, const Vector& inverseMass) {
  const SparseMatrix& k = system.stiffness();
  Vector rowSums = Vector::Zero(system.size());
  for (int c = 0; c < k.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(k, c); it; ++it) rowSums[it.row()] += std::abs(it.value());
  return rowSums.cwiseProduct(inverseMass).maxCoeff();
}

}  // namespace

Real centralDifferenceSafeStep(const LinearSecondOrderSystem& system) {
  StableTimeStep bound;
  bound.gershgorinOmegaSquared = gershgorinOmegaSquared(system, inverseLumpedMass(system));
  return bound.safe();
}

StableTimeStep centralDifferenceStableStep(const LinearSecondOrderSystem& system, Real relativeTolerance,
                                           int maximumIterations) {
  const Index n = system.size();
  const Vector inverseMass = inverseLumpedMass(system);
  const SparseMatrix& k = system.stiffness();
  StableTimeStep result;
  result.gershgorinOmegaSquared = gershgorinOmegaSquared(system, inverseMass);

  // Power iteration; the start has components along every mode (random signs), and the quotient
  // x.(M^-1 K x) / x.x tends to the dominant eigenvalue.
  std::mt19937_64 random(20261121);
  std::uniform_real_distribution<Real> uniform(-1, 1);
  Vector x(n), y(n);
  for (Index i = 0; i < n; ++i) x[i] = uniform(random);
  x.normalize();
  Real previous = 0;
  for (int iteration = 1; iteration <= maximumIterations; ++iteration) {
    y.noalias() = k * x;
    y = inverseMass.cwiseProduct(y);
    const Real quotient = x.dot(y);
    const Real norm = y.norm();
    result.iterations = iteration;
    result.powerIterationOmegaSquared = quotient;
    if (norm == 0) break;  // K x = 0: no stiffness at all
    x = y / norm;
    if (iteration > 1 && std::abs(quotient - previous) <= relativeTolerance * std::abs(quotient)) {
      result.converged = true;
      break;
    }
    previous = quotient;
  }
  return result;
}

}  // namespace mfwave
