#pragma once
// The largest stable step of central difference (and leapfrog) for an assembled linear system
// M u'' + K u = f with lumped M: dt_crit = 2 / omega_max, omega_max^2 the largest eigenvalue of
// M^{-1} K. Two numbers, so a user sees how sure the limit is:
//  - an estimate by power iteration (a lower bound on omega_max for symmetric K, so the step is
//    slightly optimistic: keep a margin, e.g. a CFL fraction of 0.9 or less);
//  - a Gershgorin bound, max_i sum_j |K_ij| / M_ii, which is never below omega_max^2 (its step is
//    safe, but may be pessimistic for wide stencils).

#include "systems/LinearOperatorSystem.hpp"
#include "systems/SecondOrderSystem.hpp"

namespace mfwave {

struct StableTimeStep {
  Real powerIterationOmegaSquared = 0;  // estimate of the largest eigenvalue of M^{-1} K
  Real gershgorinOmegaSquared = 0;      // upper bound on it
  int iterations = 0;
  bool converged = false;

  Real estimate() const;  // 2 / sqrt(powerIterationOmegaSquared)
  Real safe() const;      // 2 / sqrt(gershgorinOmegaSquared)
  // The step a run uses: the estimate when the iteration converged, else the safe bound.
  Real usable() const { return converged ? estimate() : safe(); }
};

// The Gershgorin step alone: cheap (one pass over K), never above the true limit; exact for the
// finite-difference Laplacian.
Real centralDifferenceSafeStep(const LinearOperatorSystem& system);

// Power iteration on M^{-1} K from a fixed pseudo-random start (reproducible), until the Rayleigh
// quotient changes by less than `relativeTolerance` between iterations. Throws InputError if M is
// not diagonal with positive entries.
StableTimeStep centralDifferenceStableStep(const LinearOperatorSystem& system, Real relativeTolerance = 1e-6,
                                           int maximumIterations = 20000);

// The largest |eigenvalue| of K for a linear, velocity-independent system known only through its
// acceleration, a(t, U) = a(t, 0) - K U: collocation's explicit form (ConstrainedCollocationSystem,
// Luo-Liu-Huang's G-bar of eq. (37), where K = (1/rho) A_I C^{-1} [I; 0] is neither symmetric nor
// assembled). Power iteration on K x = -(a(t, x) - a(t, 0)) (the load at t removed) from a fixed start,
// sin(0.3 .. 1.7) spread over the unknowns, until the ratio |K x| / |x| changes by less than
// `relativeTolerance` (after at least 20 iterations) or `maximumIterations` are done. When K's
// eigenvalues are real and positive the value is omega_max^2 and 2 / sqrt(value) the central-difference
// limit. A cluster of close largest eigenvalues (lamb2d's RK collocation) keeps the ratio creeping up
// from below, a dominant complex pair makes it oscillate: converged = false, and the value is the
// last ratio (lastChange says how far it still moved), a guide and not a bound.
struct AccelerationSpectralRadius {
  Real value = 0;
  int iterations = 0;
  bool converged = false;
  Real lastChange = 0;  // |last ratio - the one before| / last ratio
};
AccelerationSpectralRadius accelerationSpectralRadius(SecondOrderSystem& system, Real time = 0,
                                                      Real relativeTolerance = 1e-6, int maximumIterations = 400);

}  // namespace mfwave
