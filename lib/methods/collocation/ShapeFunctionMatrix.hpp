#pragma once
// Shape-function matrices over a set of evaluation points: row r is the point points[r], column i
// the node i, entry the chosen derivative of psi_i at that point. These are the matrices of
// collocation and of the von Neumann analysis (Luo-Liu-Huang eqs. (34), (35)):
//   M_ij = psi_j(xi_i)       shapeFunctionMatrix(shapes, points, ShapeDerivative::value())
//   A_ij = psi_j,xx(xi_i)    shapeFunctionMatrix(shapes, points, ShapeDerivative::hessian(0, 0))
//
// Sparse for RK functions (a row holds the nodes within the support radius); the dense RBF
// functions fill every entry, for them denseShapeFunctionMatrix avoids the sparse overhead.
// Points are evaluated in parallel (OpenMP), one ShapeFunctionValues per thread; the result does
// not depend on the number of threads. An InputError from any point is rethrown (the one of the
// lowest-numbered failing point).

#include <Eigen/Core>
#include <vector>

#include "methods/collocation/ShapeFunctions.hpp"
#include "particles/ParticleSet.hpp"

namespace mfwave {

// Which derivative of the shape functions a matrix holds: the value (order 0), d/dx_axis1
// (order 1) or d2/dx_axis1 dx_axis2 (order 2); axes 0..D-1.
struct ShapeDerivative {
  int order = 0;
  int axis1 = 0;
  int axis2 = 0;

  static ShapeDerivative value() { return {0, 0, 0}; }
  static ShapeDerivative gradient(int axis) { return {1, axis, 0}; }
  static ShapeDerivative hessian(int axis1, int axis2) { return {2, axis1, axis2}; }
};

// The points x_i of a coordinate array (e.g. the nodes themselves, as collocation points).
template <int D>
std::vector<Vec<D>> pointsOf(const Coordinates<D>& coordinates);

// rows = points, columns = shapes.nodeCount(). Throws InputError("method.derivative") for an
// order outside 0..2 or an axis outside 0..D-1, and whatever shapes.evaluate throws.
template <int D>
SparseMatrix shapeFunctionMatrix(const ShapeFunctions<D>& shapes, const std::vector<Vec<D>>& points,
                                 const ShapeDerivative& derivative);

// Several derivatives at once, evaluating each point once: result[k] is for derivatives[k].
template <int D>
std::vector<SparseMatrix> shapeFunctionMatrices(const ShapeFunctions<D>& shapes, const std::vector<Vec<D>>& points,
                                                const std::vector<ShapeDerivative>& derivatives);

// The same as a dense matrix (every entry stored, zeros included).
template <int D>
Eigen::MatrixXd denseShapeFunctionMatrix(const ShapeFunctions<D>& shapes, const std::vector<Vec<D>>& points,
                                         const ShapeDerivative& derivative);

}  // namespace mfwave
