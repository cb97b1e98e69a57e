#pragma once
// Radial basis functions g(r) of radial-basis collocation, written as functions of s = r^2:
//
//   inverse_multiquadric  g = (r^2 + c^2)^(-1/2)   (Luo-Liu-Huang's RBCM, with c = a_r)
//   multiquadric          g = (r^2 + c^2)^(1/2)
//   gaussian              g = exp(-(r/c)^2)
//
// Why s = r^2: each profile f(s) is smooth in s, so with r = x - x_j
//   grad g = 2 f'(s) r,   Hessian g = 2 f'(s) I + 4 f''(s) r r^T,
// exact everywhere, also at r = 0, with no division by |r|.

#include <string>
#include <vector>

#include "core/Types.hpp"

namespace mfwave {

enum class RadialBasisKind { InverseMultiquadric, Multiquadric, Gaussian };

// "inverse_multiquadric", "multiquadric", "gaussian", in that order.
const std::vector<std::string>& radialBasisNames();
const char* radialBasisName(RadialBasisKind kind);
// Throws InputError("method.basis", "unknown ...; valid: ...").
RadialBasisKind radialBasisKind(const std::string& name);

class RadialBasisFunction {
 public:
  // f(s), f'(s), f''(s) at s = r^2.
  struct Profile {
    Real value;
    Real first;
    Real second;
  };

  // Throws InputError("method.shape_parameter") unless c > 0 and finite.
  RadialBasisFunction(RadialBasisKind kind, Real shapeParameter);

  RadialBasisKind kind() const { return kind_; }
  const char* name() const { return radialBasisName(kind_); }
  Real shapeParameter() const { return c_; }

  Profile profile(Real squaredDistance) const;

  // g(r), grad g(r), Hessian g(r) with respect to x for r = x - x_j.
  template <int D>
  Real value(const Vec<D>& r) const {
    return profile(r.squaredNorm()).value;
  }
  template <int D>
  Vec<D> gradient(const Vec<D>& r) const {
    return (2 * profile(r.squaredNorm()).first) * r;
  }
  template <int D>
  Mat<D> hessian(const Vec<D>& r) const {
    const Profile p = profile(r.squaredNorm());
    Mat<D> h = (2 * p.first) * Mat<D>::Identity();
    h.noalias() += (4 * p.second) * (r * r.transpose());
    return h;
  }

 private:
  RadialBasisKind kind_;
  Real c_;
  Real c2_;
};

// Factory from the scene name: makeRadialBasisFunction("inverse_multiquadric", c).
RadialBasisFunction makeRadialBasisFunction(const std::string& name, Real shapeParameter);

}  // namespace mfwave
