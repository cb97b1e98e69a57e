#pragma once
// How large a step each time integrator takes on an undamped linear system before it grows.
//
// A lumped linear system u'' = -K u splits into oscillators u'' = -omega^2 u, one per eigenvalue
// omega^2 >= 0 of the operator. A one-step integrator is stable on all of them exactly when
// omega_max dt <= L, where L is the integrator's limit on a single oscillator; so the stable step of
// any method-integrator pair is L / omega_max, with omega_max from the method's spectrum
// (DispersionSpectrum on a periodic lattice, power iteration or Lanczos on a bounded one).
//   - central difference, leapfrog: L = 2;
//   - Newmark (beta, gamma): unconditional for 2 beta >= gamma >= 1/2, otherwise
//     L = 1 / sqrt(gamma / 2 - beta) (gamma = 1/2; central difference is beta = 0);
//   - an explicit Runge-Kutta table (ARKODE) on the first-order form (u, v)' = (v, -omega^2 u),
//     whose eigenvalues are +-i omega: L = the extent of the stability region along the imaginary
//     axis, sup { y : |R(i y')| <= 1 for 0 < y' <= y }, with R(z) = 1 + z b^T (I - z A)^{-1} 1 the
//     table's stability function (classic RK4: 2 sqrt 2; 3-stage third order: sqrt 3). A table
//     with |R(i y)| > 1 for every small y (Heun-Euler, and every explicit two-stage second-order
//     table) has L = 0 (or a tiny L, by round-off): an undamped mode grows at any step, slowly
//     when omega dt is small.

#include "core/Types.hpp"
#include "integrators/ArkodeExplicit.hpp"
#include "integrators/IntegratorFactory.hpp"

#include <string>
#include <vector>

namespace mfwave {

// |R(i y)| of an explicit Butcher table.
Real rungeKuttaAmplification(const ButcherCoefficients& table, Real y);

// The table's imaginary-axis limit: sup { y : |R(i y')| <= 1 + tolerance for 0 < y' <= y },
// scanned on (0, yMax] in steps of yMax / 1e5 and bisected (0: |R| > 1 already at the first
// sample; yMax: no crossing).
Real rungeKuttaImaginaryLimit(const ButcherCoefficients& table, Real tolerance = 1e-12, Real yMax = 10);

struct IntegratorLimit {
  std::string integrator;  // "central_difference", "leapfrog", "newmark", "newmark:<beta>", "arkode:<table>"
  // Stable for omega_max dt <= omegaDtLimit: infinity for an unconditionally stable integrator,
  // near 0 for one under which undamped modes grow at practically every step.
  Real omegaDtLimit = 0;
  // For omegaDtLimit < 0.5: |R(i y)| - 1 at y = 1 (the growth per step of a mode with omega dt = 1).
  Real growthPerStepAtOne = 0;
  std::string note;
};

// The limit of one integrator: "central_difference", "leapfrog", "newmark" (with beta, gamma),
// "newmark:<beta>" (namedIntegrator: gamma 1/2, the arguments unused) or "arkode:<table>". Throws
// InputError("integrator") for another name, and what ArkodeExplicit::coefficients throws for an
// unknown table.
IntegratorLimit integratorLimit(const std::string& integrator, Real newmarkBeta = 0.25, Real newmarkGamma = 0.5);

// The limit of a second-order integrator as a driver builds it (makeSecondOrderIntegrator): "newmark"
// with options.newmarkBeta / newmarkGamma, "arkode" with options.arkode.table (an adaptive ARKODE
// run has no fixed-step limit: its error control chooses the step; omegaDtLimit = infinity).
IntegratorLimit integratorLimit(const std::string& name, const IntegratorOptions& options);

// Every integrator mfwave offers for second-order systems, every ARKODE table included.
std::vector<IntegratorLimit> integratorLimits();

// How a fixed step dt fares on an operator whose largest frequency is omegaMax.
struct StepVerdict {
  IntegratorLimit limit;
  Real omegaMax = 0;
  Real dt = 0;
  Real limitDt = 0;           // limit.omegaDtLimit / omegaMax (infinity when unconditional)
  Real growthPerStep = 1;     // amplification of the fastest mode per step (1: not growing)
  bool aboveLimit = false;    // dt > limitDt (beyond round-off)
  // The integrator lets undamped modes grow at practically any step (Newmark gamma < 1/2, an ERK
  // table with omegaDtLimit < 0.5): the setting to change is the integrator's, not the step.
  bool integratorUnstable = false;
};

// The verdict for an undamped operator with largest frequency omegaMax. The growth per step of the
// fastest mode: |R(i omega dt)| for ARKODE tables, the larger root of the recurrence for central
// difference / leapfrog / Newmark. Throws InputError("omega_max") unless omegaMax > 0 and finite.
StepVerdict judgeStep(const std::string& name, const IntegratorOptions& options, Real omegaMax, Real dt);

}  // namespace mfwave
