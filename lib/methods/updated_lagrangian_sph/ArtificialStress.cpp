#include "methods/updated_lagrangian_sph/ArtificialStress.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace mfwave {

template <int D>
Mat<D> artificialStressTensor(const Mat<D>& sigma, Real rho, Real epsilon) {
  const Real scale = -epsilon / (rho * rho);
  if constexpr (D == 1) {
    return Mat<D>::Constant(sigma(0, 0) > 0 ? scale * sigma(0, 0) : 0.0);
  } else if constexpr (D == 2) {
    // Closed form in 2-D: l = mean +- radius. Both in tension: R' = scale diag(l), R = scale sigma.
    // Only the larger: R = scale l_1 e_1 e_1^T with the projector e_1 e_1^T = (sigma - l_2 I) / (l_1 - l_2),
    // where l_1 - l_2 = 2 radius >= l_1 > 0 (well conditioned).
    const Real mean = 0.5 * (sigma(0, 0) + sigma(1, 1));
    const Real halfDifference = 0.5 * (sigma(0, 0) - sigma(1, 1));
    const Real shear = 0.5 * (sigma(0, 1) + sigma(1, 0));
    const Real radius = std::sqrt(halfDifference * halfDifference + shear * shear);  // stresses: no overflow
    const Real larger = mean + radius;
    const Real smaller = mean - radius;
    if (!(larger > 0)) return Mat<D>::Zero();  // no tension: no correction
    if (smaller > 0) return scale * sigma;
    Mat<D> projector = sigma;
    projector.diagonal().array() -= smaller;
    return (scale * larger / (2 * radius)) * projector;
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
