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

Vector inverseLumpedMass(const LinearOperatorSystem& system) {
  Vector mass;
  try {
    mass = system.lumpedMass();
  } catch (const InputError&) {
    mass.resize(0);  // not diagonal: the message below says what the estimate needs
  }
  if (mass.size() != system.size() || !(mass.array() > 0).all())
    throw InputError("mass", "the stable-step estimate needs a diagonal mass matrix with positive entries");
  return mass.cwiseInverse();
}

// Gershgorin: every eigenvalue of M^{-1} K lies in a disc around a row's diagonal.
Real gershgorinOmegaSquared(const LinearOperatorSystem& system, const Vector& inverseMass) {
  return system.stiffnessAbsoluteRowSums().cwiseProduct(inverseMass).maxCoeff();
}

}  // namespace

Real centralDifferenceSafeStep(const LinearOperatorSystem& system) {
  StableTimeStep bound;
  bound.gershgorinOmegaSquared = gershgorinOmegaSquared(system, inverseLumpedMass(system));
  return bound.safe();
}

StableTimeStep centralDifferenceStableStep(const LinearOperatorSystem& system, Real relativeTolerance,
                                           int maximumIterations) {
  const Index n = system.size();
  const Vector inverseMass = inverseLumpedMass(system);
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
    system.applyStiffness(x, y);
    y.array() *= inverseMass.array();
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

AccelerationSpectralRadius accelerationSpectralRadius(SecondOrderSystem& system, Real time, Real relativeTolerance,
                                                      int maximumIterations) {
  const Index n = system.size();
  Vector x = Vector::LinSpaced(n, 0.3, 1.7).array().sin(), y(n), a0(n);
  const Vector zero = Vector::Zero(n);
  // The load at `time` (body force, boundary data): a(t, x) - a(t, 0) = -K x.
  system.acceleration(time, zero, zero, a0);
  AccelerationSpectralRadius out;
  for (int it = 0; it < maximumIterations; ++it) {
    system.acceleration(time, x, zero, y);
    y = -(y - a0);
    const Real next = y.norm() / x.norm();
    x = y / y.norm();
    out.iterations = it + 1;
    out.lastChange = std::abs(next - out.value) / next;
    if (it > 20 && std::abs(next - out.value) < relativeTolerance * next) {
      out.value = next;
      out.converged = true;
      break;
    }
    out.value = next;
  }
  return out;
}

}  // namespace mfwave
