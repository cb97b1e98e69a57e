#pragma once
// The oscillating cantilever plate of Gray, Monaghan and Swift (2001), "SPH elastic dynamics",
// CMAME 190: a plate of length L and thickness H in plane strain, clamped at x = 0 and free at
// x = L, started straight with the velocity of its first bending mode. The thin-plate
// (Euler-Bernoulli, plane strain) solution is the reference of the plate study; the Timoshenko
// estimates below say how much of a measured period difference shear and rotary inertia explain.
//
// Thin plate. Per unit width the bending stiffness is D = E' H^3 / 12 with the plane-strain modulus
// E' = E / (1 - nu^2) and the mass rho H, so w_tt + (D / (rho H)) w_xxxx = 0 and the first mode
//   omega^2 = E H^2 k^4 / (12 rho (1 - nu^2)),  kL = 1.8751040687 (root of cos kL cosh kL = -1),
//   f(x) = (cos kx - cosh kx) - (cos kL + cosh kL) / (sin kL + sinh kL) (sin kx - sinh kx),
// with f(0) = f'(0) = 0 (clamped) and f''(L) = f'''(L) = 0 (no moment, no shear at the free end).
// f(L) = 2 (cos kL sinh kL - sin kL cosh kL) / (sin kL + sinh kL) < 0.
//
// Initial velocity. v_y(x, 0) = V_f c0 f(x) / f(L), so the tip starts at V_f c0, with
// c0 = sqrt(K / rho) and K = lambda + 2 mu / 3 the bulk modulus (the EOS sound speed of the
// updated-Lagrangian SPH). The original paper could not be consulted here; this form and
// c0 = sqrt(K / rho) are those of the SPHinXsys "2D oscillating beam" example that reproduces GMS
// (v_y = vf c0 (M (cos kx - cosh kx) - N (sin kx - sinh kx)) / Q with M = sin kL + sinh kL,
// N = cos kL + cosh kL, Q = 2 (cos kL sinh kL - sin kL cosh kL), which is f(x) / f(L);
// c0 = sqrt(E / (3 (1 - 2 nu) rho))). The thin-plate motion is then
// w(x, t) = (V_f c0 / omega) f(x) / f(L) sin(omega t).
//
// Timoshenko estimates (shear coefficient kappa, 5/6 for a rectangle; r^2 = I / A = H^2 / 12).
// First order, derived here by perturbing the flexibility eigenproblem F M w = (1 / omega^2) w with
// the Euler-Bernoulli mode w = f:
//   rotary inertia adds rho I w_x^2 to the kinetic energy: d(1/omega^2) / (1/omega^2) = r^2 <f'^2> / <f^2>;
//   shear adds the compliance V^2 / (kappa G A) with V = E'I f''' / omega^2 the shear force of the
//   inertia load rho A f (V(L) = 0): d(1/omega^2) / (1/omega^2) = (E' / (kappa G)) r^2 <f'''^2> / <f''^2>,
// so 1/omega_T^2 = (1/omega^2) [1 + r^2 (<f'^2>/<f^2> + (E'/(kappa G)) <f'''^2>/<f''^2>)], <.> = int_0^L.
// For the clamped-free mode both ratios are 1.321888 k^2 (equal: integrate by parts with f'''' = k^4 f);
// for the GMS plate (H/L = 0.1, nu = 0.3975) the period grows by 0.96 %, 0.25403 s -> 0.25647 s.
// For a simply supported beam (f = sin kx, both ratios k^2) this is Timoshenko's classical
// omega_T = omega [1 - (kr)^2 (1 + E/(kappa G)) / 2]. In plane strain E'/G = 2 / (1 - nu).
// Exact: the first root of the Timoshenko frequency equation of the clamped-free beam (w, psi with
// w = psi = 0 at x = 0 and M = E'I psi_x = 0, V = kappa G A (w_x - psi) = 0 at x = L), found by
// integrating the clamped solutions across the beam. The two agree to O((H/L)^4) (tested).

#include "core/Material.hpp"
#include "core/Types.hpp"

namespace mfwave {

class CantileverPlate {
 public:
  // length L > 0, thickness H > 0 (InputError "length", "thickness"); E, nu, rho from `material`.
  CantileverPlate(Real length, Real thickness, const Material& material);

  // The first positive root of cos x cosh x + 1 = 0 by Newton from 1.875: 1.8751040687...
  static Real firstModeRoot();

  Real length() const { return length_; }
  Real thickness() const { return thickness_; }
  Real wavenumber() const { return k_; }                  // k = 1.8751 / L
  Real planeStrainModulus() const;                        // E' = E / (1 - nu^2)
  Real referenceSoundSpeed() const;                       // c0 = sqrt(K / rho)

  // Thin plate (Euler-Bernoulli, plane strain).
  Real angularFrequency() const;                          // omega
  Real period() const;                                    // 2 pi / omega

  // Mode shape f and its derivatives d^n f / dx^n, n = 0..3 (InputError "order" otherwise).
  Real modeShape(Real x) const { return modeShapeDerivative(x, 0); }
  Real modeShapeDerivative(Real x, int order) const;

  // GMS start: v_y(x, 0) = V_f c0 f(x) / f(L) for x > 0, 0 in the clamp (x <= 0).
  Real initialVelocity(Real x, Real velocityFactor) const;
  // Thin-plate transverse displacement w(x, t) from that start, and its tip amplitude V_f c0 / omega.
  Real displacement(Real x, Real t, Real velocityFactor) const;
  Real tipAmplitude(Real velocityFactor) const;

  // Timoshenko beam in plane strain with shear coefficient kappa > 0 (InputError "shear_coefficient").
  Real timoshenkoFirstOrderAngularFrequency(Real shearCoefficient = Real(5) / 6) const;
  Real timoshenkoFirstOrderPeriod(Real shearCoefficient = Real(5) / 6) const;
  Real timoshenkoAngularFrequency(Real shearCoefficient = Real(5) / 6) const;
  Real timoshenkoPeriod(Real shearCoefficient = Real(5) / 6) const;

  // The dimensionless ratios of the first-order estimate: <f'^2> / (k^2 <f^2>) and
  // <f'''^2> / (k^2 <f''^2>) (both 1 for a sine; constants of the clamped-free mode).
  Real rotaryInertiaRatio() const;
  Real shearRatio() const;

 private:
  Real length_, thickness_;
  Material material_;
  Real k_;
  Real shapeRatio_;  // (cos kL + cosh kL) / (sin kL + sinh kL)

  // int_0^L f^(a) f^(a) dx by composite Simpson.
  Real squaredDerivativeIntegral(int order) const;
  // Determinant of the free-end conditions at x = L of the clamped Timoshenko solutions at omega.
  Real timoshenkoFreeEndDeterminant(Real omega, Real shearCoefficient) const;
};

}  // namespace mfwave
