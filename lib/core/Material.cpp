#include "core/Material.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <sstream>

namespace mfwave {
namespace {

std::string describe(Real value) {
  std::ostringstream s;
  s.precision(10);
  s << value;
  return s.str();
}

void requireFinite(const char* key, Real value) {
  if (!std::isfinite(value)) throw InputError(key, "must be a finite number, got " + describe(value));
}

}  // namespace

Material Material::fromLame(Real lambda, Real mu, Real rho) {
  requireFinite("lambda", lambda);
  requireFinite("mu", mu);
  requireFinite("density", rho);
  if (mu <= 0) throw InputError("mu", "shear modulus must be positive, got " + describe(mu));
  if (rho <= 0) throw InputError("density", "must be positive, got " + describe(rho));
  // Strong ellipticity and a positive bulk modulus: 3 lambda + 2 mu > 0 (equivalently nu < 0.5
  // and nu > -1 for mu > 0).
  if (3 * lambda + 2 * mu <= 0)
    throw InputError("lambda", "bulk modulus lambda + 2 mu / 3 must be positive, got lambda = " +
                                   describe(lambda) + " with mu = " + describe(mu));
  return Material(lambda, mu, rho);
}

Material Material::fromYoung(Real youngsModulus, Real poissonRatio, Real rho) {
  requireFinite("youngs_modulus", youngsModulus);
  requireFinite("poisson_ratio", poissonRatio);
  if (youngsModulus <= 0)
    throw InputError("youngs_modulus", "must be positive, got " + describe(youngsModulus));
  if (!(poissonRatio > -1.0 && poissonRatio < 0.5))
    throw InputError("poisson_ratio",
                     "must lie in (-1, 0.5) for an isotropic elastic solid, got " + describe(poissonRatio));
  const Real mu = youngsModulus / (2 * (1 + poissonRatio));
  const Real lambda = youngsModulus * poissonRatio / ((1 + poissonRatio) * (1 - 2 * poissonRatio));
  return fromLame(lambda, mu, rho);
}

Real Material::youngsModulus() const { return mu_ * (3 * lambda_ + 2 * mu_) / (lambda_ + mu_); }
Real Material::poissonRatio() const { return lambda_ / (2 * (lambda_ + mu_)); }
Real Material::bulkModulus() const { return lambda_ + 2 * mu_ / 3; }
Real Material::pWaveModulus() const { return lambda_ + 2 * mu_; }
Real Material::pWaveSpeed() const { return std::sqrt(pWaveModulus() / rho_); }
Real Material::sWaveSpeed() const { return std::sqrt(mu_ / rho_); }
Real Material::barSpeed() const { return std::sqrt(youngsModulus() / rho_); }

Real Material::rayleighSpeed() const {
  // Rayleigh equation in xi = (c / c_s)^2, with kappa = (c_s / c_p)^2:
  //   R(xi) = xi^3 - 8 xi^2 + (24 - 16 kappa) xi - 16 (1 - kappa) = 0,
  // with exactly one root in (0, 1). R(0) < 0 < R(1) = 1, so bisection is safe.
  const Real kappa = sWaveSpeed() * sWaveSpeed() / (pWaveSpeed() * pWaveSpeed());
  auto rayleigh = [kappa](Real xi) { return ((xi - 8) * xi + (24 - 16 * kappa)) * xi - 16 * (1 - kappa); };
  Real lo = 0, hi = 1;
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const Real mid = 0.5 * (lo + hi);
    (rayleigh(mid) < 0 ? lo : hi) = mid;
  }
  return sWaveSpeed() * std::sqrt(0.5 * (lo + hi));
}

}  // namespace mfwave
