#include "lattice/DashpotSurfaceSolve.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <string>

namespace mfwave {

template <int D, int C>
DashpotSurfaceSolve<D, C>::DashpotSurfaceSolve(const LatticeSecondOrderSystem<D, C>& system, Real dt,
                                            const std::vector<Index>& prescribedDofs) {
  const LatticeRowTypes<D>& types = system.types();
  const LatticeStencils<D, C>& c = system.damping();
  const Index n = types.nodeCount();
  // the nodes with dashpot rows, and the nodes their columns reach
  for (Index p = 0; p < n; ++p) {
    const Index type = types.typeOf(types.node(p));
    if (c.begin(type) == c.end(type)) continue;
    nodes_.push_back(p);
    for (Index e = c.begin(type); e < c.end(type); ++e) nodes_.push_back(c.column(e, p));
  }
  std::sort(nodes_.begin(), nodes_.end());
  nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());
  const auto local = [&](Index p) {
    return static_cast<Index>(std::lower_bound(nodes_.begin(), nodes_.end(), p) - nodes_.begin());
  };
  std::vector<char> prescribed(static_cast<std::size_t>(C) * nodes_.size(), 0);
  for (std::size_t i = 0; i < prescribedDofs.size(); ++i) {
    const Index dof = prescribedDofs[i];
    if (dof < 0 || dof >= system.size())
      throw InputError("prescribed_displacement", "dof " + std::to_string(dof) + " is outside the system's " +
                                                      std::to_string(system.size()) + " unknowns");
    const Index node = dof / C;
    const Index at = local(node);
    if (at < static_cast<Index>(nodes_.size()) && nodes_[static_cast<std::size_t>(at)] == node) {
      prescribed[static_cast<std::size_t>(C * at + dof % C)] = 1;
      inside_.emplace_back(C * at + dof % C, static_cast<Index>(i));
    } else {
      outside_.emplace_back(dof, static_cast<Index>(i));
    }
  }
  std::vector<Triplet> entries;
  const LatticeStencils<D, C>& m = system.mass();
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const Index p = nodes_[k];
    const Index type = types.typeOf(types.node(p));
    auto add = [&](const LatticeStencils<D, C>& table, Index e, Real scale) {
      const Index q = local(table.column(e, p));
      for (int a = 0; a < C; ++a) {
        const std::size_t row = static_cast<std::size_t>(C) * k + static_cast<std::size_t>(a);
        if (prescribed[row]) continue;
        for (int b = 0; b < C; ++b) {
          const Real value = scale * table.block(e)[C * a + b];
          if (value != 0) entries.emplace_back(static_cast<int>(row), static_cast<int>(C * q + b), value);
        }
      }
    };
    for (Index e = m.begin(type); e < m.end(type); ++e) add(m, e, 1.0);
    for (Index e = c.begin(type); e < c.end(type); ++e) add(c, e, 0.5 * dt);
    for (int a = 0; a < C; ++a)
      if (prescribed[static_cast<std::size_t>(C) * k + static_cast<std::size_t>(a)])
        entries.emplace_back(static_cast<int>(C * static_cast<Index>(k) + a), static_cast<int>(C * static_cast<Index>(k) + a), 1.0);
  }
  const Index size = C * static_cast<Index>(nodes_.size());
  SparseMatrix matrix(size, size);
  matrix.setFromTriplets(entries.begin(), entries.end());
  solver_.factorise(matrix, "the dashpot rows of M + dt/2 C on the lattice");
}

template class DashpotSurfaceSolve<1>;
template class DashpotSurfaceSolve<2>;
template class DashpotSurfaceSolve<3>;
template class DashpotSurfaceSolve<2, 1>;
template class DashpotSurfaceSolve<3, 1>;

}  // namespace mfwave
