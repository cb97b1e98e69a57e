#include "kernels/GaussianKernel.hpp"

#include "kernels/KernelProfiles.hpp"

#include <array>
#include <cmath>

namespace mfwave {

namespace {

constexpr Real kCut = 3.0;

// Mass of pi^{-d/2} exp(-|x|^2) inside the unit-h ball of radius 3: the radial integral
// S_d int_0^3 q^{d-1} e^{-q^2} dq with S_1 = 2, S_2 = 2 pi, S_3 = 4 pi, in closed form.
Real truncatedMass(int d) {
  const Real e9 = std::exp(-kCut * kCut);
  switch (d) {
    case 1: return std::erf(kCut);
    case 2: return 1.0 - e9;
    default: return std::erf(kCut) - 2.0 * kCut / std::sqrt(kPi) * e9;
  }
}

// pi^{-d/2} / truncated mass.
std::array<Real, 3> gaussianSigma() {
  return {1.0 / (std::sqrt(kPi) * truncatedMass(1)), 1.0 / (kPi * truncatedMass(2)),
          1.0 / (kPi * std::sqrt(kPi) * truncatedMass(3))};
}

}  // namespace

GaussianKernel::GaussianKernel(int dimension, Real h) : Kernel(dimension, h, kCut, gaussianSigma(), "smoothing_length") {}

Real GaussianKernel::shape(Real q) const { return GaussianProfile{}.shape(q); }

// f' = -2 q e^{-q^2}; f'' = (4 q^2 - 2) e^{-q^2}.
Real GaussianKernel::slopeOverQ(Real q) const { return GaussianProfile{}.slopeOverQ(q); }

Kernel::Curvature GaussianKernel::curvature(Real q) const {
  if (q >= kCut) return {0.0, 0.0};
  const Real e = std::exp(-q * q);
  return {-2.0 * e, (4.0 * q * q - 2.0) * e};
}

}  // namespace mfwave
