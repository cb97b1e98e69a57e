#include "spectra/SpectralElementDispersion.hpp"

#include "core/Error.hpp"
#include "methods/spectral_element/GaussLobattoLegendre.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <limits>

namespace mfwave {
namespace {

// The Bloch eigenvalues omega^2 / c^2 at wavenumber k.
Eigen::VectorXcd blochEigenvalues(int order, Real spacing, Real wavenumber) {
  if (order < 1) throw InputError("order", "must be at least 1, got " + std::to_string(order));
  const QuadratureRule rule = gaussLobattoLegendre(order);
  const Eigen::MatrixXd d = lagrangeDerivativeMatrix(rule.nodes);  // d(q, j) = l_j'(x_q) on [-1, 1]
  const int n = order + 1;
  const Real h = order * spacing;
  // Element matrices on [0, h]: d/dx = (2 / h) d/dxi.
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (int q = 0; q < n; ++q)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) k(i, j) += rule.weights[static_cast<std::size_t>(q)] * d(q, i) * d(q, j);
  k *= 2 / h;
  // Fold node N onto node 0 of the next element: phase exp(i k h).
  const std::complex<Real> phase = std::polar(Real(1), wavenumber * h);
  Eigen::MatrixXcd kb = Eigen::MatrixXcd::Zero(order, order);
  Eigen::VectorXd mb = Eigen::VectorXd::Zero(order);
  const auto fold = [order](int i) { return i == order ? 0 : i; };
  const auto factor = [order, phase](int i) { return i == order ? phase : std::complex<Real>(1); };
  for (int i = 0; i < n; ++i) {
    mb[fold(i)] += rule.weights[static_cast<std::size_t>(i)] * h / 2;
    for (int j = 0; j < n; ++j) kb(fold(i), fold(j)) += std::conj(factor(i)) * factor(j) * k(i, j);
  }
  const Eigen::MatrixXcd a = mb.cwiseInverse().asDiagonal() * kb;
  return Eigen::ComplexEigenSolver<Eigen::MatrixXcd>(a).eigenvalues();
}

}  // namespace

Real spectralElementFrequency(int order, Real spacing, Real speed, Real wavenumber) {
  if (!(wavenumber > 0)) throw InputError("wavenumber", "must be positive");
  const Eigen::VectorXcd lambda = blochEigenvalues(order, spacing, wavenumber);
  const Real exact = speed * wavenumber;
  Real best = std::numeric_limits<Real>::quiet_NaN(), distance = std::numeric_limits<Real>::infinity();
  for (Index b = 0; b < lambda.size(); ++b) {
    const Real omega = speed * std::sqrt(std::max<Real>(0, lambda[b].real()));
    if (std::abs(omega - exact) < distance) {
      distance = std::abs(omega - exact);
      best = omega;
    }
  }
  return best;
}

Real spectralElementLargestFrequency(int order, Real spacing, Real speed) {
  Real largest = 0;
  const Real h = order * spacing;
  for (int s = 0; s <= 64; ++s) {
    const Real k = kPi / h * s / 64;
    const Eigen::VectorXcd lambda = blochEigenvalues(order, spacing, k);
    for (Index b = 0; b < lambda.size(); ++b) largest = std::max(largest, std::abs(lambda[b]));
  }
  return speed * std::sqrt(largest);
}

}  // namespace mfwave
