#include "analytic/CantileverPlate.hpp"

#include "core/Error.hpp"

#include <array>
#include <cmath>

namespace mfwave {
namespace {

constexpr Real pi = kPi;

void requireShearCoefficient(Real kappa) {
  if (!(kappa > 0) || !std::isfinite(kappa)) throw InputError("shear_coefficient", "must be positive");
}

}  // namespace

CantileverPlate::CantileverPlate(Real length, Real thickness, const Material& material)
    : length_(length), thickness_(thickness), material_(material) {
  if (!(length > 0) || !std::isfinite(length)) throw InputError("length", "must be positive");
  if (!(thickness > 0) || !std::isfinite(thickness)) throw InputError("thickness", "must be positive");
  const Real kL = firstModeRoot();
  k_ = kL / length;
  shapeRatio_ = (std::cos(kL) + std::cosh(kL)) / (std::sin(kL) + std::sinh(kL));
}

Real CantileverPlate::firstModeRoot() {
  // g(x) = cos x cosh x + 1, g'(x) = cos x sinh x - sin x cosh x (about -3.8 there, far from zero):
  // Newton from 1.875 converges in a few steps.
  Real x = 1.875;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Real g = std::cos(x) * std::cosh(x) + 1;
    const Real dg = -std::sin(x) * std::cosh(x) + std::cos(x) * std::sinh(x);
    const Real step = g / dg;
    x -= step;
    if (std::abs(step) < 1e-15 * x) break;
  }
  return x;
}

Real CantileverPlate::planeStrainModulus() const {
  const Real nu = material_.poissonRatio();
  return material_.youngsModulus() / (1 - nu * nu);
}

Real CantileverPlate::referenceSoundSpeed() const {
  return std::sqrt(material_.bulkModulus() / material_.density());
}

Real CantileverPlate::angularFrequency() const {
  const Real k2 = k_ * k_;
  return std::sqrt(planeStrainModulus() * thickness_ * thickness_ * k2 * k2 / (12 * material_.density()));
}

Real CantileverPlate::period() const { return 2 * pi / angularFrequency(); }

Real CantileverPlate::modeShapeDerivative(Real x, int order) const {
  const Real kx = k_ * x;
  const Real c = std::cos(kx), ch = std::cosh(kx), s = std::sin(kx), sh = std::sinh(kx);
  const Real a = shapeRatio_;
  switch (order) {
    case 0: return (c - ch) - a * (s - sh);
    case 1: return k_ * ((-s - sh) - a * (c - ch));
    case 2: return k_ * k_ * ((-c - ch) - a * (-s - sh));
    case 3: return k_ * k_ * k_ * ((s - sh) - a * (-c - ch));
    default: throw InputError("order", "must be 0, 1, 2 or 3, got " + std::to_string(order));
  }
}

Real CantileverPlate::initialVelocity(Real x, Real velocityFactor) const {
  if (x <= 0) return 0;
  return velocityFactor * referenceSoundSpeed() * modeShape(x) / modeShape(length_);
}

Real CantileverPlate::displacement(Real x, Real t, Real velocityFactor) const {
  if (x <= 0) return 0;
  return tipAmplitude(velocityFactor) * modeShape(x) / modeShape(length_) * std::sin(angularFrequency() * t);
}

Real CantileverPlate::tipAmplitude(Real velocityFactor) const {
  return velocityFactor * referenceSoundSpeed() / angularFrequency();
}

Real CantileverPlate::squaredDerivativeIntegral(int order) const {
  // The integrands are smooth (hyperbolic and circular functions of kx <= 1.88): Simpson with 2000
  // intervals is exact to ~1e-13 relative.
  const int n = 2000;
  const Real h = length_ / n;
  Real sum = 0;
  for (int i = 0; i <= n; ++i) {
    const Real value = modeShapeDerivative(i * h, order);
    const Real weight = (i == 0 || i == n) ? 1 : (i % 2 == 1 ? 4 : 2);
    sum += weight * value * value;
  }
  return sum * h / 3;
}

Real CantileverPlate::rotaryInertiaRatio() const {
  return squaredDerivativeIntegral(1) / (k_ * k_ * squaredDerivativeIntegral(0));
}

Real CantileverPlate::shearRatio() const {
  return squaredDerivativeIntegral(3) / (k_ * k_ * squaredDerivativeIntegral(2));
}

Real CantileverPlate::timoshenkoFirstOrderAngularFrequency(Real shearCoefficient) const {
  requireShearCoefficient(shearCoefficient);
  const Real r2 = thickness_ * thickness_ / 12;
  const Real stiffnessRatio = planeStrainModulus() / (shearCoefficient * material_.mu());  // E' / (kappa G)
  const Real kr2 = k_ * k_ * r2;
  const Real compliance = 1 + kr2 * (rotaryInertiaRatio() + stiffnessRatio * shearRatio());
  return angularFrequency() / std::sqrt(compliance);
}

Real CantileverPlate::timoshenkoFirstOrderPeriod(Real shearCoefficient) const {
  return 2 * pi / timoshenkoFirstOrderAngularFrequency(shearCoefficient);
}

Real CantileverPlate::timoshenkoFreeEndDeterminant(Real omega, Real kappa) const {
  // Per unit width: A = H, I = H^3 / 12. State y = (w, psi, M, V) with M = E'I psi', V = kappa G A (w' - psi):
  //   w' = psi + V / (kappa G A),  psi' = M / (E'I),  M' = -V - rho I omega^2 psi,  V' = -rho A omega^2 w.
  const Real area = thickness_, inertia = thickness_ * thickness_ * thickness_ / 12;
  const Real bending = planeStrainModulus() * inertia, shear = kappa * material_.mu() * area;
  const Real rho = material_.density(), w2 = omega * omega;
  using State = std::array<Real, 4>;
  const auto rhs = [&](const State& y) -> State {
    return {y[1] + y[3] / shear, y[2] / bending, -y[3] - rho * inertia * w2 * y[1], -rho * area * w2 * y[0]};
  };
  const int steps = 4000;
  const Real h = length_ / steps;
  // The two clamped solutions (w = psi = 0 at x = 0) with unit moment and unit shear force.
  std::array<State, 2> y = {State{0, 0, 1, 0}, State{0, 0, 0, bending * k_}};  // V scaled to be O(M k)
  for (State& s : y) {
    for (int i = 0; i < steps; ++i) {
      const State k1 = rhs(s);
      State t;
      for (int c = 0; c < 4; ++c) t[c] = s[c] + 0.5 * h * k1[c];
      const State k2 = rhs(t);
      for (int c = 0; c < 4; ++c) t[c] = s[c] + 0.5 * h * k2[c];
      const State k3 = rhs(t);
      for (int c = 0; c < 4; ++c) t[c] = s[c] + h * k3[c];
      const State k4 = rhs(t);
      for (int c = 0; c < 4; ++c) s[c] += h / 6 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
    }
  }
  // A combination with M(L) = V(L) = 0 exists iff this vanishes.
  return y[0][2] * y[1][3] - y[0][3] * y[1][2];
}

Real CantileverPlate::timoshenkoAngularFrequency(Real shearCoefficient) const {
  requireShearCoefficient(shearCoefficient);
  // Shear and rotary inertia only lower the frequency: the first root lies below the thin-plate
  // omega. Scan up from omega / 100 for the first sign change, then bisect.
  const Real thin = angularFrequency();
  Real lo = 0.01 * thin;
  Real dLo = timoshenkoFreeEndDeterminant(lo, shearCoefficient);
  const int scan = 200;
  for (int i = 1; i <= scan; ++i) {
    const Real hi = 0.01 * thin * std::pow(101.0, static_cast<Real>(i) / scan);  // up to 1.01 omega
    const Real dHi = timoshenkoFreeEndDeterminant(hi, shearCoefficient);
    if ((dLo < 0) != (dHi < 0)) {
      Real a = lo, b = hi, da = dLo;
      for (int it = 0; it < 200 && b - a > 1e-15 * b; ++it) {
        const Real m = 0.5 * (a + b);
        const Real dm = timoshenkoFreeEndDeterminant(m, shearCoefficient);
        if ((dm < 0) == (da < 0)) {
          a = m;
          da = dm;
        } else {
          b = m;
        }
      }
      return 0.5 * (a + b);
    }
    lo = hi;
    dLo = dHi;
  }
  throw Error("CantileverPlate: no Timoshenko frequency below the thin-plate frequency (bracket search failed)");
}

Real CantileverPlate::timoshenkoPeriod(Real shearCoefficient) const {
  return 2 * pi / timoshenkoAngularFrequency(shearCoefficient);
}

}  // namespace mfwave
