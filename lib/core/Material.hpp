#pragma once
// Isotropic linear elastic material: Lame constants and density, and the wave speeds they imply.

#include "core/Types.hpp"

namespace mfwave {

class Material {
 public:
  // From the Lame constants lambda, mu and the density rho. Throws InputError naming the
  // parameter when the material is not physical (mu <= 0, rho <= 0, bulk modulus <= 0).
  static Material fromLame(Real lambda, Real mu, Real rho);
  // From Young's modulus E, Poisson's ratio nu and the density rho (-1 < nu < 0.5, E > 0).
  static Material fromYoung(Real youngsModulus, Real poissonRatio, Real rho);

  Real lambda() const { return lambda_; }
  Real mu() const { return mu_; }
  Real density() const { return rho_; }
  Real youngsModulus() const;
  Real poissonRatio() const;
  Real bulkModulus() const;    // 3-D bulk modulus K = lambda + 2 mu / 3
  Real pWaveModulus() const;   // M = lambda + 2 mu

  Real pWaveSpeed() const;         // c_p = sqrt((lambda + 2 mu) / rho)
  Real sWaveSpeed() const;         // c_s = sqrt(mu / rho)
  Real barSpeed() const;           // c_0 = sqrt(E / rho), thin bar
  Real rayleighSpeed() const;      // root of the Rayleigh equation, 0 < c_R < c_s

 private:
  Material(Real lambda, Real mu, Real rho) : lambda_(lambda), mu_(mu), rho_(rho) {}
  Real lambda_;
  Real mu_;
  Real rho_;
};

}  // namespace mfwave
