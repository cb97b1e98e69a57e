#pragma once
// Gauss-Lobatto-Legendre (GLL) quadrature and the Lagrange derivative matrix on its nodes: the
// one-dimensional building blocks of the spectral-element method. With the interpolation nodes
// and the quadrature points the same, the mass matrix is diagonal (Komatitsch & Tromp 1999); the
// N + 1 point rule is exact for polynomials of degree 2N - 1.

#include "core/GaussLegendre.hpp"
#include "core/Types.hpp"

#include <vector>

namespace mfwave {

// The N + 1 GLL points of order N >= 1 on [-1, 1], ascending: -1, 1 and the roots of P'_N (by
// Newton's method on the Legendre recurrence), with weights 2 / (N (N + 1) P_N(x_i)^2).
// Throws InputError("order") for N < 1.
QuadratureRule gaussLobattoLegendre(int order);

// D(i, j) = l_j'(x_i) for the Lagrange polynomials l_j of distinct nodes x (barycentric form:
// Berrut & Trefethen 2004; each diagonal entry is minus its row's other entries, so D annihilates
// constants to rounding).
Eigen::MatrixXd lagrangeDerivativeMatrix(const std::vector<Real>& nodes);

}  // namespace mfwave
