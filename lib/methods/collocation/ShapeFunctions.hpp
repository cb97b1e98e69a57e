#pragma once
// The common face of the collocation shape functions: reproducing-kernel (RK) and radial-basis
// (RBF) shape functions both answer "which nodes act at x, and with what psi_i(x), grad psi_i(x),
// Hessian psi_i(x)". Collocation assembly and the von Neumann analysis (Luo-Liu-Huang eqs.
// (34)-(45): M_ij = psi_j(xi_i), A_ij = psi_j,xx(xi_i)) only need this interface.
//
// Why an output struct the caller owns: the evaluators run once per collocation point in hot loops
// (possibly one per OpenMP thread). The caller keeps one ShapeFunctionValues per thread and passes
// it again and again; its vectors keep their capacity, so after the first few points evaluation
// does not allocate. The evaluators themselves hold no mutable state and are thread-safe.

#include <array>
#include <string>
#include <vector>

#include "core/Types.hpp"

namespace mfwave {

template <int D>
struct ShapeFunctionValues {
  // The nodes whose shape function may be non-zero at x, in increasing index order
  // (every node for the dense RBF functions).
  std::vector<Index> nodes;
  // value[k] = psi_{nodes[k]}(x).
  std::vector<Real> value;
  // gradient[k] = d psi_{nodes[k]} / dx (filled when derivatives >= 1, otherwise empty).
  std::vector<Vec<D>> gradient;
  // hessian[k] = d2 psi_{nodes[k]} / dx dx^T, symmetric (filled when derivatives == 2, otherwise empty).
  std::vector<Mat<D>> hessian;
  // Scratch storage of the evaluators (kernel values per neighbour, right-hand sides), kept here
  // so that its capacity is reused between calls. Contents are unspecified.
  std::vector<Real> workspace;

  Index size() const { return static_cast<Index>(nodes.size()); }
};

template <int D>
class ShapeFunctions {
  static_assert(D >= 1 && D <= 3, "shape functions exist in 1, 2 and 3 dimensions");

 public:
  static constexpr int dimension = D;

  virtual ~ShapeFunctions();

  // Number of nodes (columns of a shape-function matrix).
  virtual Index nodeCount() const = 0;

  // psi_i(x) of every node i that acts at x, and with derivatives >= 1 the gradients, with
  // derivatives == 2 also the Hessians. Throws InputError("method.derivatives") unless derivatives
  // is 0, 1 or 2; the concrete classes throw InputError for points where the functions do not exist.
  virtual void evaluate(const Vec<D>& x, int derivatives, ShapeFunctionValues<D>& out) const = 0;

  // A short description for logs and summaries, e.g. "reproducing_kernel(m=2, cubic_b_spline, a=0.25)".
  virtual std::string name() const = 0;

 protected:
  ShapeFunctions() = default;
  ShapeFunctions(const ShapeFunctions&) = default;  // protected: copying through the base would slice
  ShapeFunctions& operator=(const ShapeFunctions&) = default;

  // Throws InputError("method.derivatives", ...) unless 0 <= derivatives <= 2.
  static void checkDerivatives(int derivatives);
};

// Resizes out's node, value, gradient and Hessian arrays for `count` nodes and the requested
// derivatives (derivative arrays not asked for are emptied). Capacity is kept.
template <int D>
void resizeShapeFunctionValues(ShapeFunctionValues<D>& out, std::size_t count, int derivatives);

// Validates node coordinates handed to a shape-function constructor: every axis holds the same
// number of finite values, and there is at least one node. Throws InputError("method.nodes", ...).
template <int D>
Index checkedNodeCount(const std::array<std::vector<Real>, D>& nodes);

// Formats a point as "(x, y, z)" for error messages.
template <int D>
std::string formatPoint(const Vec<D>& x);

extern template struct ShapeFunctionValues<1>;
extern template struct ShapeFunctionValues<2>;
extern template struct ShapeFunctionValues<3>;
extern template class ShapeFunctions<1>;
extern template class ShapeFunctions<2>;
extern template class ShapeFunctions<3>;

}  // namespace mfwave
