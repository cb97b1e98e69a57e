#pragma once
// The 3-D Lamb problem of Ding-Long-Wu section 8 (eq. 36-37): a half-space with Poisson ratio 1/4
// (lambda = mu) loaded on its free surface by the normal traction T_z = p f(t) X(x1, x2), X = 1 on
// the square |x1| < l, |x2| < l (the paper's eq. 37 prints |x1 - 1| < l, but its text puts the load
// at the centre of the free surface; docs/references.md, reading 2), f piecewise linear with f = 0
// before its first breakpoint (eq. 36: the triangle t on (0, 1), 2 - t on (1, 2), 0 after).
//
// Sign convention: displacement and velocity are the surface components ALONG THE APPLIED TRACTION
// (+z when T_z = p f X e_z with p f > 0). By linearity this is the vertical component u_z in the
// paper's frame whether the body lies in x3 < 0 or x3 > 0 (the paper does not say), so the values
// compare directly with the paper's "vertical velocity" for T_z as printed in eq. 36.
//
// Method (exact up to a 1-D quadrature). The step response of the square is the Pekeris point
// response w = p dA G(c_s t / rho) / (pi mu rho) (PekerisPointLoad) integrated over the square. The
// square is the signed sum of the four triangles (receiver, corner k, corner k+1); on each, in polar
// coordinates (rho, theta) about the receiver, the Jacobian rho cancels the 1/rho of w and the
// radial integral is closed form:
//   int_0^R G(c t / rho) drho = c t [H(inf) - H(c t / R)],        H(tau) = int_0^tau G / s^2,
//   int_0^t int_0^R G(c t' / rho) drho dt' = (R^2 / c) K(c t / R),
//   K(tau) = tau^2 / 2 [H(inf) - H(tau)] + M(tau) / 2,             M(tau) = int_0^tau G,
// with R(theta) the distance to the far edge. The remaining theta integral is done by
// Gauss-Legendre on pieces split where R(theta) = c_p t, c_s t, c_R t (the integrand has kinks
// there, and a square-root cusp at the Rayleigh radius) and at the foot of the perpendicular; each
// piece is mapped by a smoothstep so that square-root endpoint behaviour becomes smooth.
// Time: f(t) = sum_k ds_k (t - t_k)_+ (ds_k the slope changes), so the displacement is
// sum_k ds_k Ramp(t - t_k) and the velocity sum_k ds_k Step(t - t_k) (the step response is
// continuous, so the velocity is finite everywhere). Accuracy: about 1e-12 relative (tests compare
// 24- and 48-point rules and the time integral of the velocity with the displacement).

#include "analytic/PiecewiseLinearLoad.hpp"
#include "core/GaussLegendre.hpp"
#include "core/Types.hpp"

#include <vector>

namespace mfwave {

class LambSquareLoad {
 public:
  // mu > 0, c_s > 0, half-width l > 0; breakpoints (times strictly increasing, at least 2, first
  // value 0: no jump in the load) of f, held constant after the last breakpoint as
  // TimeFunction::tabulated does; p = pressure amplitude. Throws InputError naming the parameter.
  LambSquareLoad(Real shearModulus, Real shearSpeed, Real halfWidth, std::vector<Real> times,
                 std::vector<Real> values, Real pressure = 1);
  // The Ding-Long-Wu test: lambda = mu = rho = 1, l = 0.5, f = TimeFunction::triangle(0, 1, 1, 1).
  static LambSquareLoad dingLongWu();

  Real displacement(Real x, Real y, Real t) const;
  Real velocity(Real x, Real y, Real t) const;
  // Responses to p H(t) and to p t H(t) on the square (the building blocks above).
  Real stepDisplacement(Real x, Real y, Real t) const;
  Real rampDisplacement(Real x, Real y, Real t) const;
  Real loadHistory(Real t) const { return load_.value(t); }  // f(t)

  // Gauss-Legendre points per theta piece (default 24); for convergence studies.
  void setQuadraturePoints(int points);

 private:
  Real integrateSquare(Real x, Real y, Real t, bool ramp) const;
  Real mu_, cs_, l_, p_;
  PiecewiseLinearLoad load_;
  QuadratureRule rule_;
};

}  // namespace mfwave
