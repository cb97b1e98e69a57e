#include "analytic/PekerisPointLoad.hpp"

#include "core/Error.hpp"
#include "core/Material.hpp"

#include <cmath>
#include <limits>

namespace mfwave {

namespace {

// Constants of Pekeris' (1955) closed form for nu = 1/4; see the header.
const Real kS3 = PekerisPointLoad::kSqrt3;
const Real kTauP = 1 / kS3;                        // c_s / c_p
const Real kG = PekerisPointLoad::kRayleighTau;    // c_s / c_R
const Real kG2 = (3 + kS3) / 4;                    // root of 8x^2 - 12x + 3 (Rayleigh)
const Real kB2 = (3 - kS3) / 4;                    // the other root of 8x^2 - 12x + 3
const Real kA = std::sqrt(3 * kS3 + 5);
const Real kB = std::sqrt(3 * kS3 - 5);
const Real kStatic = 3.0 / 8.0;                    // (1 - nu) / 2 with nu = 1/4 (Boussinesq)

// Antiderivatives of G(s) / s^2 on (tau_P, 1) and (1, g), from
//   int ds / (s^2 sqrt(s^2 - q)) = sqrt(s^2 - q) / (q s),
//   int ds / (s^2 sqrt(c - s^2)) = -sqrt(c - s^2) / (c s).
Real primitiveOverS2PS(Real s) {
  return (-6 / s - kS3 * std::sqrt(s * s - 0.25) / (0.25 * s) +
          kA * std::sqrt(std::max<Real>(kG2 - s * s, 0)) / (kG2 * s) +
          kB * std::sqrt(s * s - kB2) / (kB2 * s)) /
         32;
}
Real primitiveOverS2SR(Real s) {
  return (-6 / s + kA * std::sqrt(std::max<Real>(kG2 - s * s, 0)) / (kG2 * s)) / 16;
}
// Antiderivatives of G(s), from int ds / sqrt(s^2 - q) = acosh(s / sqrt q) and
// int ds / sqrt(c - s^2) = asin(s / sqrt c).
Real primitivePS(Real s) {
  return (6 * s - kS3 * std::acosh(2 * s) - kA * std::asin(std::min<Real>(s / kG, 1)) +
          kB * std::acosh(s / std::sqrt(kB2))) /
         32;
}
Real primitiveSR(Real s) { return (6 * s - kA * std::asin(std::min<Real>(s / kG, 1))) / 16; }

const Real kHatS = primitiveOverS2PS(1) - primitiveOverS2PS(kTauP);
const Real kHatG = kHatS + primitiveOverS2SR(kG) - primitiveOverS2SR(1);
const Real kMatS = primitivePS(1) - primitivePS(kTauP);
const Real kMatG = kMatS + primitiveSR(kG) - primitiveSR(1);

}  // namespace

PekerisPointLoad::PekerisPointLoad(Real shearModulus, Real shearSpeed, Real force)
    : mu_(shearModulus), cs_(shearSpeed), force_(force) {
  if (!(shearModulus > 0) || !std::isfinite(shearModulus))
    throw InputError("shear_modulus", "must be positive");
  if (!(shearSpeed > 0) || !std::isfinite(shearSpeed))
    throw InputError("shear_speed", "must be positive");
  if (!std::isfinite(force)) throw InputError("force", "must be finite");
}

PekerisPointLoad PekerisPointLoad::fromMaterial(const Material& material, Real force) {
  if (std::abs(material.lambda() - material.mu()) > 1e-9 * material.mu())
    throw InputError("material.poisson_ratio",
                     "the Pekeris closed form needs lambda = mu (Poisson ratio 1/4)");
  return PekerisPointLoad(material.mu(), material.sWaveSpeed(), force);
}

Real PekerisPointLoad::shape(Real tau) {
  if (tau <= kTauP) return 0;
  if (tau < 1) {
    const Real t2 = tau * tau;
    return (6 - kS3 / std::sqrt(t2 - 0.25) - kA / std::sqrt(kG2 - t2) + kB / std::sqrt(t2 - kB2)) /
           32;
  }
  if (tau < kG) return (6 - kA / std::sqrt(kG2 - tau * tau)) / 16;
  if (tau == kG) return -std::numeric_limits<Real>::infinity();
  return kStatic;
}

Real PekerisPointLoad::shapeOverTauSquaredIntegral(Real tau) {
  if (tau <= kTauP) return 0;
  if (tau <= 1) return primitiveOverS2PS(tau) - primitiveOverS2PS(kTauP);
  if (tau <= kG) return kHatS + primitiveOverS2SR(tau) - primitiveOverS2SR(1);
  return kHatG + kStatic * (1 / kG - 1 / tau);
}

Real PekerisPointLoad::shapeOverTauSquaredIntegralAtInfinity() { return kHatG + kStatic / kG; }

Real PekerisPointLoad::shapeIntegral(Real tau) {
  if (tau <= kTauP) return 0;
  if (tau <= 1) return primitivePS(tau) - primitivePS(kTauP);
  if (tau <= kG) return kMatS + primitiveSR(tau) - primitiveSR(1);
  return kMatG + kStatic * (tau - kG);
}

Real PekerisPointLoad::displacement(Real r, Real t) const {
  if (!(r > 0)) throw InputError("r", "must be positive (the point response is singular at r = 0)");
  return force_ / (kPi * mu_ * r) * shape(cs_ * t / r);
}

}  // namespace mfwave
