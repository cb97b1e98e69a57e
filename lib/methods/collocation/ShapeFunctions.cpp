#include "methods/collocation/ShapeFunctions.hpp"

#include <array>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"

namespace mfwave {

template <int D>
ShapeFunctions<D>::~ShapeFunctions() = default;

template <int D>
void ShapeFunctions<D>::checkDerivatives(int derivatives) {
  if (derivatives < 0 || derivatives > 2) {
    throw InputError("method.derivatives",
                     "asked for derivatives of order " + std::to_string(derivatives) + "; valid: 0, 1, 2");
  }
}

template <int D>
void resizeShapeFunctionValues(ShapeFunctionValues<D>& out, std::size_t count, int derivatives) {
  out.nodes.resize(count);
  out.value.resize(count);
  out.gradient.resize(derivatives >= 1 ? count : 0);
  out.hessian.resize(derivatives >= 2 ? count : 0);
}

template <int D>
Index checkedNodeCount(const std::array<std::vector<Real>, D>& nodes) {
  const std::size_t count = nodes[0].size();
  for (int a = 1; a < D; ++a) {
    if (nodes[static_cast<std::size_t>(a)].size() != count) {
      throw InputError("method.nodes", "the coordinate arrays differ in length (" + std::to_string(count) + " x, " +
                                           std::to_string(nodes[static_cast<std::size_t>(a)].size()) + " along axis " +
                                           std::to_string(a) + ")");
    }
  }
  if (count == 0) throw InputError("method.nodes", "no nodes: shape functions need at least one node");
  for (int a = 0; a < D; ++a) {
    for (std::size_t i = 0; i < count; ++i) {
      if (!std::isfinite(nodes[static_cast<std::size_t>(a)][i])) {
        throw InputError("method.nodes", "node " + std::to_string(i) + " has a non-finite coordinate");
      }
    }
  }
  return static_cast<Index>(count);
}

template <int D>
std::string formatPoint(const Vec<D>& x) {
  std::ostringstream text;
  text.precision(10);
  text << '(';
  for (int a = 0; a < D; ++a) text << (a > 0 ? ", " : "") << x[a];
  text << ')';
  return text.str();
}

template struct ShapeFunctionValues<1>;
template struct ShapeFunctionValues<2>;
template struct ShapeFunctionValues<3>;
template class ShapeFunctions<1>;
template class ShapeFunctions<2>;
template class ShapeFunctions<3>;
template void resizeShapeFunctionValues<1>(ShapeFunctionValues<1>&, std::size_t, int);
template void resizeShapeFunctionValues<2>(ShapeFunctionValues<2>&, std::size_t, int);
template void resizeShapeFunctionValues<3>(ShapeFunctionValues<3>&, std::size_t, int);
template Index checkedNodeCount<1>(const std::array<std::vector<Real>, 1>&);
template Index checkedNodeCount<2>(const std::array<std::vector<Real>, 2>&);
template Index checkedNodeCount<3>(const std::array<std::vector<Real>, 3>&);
template std::string formatPoint<1>(const Vec<1>&);
template std::string formatPoint<2>(const Vec<2>&);
template std::string formatPoint<3>(const Vec<3>&);

}  // namespace mfwave
