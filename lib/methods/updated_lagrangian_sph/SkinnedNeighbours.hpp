#pragma once
// Neighbour lists for moving particles with a skin (Verlet lists): built with radius
// (1 + skin) R, R the kernel support, and rebuilt only when some particle has moved more than
// skin R / 2 since the last build. Then every pair closer than R is still listed (each of the two
// moved at most skin R / 2, so at the build they were closer than (1 + skin) R), and the pair sums,
// which skip listed pairs beyond R, are the same as with freshly built lists.

#include "core/StateArchive.hpp"
#include "core/Types.hpp"
#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"

#include <functional>

namespace mfwave {

template <int D>
class SkinnedNeighbours {
 public:
  SkinnedNeighbours(Real supportRadius, Real skin);
  // Keeps only the pairs (i, j) for which interacts(i, j) is true at every rebuild (the self pair
  // always): a crack's visibility criterion. Empty (the default): every pair within the radius.
  void setPairFilter(std::function<bool(Index, Index)> interacts) { interacts_ = std::move(interacts); }

  // Makes the lists valid for positions x (particle-major, count * D entries). Returns true when it
  // rebuilt them.
  bool refresh(const Real* x, Index count);

  const NeighbourList& list() const { return list_; }
  long rebuilds() const { return rebuilds_; }
  Real listRadius() const { return cells_.radius(); }

  // Checkpoints: the positions at the last build and the rebuild count. restoreState rebuilds the
  // lists from those very positions, so the restored lists hold the same pairs in the same order
  // (pair sums in the same order: bitwise the same rates) and the next refresh rebuilds exactly
  // when the uninterrupted run would.
  void saveState(StateArchive& archive) const;
  void restoreState(const StateArchive& archive);

 private:
  void rebuild(const Real* x, Index count);

  Real trigger2_;  // (skin R / 2)^2
  CellList<D> cells_;
  NeighbourList list_;
  Coordinates<D> built_;  // positions at the last build
  long rebuilds_ = 0;
  std::function<bool(Index, Index)> interacts_;
};

extern template class SkinnedNeighbours<1>;
extern template class SkinnedNeighbours<2>;
extern template class SkinnedNeighbours<3>;

}  // namespace mfwave
