#pragma once
// Lamb's problem for a point load (Pekeris 1955, "The seismic surface pulse", PNAS 41:469-480):
// the vertical surface displacement of a homogeneous isotropic half-space with Poisson ratio 1/4
// (lambda = mu, c_p = sqrt(3) c_s) due to a normal point force P H(t) applied at the surface.
//
// Sign convention: w is the displacement ALONG THE FORCE. For a force pushing into the body,
// w > 0 means motion into the body. By linearity the same w is the displacement along the force
// when the force pulls outwards, so "u_z = w" holds for a surface force P e_z whichever side of
// the surface the body occupies.
//
// With tau = c_s t / r (r = surface distance from the load), w(r, t) = P / (pi mu r) G(tau):
//   G = 0                                                                    tau < 1/sqrt3 (P)
//   G = (1/32) [6 - sqrt3 / sqrt(tau^2 - 1/4) - A / sqrt(g^2 - tau^2)
//                 + B / sqrt(tau^2 - b)]                                      1/sqrt3 < tau < 1 (S)
//   G = (1/16) [6 - A / sqrt(g^2 - tau^2)]                                    1 < tau < g (Rayleigh)
//   G = 3/8   (Boussinesq: w = P (1 - nu) / (2 pi mu r))                      tau > g
// with A = sqrt(3 sqrt3 + 5), B = sqrt(3 sqrt3 - 5), b = (3 - sqrt3)/4, g^2 = (3 + sqrt3)/4.
// (Pekeris 1955; the same kernel as Mooney 1974, BSSA 64:473. For nu = 1/4 the rationalised
// Rayleigh function in x = (c_s p)^2 is 32 x^3 - 56 x^2 + 24 x - 3 = (4x - 1)(8x^2 - 12x + 3),
// roots 1/4, (3 - sqrt3)/4 and g^2 = (3 + sqrt3)/4; g = c_s / c_R, c_R / c_s = sqrt(2 - 2/sqrt3)
// = 0.919402.) G is continuous at the P and S arrivals (kinks there) and tends to -infinity like
// 1/sqrt(g - tau) just before the Rayleigh arrival, then jumps to the static value: the
// singularity is integrable, so every load spread over an area gives a finite response.
// The formula was checked against a numerical Laplace-Hankel inversion of the transform solution
// (agreement 1e-12), and the tests check the static limit and the plane-wave limit (see
// shapeOverTauSquaredIntegral).

#include "core/Types.hpp"

namespace mfwave {

class Material;

class PekerisPointLoad {
 public:
  // shear modulus mu > 0, shear speed c_s > 0, force P (any sign); throws InputError.
  PekerisPointLoad(Real shearModulus, Real shearSpeed, Real force = 1);
  // From a material with lambda = mu (Poisson ratio 1/4, relative tolerance 1e-9); throws
  // InputError("material.poisson_ratio", ...) otherwise.
  static PekerisPointLoad fromMaterial(const Material& material, Real force = 1);

  // Step response w(r, t) (r > 0). 0 for t <= r / c_p; at exactly t = r / c_R returns -infinity
  // (the limit from before the arrival).
  Real displacement(Real r, Real t) const;

  Real pArrival(Real r) const { return r / (kSqrt3 * cs_); }
  Real sArrival(Real r) const { return r / cs_; }
  Real rayleighArrival(Real r) const { return r * kRayleighTau / cs_; }
  Real rayleighSpeed() const { return cs_ / kRayleighTau; }
  Real shearModulus() const { return mu_; }
  Real shearSpeed() const { return cs_; }
  Real force() const { return force_; }

  // The dimensionless kernel G(tau) above and two closed-form integrals of it, used to integrate
  // the point response over an area and in time (LambSquareLoad):
  //   shapeOverTauSquaredIntegral(tau) = H(tau) = int_0^tau G(s) / s^2 ds,
  //   shapeIntegral(tau)               = M(tau) = int_0^tau G(s) ds.
  // H(infinity) = 1 / (2 sqrt3): a uniform pressure p H(t) on the whole surface gives
  // u = 2 c_s t H(infinity) p / mu = p t / (rho c_p), the 1-D plane P wave.
  static Real shape(Real tau);
  static Real shapeOverTauSquaredIntegral(Real tau);
  static Real shapeOverTauSquaredIntegralAtInfinity();
  static Real shapeIntegral(Real tau);

  static constexpr Real kSqrt3 = 1.7320508075688772935;
  // g = c_s / c_R = sqrt((3 + sqrt3) / 4) for nu = 1/4.
  static constexpr Real kRayleighTau = 1.0876638735805374369;

 private:
  Real mu_, cs_, force_;
};

}  // namespace mfwave
