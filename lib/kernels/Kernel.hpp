#pragma once
// Radial SPH kernel W(r, h) = sigma_d / h^d f(q), q = |r| / h, with value, gradient and Hessian.
//
// A concrete kernel supplies only the dimensionless profile f; this base turns it into W and its
// derivatives. The evaluators are inline and allocation-free because they run once per particle
// pair in the hot loops; the profile costs one virtual call per evaluation.
//
// The profile is asked for f'(q)/q rather than f'(q): every kernel here has f'(0) = 0, so f'(q)/q
// is a polynomial near the centre (f''(0) at q = 0). Evaluating it directly keeps the gradient
// sigma/h^{d+2} (f'/q) r and the isotropic part of the Hessian exact at and near r = 0, with no
// division by |r| and no sqrt-induced cancellation.

#include "core/Types.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace mfwave {

class Kernel {
 public:
  // f'(q)/q and f''(q) at one q: what the Hessian needs.
  struct Curvature {
    Real slopeOverQ;
    Real second;
  };

  virtual ~Kernel() = default;

  virtual const char* name() const = 0;

  int dimension() const { return dimension_; }
  // The length the profile is scaled by: h for SPH kernels, the support radius a for the
  // reproducing-kernel B-spline.
  Real smoothingLength() const { return h_; }
  Real supportRadius() const { return supportRadius_; }
  // kappa: support radius in units of the smoothing length.
  Real supportFactor() const { return kappa_; }
  // sigma_d: makes W integrate to 1 over R^d.
  Real normalisation() const { return sigma_; }
  // 1 / h, sigma / h^d (W = this * f) and sigma / h^{d+2} (grad W = this * (f'/q) r): what
  // InlineKernel (KernelProfiles.hpp) needs to evaluate W exactly as value() and gradient() do.
  Real inverseSmoothingLength() const { return invH_; }
  Real valueScale() const { return valueScale_; }
  Real derivativeScale() const { return derivativeScale_; }

  // Dimensionless profile. All are zero for q >= supportFactor().
  virtual Real shape(Real q) const = 0;            // f(q)
  virtual Real slopeOverQ(Real q) const = 0;       // f'(q) / q, equal to f''(0) at q = 0
  virtual Curvature curvature(Real q) const = 0;   // {f'(q)/q, f''(q)}
  Real shapeDerivative(Real q) const { return q * slopeOverQ(q); }
  Real shapeSecondDerivative(Real q) const { return curvature(q).second; }
  // Points 0 = q_0 < ... < q_n = supportFactor() between which f is one smooth (for the splines,
  // polynomial) piece: lets quadrature integrate the kernel exactly.
  virtual std::vector<Real> pieceBreaks() const = 0;

  // W at distance r (any sign; only |r| matters).
  Real value(Real r) const { return valueScale_ * shape(std::abs(r) * invH_); }

  // W(r) for r = x_a - x_b. D must equal dimension().
  template <int D>
  Real value(const Vec<D>& r) const {
    checkDimension(D);
    const Real r2 = r.squaredNorm();
    if (r2 >= supportRadius2_) return 0.0;
    return valueScale_ * shape(std::sqrt(r2) * invH_);
  }

  // dW/dr_j = sigma/h^{d+1} f'(q) e_j, e = r/|r|; zero at r = 0.
  template <int D>
  Vec<D> gradient(const Vec<D>& r) const {
    checkDimension(D);
    const Real r2 = r.squaredNorm();
    if (r2 >= supportRadius2_) return Vec<D>::Zero();
    return (derivativeScale_ * slopeOverQ(std::sqrt(r2) * invH_)) * r;
  }

  // d2W/dr_i dr_j = sigma/h^{d+2} [ f'' e e^T + (f'/q) (I - e e^T) ]
  //               = sigma/h^{d+2} [ (f'/q) I + (f'' - f'/q) e e^T ].
  // At r = 0 the second term vanishes (f'' = f'/q there) and the Hessian is sigma/h^{d+2} f''(0) I.
  template <int D>
  Mat<D> hessian(const Vec<D>& r) const {
    checkDimension(D);
    const Real r2 = r.squaredNorm();
    if (r2 >= supportRadius2_) return Mat<D>::Zero();
    const Curvature c = curvature(std::sqrt(r2) * invH_);
    Mat<D> hess = (derivativeScale_ * c.slopeOverQ) * Mat<D>::Identity();
    if (r2 > 0.0) hess.noalias() += (derivativeScale_ * (c.second - c.slopeOverQ) / r2) * (r * r.transpose());
    return hess;
  }

  // The same for Eigen expressions such as x_a - x_b, which do not deduce Vec<D>.
  template <class Derived>
  Real value(const Eigen::MatrixBase<Derived>& r) const {
    return value<fixedRows<Derived>()>(Vec<fixedRows<Derived>()>(r));
  }
  template <class Derived>
  Vec<Derived::RowsAtCompileTime> gradient(const Eigen::MatrixBase<Derived>& r) const {
    return gradient<fixedRows<Derived>()>(Vec<fixedRows<Derived>()>(r));
  }
  template <class Derived>
  Mat<Derived::RowsAtCompileTime> hessian(const Eigen::MatrixBase<Derived>& r) const {
    return hessian<fixedRows<Derived>()>(Vec<fixedRows<Derived>()>(r));
  }

 protected:
  // sigmaByDimension[d - 1] is sigma_d. Throws InputError("dimension") unless 1 <= dimension <= 3
  // and InputError(lengthKey) unless length > 0 and finite.
  Kernel(int dimension, Real length, Real supportFactor, const std::array<Real, 3>& sigmaByDimension,
         const char* lengthKey);
  Kernel(const Kernel&) = default;             // protected: copying through the base would slice
  Kernel& operator=(const Kernel&) = default;

 private:
  template <class Derived>
  static constexpr int fixedRows() {
    static_assert(Derived::ColsAtCompileTime == 1 && Derived::RowsAtCompileTime >= 1 &&
                      Derived::RowsAtCompileTime <= 3,
                  "kernel evaluators take a fixed-size 1-, 2- or 3-vector");
    return Derived::RowsAtCompileTime;
  }

  void checkDimension(int d) const {
    if (d != dimension_) throwDimensionMismatch(d);
  }
  [[noreturn]] void throwDimensionMismatch(int d) const;

  int dimension_;
  Real h_;
  Real invH_;
  Real kappa_;
  Real supportRadius_;
  Real supportRadius2_;
  Real sigma_;
  Real valueScale_;       // sigma / h^d
  Real derivativeScale_;  // sigma / h^{d+2}: gradient = this * (f'/q) r
};

}  // namespace mfwave
