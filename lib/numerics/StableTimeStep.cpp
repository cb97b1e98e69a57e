#include "numerics/StableTimeStep.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <limits>
#include <cstdint>

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

// Gershgorin: every eigenvalue of M^{-1} K lies in a disc around a row's diagonal (the largest
// over the ranks of a distributed system).
Real gershgorinOmegaSquared(const LinearOperatorSystem& system, const Vector& inverseMass) {
  return system.maximum(system.stiffnessAbsoluteRowSums().cwiseProduct(inverseMass).maxCoeff());
}

// The power iteration's start: a value in [-1, 1) per global unknown from a hash of its number
// (splitmix64), so it has components along every mode and is the same vector on any number of
// ranks.
Real startValue(Index i) {
  std::uint64_t z = 0x9e3779b97f4a7c15ULL * (static_cast<std::uint64_t>(i) + 20261121ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<Real>(z >> 11) * 0x1.0p-52 - 1;
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

  // Power iteration; the start has components along every mode, and the quotient
  // x.(M^-1 K x) / x.x tends to the dominant eigenvalue. Dot products through the system, so a
  // distributed one sums over its ranks in the serial order and every rank gets the serial figure.
  Vector x(n), y(n);
  system.fillByGlobalIndex(x, startValue);
  x /= std::sqrt(system.dot(x, x));
  Real previous = 0;
  for (int iteration = 1; iteration <= maximumIterations; ++iteration) {
    system.applyStiffness(x, y);
    y.array() *= inverseMass.array();
    const Real quotient = system.dot(x, y);
    const Real norm = std::sqrt(system.dot(y, y));
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
