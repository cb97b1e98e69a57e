#pragma once
// The 2-D (plane-strain) Lamb problem: a half-space z >= 0 (z the depth) loaded on its free
// surface by the normal traction q = p f(t) on the strip |x| < l, pushing into the solid, f
// piecewise linear from 0 (PiecewiseLinearLoad). The 2-D analogue of Ding-Long-Wu's 3-D test
// (LambSquareLoad): lambda = mu = rho = 1, l = 0.5, f the triangle t on (0, 1), 2 - t on (1, 2).
//
// Sign convention: displacement and velocity are the vertical components ALONG THE APPLIED
// TRACTION (into the solid), at any receiver (x, depth), on the surface or inside.
//
// Method: Cagniard-de Hoop, exact up to a 1-D quadrature. With the Laplace variable s and the
// horizontal slowness q (e^{-s q x}), the strip's transform 2 sinh(s q l)/(s q) splits the response
// into two half-plane loads starting at the strip's edges: u = p / (2 pi mu s) [J(x - l) - J(x + l)]
// per unit Laplace load, J odd in xi = receiver - edge. For xi > 0, J is the principal value of
//   int dkappa G(q) e^{-s (q xi + gamma z)},  q = i kappa,
//   gamma_c = sqrt(1/c^2 - q^2) (c = c_p, c_s),  R(q) = (1/c_s^2 - 2 q^2)^2 + 4 q^2 gamma_p gamma_s,
//   G_P = gamma_p (1/c_s^2 - 2 q^2) / (q R)  (with e^{-s gamma_p z}),
//   G_S = 2 q gamma_p / R                    (with e^{-s gamma_s z}),
// and the pole at q = 0 gives the plane P wave under the strip, -(pi c_s^2 / c_p) e^{-s z / c_p}.
// Deforming each term onto its Cagniard path q(t) (t = q xi + gamma z real: a hyperbola from the
// ray arrival r / c, r^2 = xi^2 + z^2, plus for the S term the head-wave segment of the real axis
// when xi / r > c_s / c_p) gives J = int e^{-s t} k(t) dt with k(t) = 2 Im[G(q) dq/dt] summed over
// the terms, so the step displacement is int_0^t (t - t') k dt' and the ramp displacement
// int_0^t (t - t')^2 / 2 k dt' (a 1-D quadrature each). On the surface (z = 0) both terms share
// q = t / xi and k(t) = -(2 / xi) sqrt(q^2 - 1/c_p^2) Re[1 / R(q)] / (c_s^2 q), with a Cauchy
// pole at the Rayleigh arrival xi / c_R, integrated as a principal value by subtracting the pole.
// The velocity under the triangle load is sum_k ds_k stepDisplacement(t - t_k) (finite everywhere:
// the strip smooths the line load's Rayleigh singularity), the displacement sum_k ds_k ramp(...).
//
// 2-D responses keep a slow tail: the step displacement grows like (1 - nu) 2 l p ln(t) / (pi mu)
// (Flamant's logarithm), so the triangle's displacement decays only like 1/t and its velocity like
// 1/t^2 after the fronts have passed.
//
// Checked (tests/analytic/LambStripLoadTest.cpp, LambStripLoadFrequencyWavenumberTest.cpp): against
// a frequency-wavenumber integration with FFTW (HalfSpaceFrequencyWavenumber: relative L2 over
// 0 <= t <= 6 of 6e-6 .. 1.3e-4 in velocity and 5e-9 .. 4e-7 in displacement at the study's receivers
// and a head-wave receiver, the f-k side's own error), the plane-wave first motion, the arrival
// times, the late-time Flamant difference between two surface points, 24- against 48-point rules
// (1e-11), and the time integral of the velocity against the displacement.
// Limits: receivers just below the surface (depth < 1e-3 xi) see the Rayleigh pole through a peak
// of width ~depth on the Cagniard path; the graded pieces resolve it only to about 4e-5 there (the
// surface itself, depth = 0, uses the exact surface kernel). Long times: at t = 1000 the plane
// wave's (t - z/c_p) and the integral cancel to about 5e-7 relative.

#include "analytic/PiecewiseLinearLoad.hpp"
#include "core/GaussLegendre.hpp"
#include "core/Types.hpp"

#include <vector>

namespace mfwave {

class LambStripLoad {
 public:
  // lambda >= 0 (any Poisson ratio in [0, 1/2)), mu > 0, rho > 0, half-width l > 0, the load's
  // breakpoints, p = pressure amplitude. Throws InputError naming the parameter.
  LambStripLoad(Real lambda, Real mu, Real rho, Real halfWidth, std::vector<Real> times,
                std::vector<Real> values, Real pressure = 1);
  // lambda = mu = rho = 1, l = 0.5, p = 1, the triangle load of the 3-D test.
  static LambStripLoad dingLongWu();

  // Receiver at horizontal offset x from the strip's centre and depth >= 0.
  Real displacement(Real x, Real depth, Real t) const;
  Real velocity(Real x, Real depth, Real t) const;
  // Responses to p H(t) and to p t H(t) on the strip (the building blocks above).
  Real stepDisplacement(Real x, Real depth, Real t) const;
  Real rampDisplacement(Real x, Real depth, Real t) const;
  Real loadHistory(Real t) const { return load_.value(t); }

  Real pWaveSpeed() const { return cp_; }
  Real shearWaveSpeed() const { return cs_; }
  Real rayleighWaveSpeed() const { return 1 / rayleighSlowness_; }

  // Gauss-Legendre points per time piece (default 24); for convergence studies.
  void setQuadraturePoints(int points);

 private:
  // int_0^t (t - t')^n / n! k(xi, z, t') dt' for one half-plane load (xi != 0 signed).
  Real halfPlane(Real xi, Real z, Real t, int power) const;
  Real halfPlaneSurface(Real xi, Real t, int power) const;
  Real halfPlaneInterior(Real xi, Real z, Real t, int power) const;
  Real response(Real x, Real z, Real t, int power) const;

  Real mu_, cp_, cs_, l_, p_;
  Real surfacePoleNumerator(Real q) const;

  Real rayleighSlowness_ = 0, rayleighX_ = 0;  // q_R and q_R^2
  Real quotient_[3] = {0, 0, 0};              // the Rayleigh cubic divided by (x - x_R)
  PiecewiseLinearLoad load_;
  QuadratureRule rule_;
};

}  // namespace mfwave
