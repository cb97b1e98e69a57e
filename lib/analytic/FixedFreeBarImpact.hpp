#pragma once
// A bar on [0, L] fixed at x = 0 (u = 0) and free at x = L (E u_x = 0), at rest and undeformed at
// t = 0 but moving with the uniform velocity v0: u(x, 0) = 0, u_t(x, 0) = v0. The example of
// Luo-Liu-Huang (L = 10, rho = 1, E = 10, v0 = -1). u_tt = c^2 u_xx, c = sqrt(E / rho).
//
// Method of images: the velocity v obeys the same wave equation with v(0) = 0, v_x(L) = 0,
// v(x, 0) = v0, v_t(x, 0) = c^2 u_xx(x, 0) = 0. Extend v0 oddly about x = 0 and evenly about x = L:
// v0 sq(x) with the square wave sq = +1 on (0, 2L), -1 on (2L, 4L), period 4L. d'Alembert gives
//
//   v(x, t) = (v0 / 2) [sq(x - c t) + sq(x + c t)],
//   u(x, t) = (v0 / (2 c)) [W(x + c t) - W(x - c t)],   W(y) = int_0^y sq = triangle wave,
//
// W(y) = y on [0, 2L], 4L - y on [2L, 4L], even and 4L-periodic. u is piecewise linear in x and t,
// v and the strain u_x are piecewise constant: a step front leaves the fixed end at t = 0, reflects
// at the free end and so on; the period of the motion is 4 L / c.

#include "core/Types.hpp"

namespace mfwave {

class FixedFreeBarImpact {
 public:
  // length L > 0, wave speed c > 0; throws InputError naming the parameter.
  FixedFreeBarImpact(Real length, Real waveSpeed, Real initialVelocity);

  Real displacement(Real x, Real t) const;
  // At a front, the mean of the two sides.
  Real velocity(Real x, Real t) const;
  Real strain(Real x, Real t) const;  // u_x
  Real period() const { return 4 * length_ / c_; }
  Real length() const { return length_; }
  Real waveSpeed() const { return c_; }

  // The extension functions, exposed for tests: sq (odd about 0, even about L) and W = int_0^y sq.
  Real squareWave(Real y) const;
  Real triangleWave(Real y) const;

 private:
  Real length_, c_, v0_;
};

}  // namespace mfwave
