#include "geometry/LatticeNodesInside.hpp"

#include "geometry/LatticeWindow.hpp"

namespace mfwave {

template <int D>
InsideNodes<D> latticeNodesInside(const Solid<D>& solid, Real dx, const Vec<D>& origin) {
  const LatticeWindow<D> window = latticeWindow<D>(solid.bounds(), dx, origin, 0.0);
  InsideNodes<D> nodes;
  const Index count = window.count();
  for (Index k = 0; k < count; ++k) {
    const std::array<Index, D> node = window.node(k);
    const Vec<D> x = latticePoint<D>(origin, dx, node);
    if (solid.signedDistance(x) <= 1e-9 * dx) {
      nodes.node.push_back(node);
      nodes.position.push_back(x);
    }
  }
  return nodes;
}

template InsideNodes<2> latticeNodesInside<2>(const Solid<2>&, Real, const Vec2&);
template InsideNodes<3> latticeNodesInside<3>(const Solid<3>&, Real, const Vec3&);

}  // namespace mfwave
