#pragma once
// The dimensionless profiles f(q) and f'(q)/q of every kernel here as small inline structs, and
// InlineKernel<Profile>: W and grad W from a profile with no virtual call, for hot pair loops that
// are templates on the kernel type (lib/methods/updated_lagrangian_sph/PairTable.cpp). The virtual
// kernels (CubicSplineKernel, ...) evaluate their profiles through these very structs, so the two
// paths compute the same expressions (tests/kernels/InlineKernelTest.cpp checks they agree).
// visitInlineKernel(kernel, f) calls f(InlineKernel<P>) for the profile P of a kernel: one
// dispatch per call instead of one virtual call per pair.

#include "core/Error.hpp"
#include "core/Types.hpp"
#include "kernels/Kernel.hpp"

#include <cmath>
#include <cstring>
#include <string>

namespace mfwave {

// Li primer eq. (8): f = 1 - 3/2 q^2 + 3/4 q^3 (q <= 1), 1/4 (2 - q)^3 (1 < q <= 2).
struct CubicSplineProfile {
  Real shape(Real q) const {
    if (q < 1.0) return 1.0 + q * q * (-1.5 + 0.75 * q);
    if (q < 2.0) {
      const Real t = 2.0 - q;
      return 0.25 * t * t * t;
    }
    return 0.0;
  }
  Real slopeOverQ(Real q) const {
    if (q < 1.0) return -3.0 + 2.25 * q;
    if (q < 2.0) {
      const Real t = 2.0 - q;
      return -0.75 * t * t / q;
    }
    return 0.0;
  }
};

// Luo-Liu-Huang eq. (6), z = |r| / a: phi = 2/3 - 4 z^2 + 4 z^3 (z <= 1/2), 4/3 (1 - z)^3 (z <= 1).
struct CubicBSplineProfile {
  Real shape(Real z) const {
    if (z < 0.5) return 2.0 / 3.0 + z * z * (-4.0 + 4.0 * z);
    if (z < 1.0) {
      const Real t = 1.0 - z;
      return 4.0 / 3.0 * t * t * t;
    }
    return 0.0;
  }
  // phi' = -8 z + 12 z^2 (z <= 1/2), -4 (1 - z)^2.
  Real slopeOverQ(Real z) const {
    if (z < 0.5) return -8.0 + 12.0 * z;
    if (z < 1.0) {
      const Real t = 1.0 - z;
      return -4.0 * t * t / z;
    }
    return 0.0;
  }
};

// Li primer eq. (7): f = exp(-q^2) cut at q = 3 (the normalisation is the kernel's).
struct GaussianProfile {
  static constexpr Real cut = 3.0;
  Real shape(Real q) const { return q < cut ? std::exp(-q * q) : 0.0; }
  // f' = -2 q e^{-q^2}.
  Real slopeOverQ(Real q) const { return q < cut ? -2.0 * std::exp(-q * q) : 0.0; }
};

// Morris's quintic: f = (3-q)^5 - 6 (2-q)^5 + 15 (1-q)^5, each term only where its base is positive.
struct QuinticSplineProfile {
  static Real pow4(Real t) { return (t * t) * (t * t); }
  static Real pow5(Real t) { return pow4(t) * t; }
  Real shape(Real q) const {
    if (q >= 3.0) return 0.0;
    Real f = pow5(3.0 - q);
    if (q < 2.0) f -= 6.0 * pow5(2.0 - q);
    if (q < 1.0) f += 15.0 * pow5(1.0 - q);
    return f;
  }
  // f' = -5 (3-q)^4 + 30 (2-q)^4 - 75 (1-q)^4. On the inner piece the three terms cancel to O(q),
  // so f'/q is taken from its expanded polynomial -120 + 120 q^2 - 50 q^3 instead of dividing.
  Real slopeOverQ(Real q) const {
    if (q < 1.0) return -120.0 + q * q * (120.0 - 50.0 * q);
    if (q < 2.0) return (-5.0 * pow4(3.0 - q) + 30.0 * pow4(2.0 - q)) / q;
    if (q < 3.0) return -5.0 * pow4(3.0 - q) / q;
    return 0.0;
  }
};

// Wendland C2, s = 1 - q/2: 1-D f = s^3 (3/2 q + 1), f'/q = -3 s^2; 2-/3-D f = s^4 (2 q + 1),
// f'/q = -5 s^3.
struct WendlandC2Profile {
  bool oneD = false;
  Real shape(Real q) const {
    if (q >= 2.0) return 0.0;
    const Real s = 1.0 - 0.5 * q;
    if (oneD) return s * s * s * (1.5 * q + 1.0);
    return (s * s) * (s * s) * (2.0 * q + 1.0);
  }
  Real slopeOverQ(Real q) const {
    if (q >= 2.0) return 0.0;
    const Real s = 1.0 - 0.5 * q;
    if (oneD) return -3.0 * s * s;
    return -5.0 * s * s * s;
  }
};

// Wendland C4, s = 1 - q/2: 1-D f = s^5 (2 q^2 + 5/2 q + 1), f'/q = -7/2 s^4 (2 q + 1);
// 2-/3-D f = s^6 (35/12 q^2 + 3 q + 1), f'/q = -7/3 s^5 (5 q + 2).
struct WendlandC4Profile {
  bool oneD = false;
  Real shape(Real q) const {
    if (q >= 2.0) return 0.0;
    const Real s = 1.0 - 0.5 * q;
    const Real s2 = s * s;
    if (oneD) return s2 * s2 * s * ((2.0 * q + 2.5) * q + 1.0);
    return s2 * s2 * s2 * ((35.0 / 12.0 * q + 3.0) * q + 1.0);
  }
  Real slopeOverQ(Real q) const {
    if (q >= 2.0) return 0.0;
    const Real s = 1.0 - 0.5 * q;
    const Real s2 = s * s;
    if (oneD) return -3.5 * s2 * s2 * (2.0 * q + 1.0);
    return -7.0 / 3.0 * s2 * s2 * s * (5.0 * q + 2.0);
  }
};

// W and grad W of a kernel with its profile inlined: the same expressions as Kernel::value and
// Kernel::gradient (Kernel.hpp), without the virtual call and the dimension check.
template <class Profile>
class InlineKernel {
 public:
  InlineKernel(const Kernel& kernel, Profile profile)
      : profile_(profile),
        invH_(kernel.inverseSmoothingLength()),
        supportRadius2_(kernel.supportRadius() * kernel.supportRadius()),
        valueScale_(kernel.valueScale()),
        derivativeScale_(kernel.derivativeScale()) {}

  Real supportRadius2() const { return supportRadius2_; }

  // W at distance r >= 0 and (dW/dr) / r there (grad W = that * r), for r inside the support.
  Real valueAt(Real r) const { return valueScale_ * profile_.shape(r * invH_); }
  Real gradientFactorAt(Real r) const { return derivativeScale_ * profile_.slopeOverQ(r * invH_); }

  template <int D>
  Real value(const Vec<D>& r) const {
    const Real r2 = r.squaredNorm();
    if (r2 >= supportRadius2_) return 0.0;
    return valueAt(std::sqrt(r2));
  }
  template <int D>
  Vec<D> gradient(const Vec<D>& r) const {
    const Real r2 = r.squaredNorm();
    if (r2 >= supportRadius2_) return Vec<D>::Zero();
    return gradientFactorAt(std::sqrt(r2)) * r;
  }

 private:
  Profile profile_;
  Real invH_;
  Real supportRadius2_;
  Real valueScale_;
  Real derivativeScale_;
};

// f(InlineKernel<P>(kernel, ...)) for the profile P of `kernel` (by its name()); every kernel of
// kernelNames() has one. Throws Error for a kernel without an inline profile.
template <class F>
decltype(auto) visitInlineKernel(const Kernel& kernel, F&& f) {
  const char* name = kernel.name();
  const bool oneD = kernel.dimension() == 1;
  if (std::strcmp(name, "cubic_spline") == 0) return f(InlineKernel<CubicSplineProfile>(kernel, {}));
  if (std::strcmp(name, "gaussian") == 0) return f(InlineKernel<GaussianProfile>(kernel, {}));
  if (std::strcmp(name, "quintic_spline") == 0) return f(InlineKernel<QuinticSplineProfile>(kernel, {}));
  if (std::strcmp(name, "wendland_c2") == 0) return f(InlineKernel<WendlandC2Profile>(kernel, {oneD}));
  if (std::strcmp(name, "wendland_c4") == 0) return f(InlineKernel<WendlandC4Profile>(kernel, {oneD}));
  if (std::strcmp(name, "cubic_b_spline") == 0) return f(InlineKernel<CubicBSplineProfile>(kernel, {}));
  throw Error(std::string("visitInlineKernel: no inline profile for the kernel '") + name + "'");
}

}  // namespace mfwave
