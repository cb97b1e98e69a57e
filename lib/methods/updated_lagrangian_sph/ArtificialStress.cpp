#include "methods/updated_lagrangian_sph/ArtificialStress.hpp"

#include <Eigen/Eigenvalues>

namespace mfwave {

template <int D>
Mat<D> artificialStressTensor(const Mat<D>& sigma, Real rho, Real epsilon) {
  const Real scale = -epsilon / (rho * rho);
  if constexpr (D == 1) {
    return Mat<D>::Constant(sigma(0, 0) > 0 ? scale * sigma(0, 0) : 0.0);
  } else {
    // Principal frame of sigma (Gray, Monaghan & Swift 2001, eq. 4.5-4.7 in their notation).
    Eigen::SelfAdjointEigenSolver<Mat<D>> eigen(sigma);
    const Vec<D> principal = eigen.eigenvalues();
    if (!(principal.maxCoeff() > 0)) return Mat<D>::Zero();  // no tension: no correction
    Vec<D> diagonal;
    for (int a = 0; a < D; ++a) diagonal[a] = principal[a] > 0 ? scale * principal[a] : 0.0;
    const Mat<D>& q = eigen.eigenvectors();
    return q * diagonal.asDiagonal() * q.transpose();
  }
}

template Mat<1> artificialStressTensor<1>(const Mat<1>&, Real, Real);
template Mat<2> artificialStressTensor<2>(const Mat<2>&, Real, Real);
template Mat<3> artificialStressTensor<3>(const Mat<3>&, Real, Real);

}  // namespace mfwave
