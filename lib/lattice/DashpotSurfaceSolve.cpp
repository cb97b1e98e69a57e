#include "lattice/DashpotSurfaceSolve.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <string>

namespace mfwave {

template <int D>
DashpotSurfaceSolve<D>::DashpotSurfaceSolve(const LatticeSecondOrderSystem<D>& system, Real dt,
                                            const std::vector<Index>& prescribedDofs) {
  const LatticeRowTypes<D>& types = system.types();
  const LatticeStencils<D>& c = system.damping();
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
  std::vector<char> prescribed(static_cast<std::size_t>(D) * nodes_.size(), 0);
  for (std::size_t i = 0; i < prescribedDofs.size(); ++i) {
    const Index dof = prescribedDofs[i];
    if (dof < 0 || dof >= system.size())
      throw InputError("prescribed_displacement", "dof " + std::to_string(dof) + " is outside the system's " +
                                                      std::to_string(system.size()) + " unknowns");
    const Index node = dof / D;
    const Index at = local(node);
    if (at < static_cast<Index>(nodes_.size()) && nodes_[static_cast<std::size_t>(at)] == node) {
      prescribed[static_cast<std::size_t>(D * at + dof % D)] = 1;
      inside_.emplace_back(D * at + dof % D, static_cast<Index>(i));
    } else {
      outside_.emplace_back(dof, static_cast<Index>(i));
    }
  }
  std::vector<Triplet> entries;
  const LatticeStencils<D>& m = system.mass();
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const Index p = nodes_[k];
    const Index type = types.typeOf(types.node(p));
    auto add = [&](const LatticeStencils<D>& table, Index e, Real scale) {
      const Index q = local(table.column(e, p));
      for (int a = 0; a < D; ++a) {
        const std::size_t row = static_cast<std::size_t>(D) * k + static_cast<std::size_t>(a);
        if (prescribed[row]) continue;
        for (int b = 0; b < D; ++b) {
          const Real value = scale * table.block(e)[D * a + b];
          if (value != 0) entries.emplace_back(static_cast<int>(row), static_cast<int>(D * q + b), value);
        }
      }
    };
    for (Index e = m.begin(type); e < m.end(type); ++e) add(m, e, 1.0);
    for (Index e = c.begin(type); e < c.end(type); ++e) add(c, e, 0.5 * dt);
    for (int a = 0; a < D; ++a)
      if (prescribed[static_cast<std::size_t>(D) * k + static_cast<std::size_t>(a)])
        entries.emplace_back(static_cast<int>(D * static_cast<Index>(k) + a), static_cast<int>(D * static_cast<Index>(k) + a), 1.0);
  }
  const Index size = D * static_cast<Index>(nodes_.size());
  SparseMatrix matrix(size, size);
  matrix.setFromTriplets(entries.begin(), entries.end());
  solver_.factorise(matrix, "the dashpot rows of M + dt/2 C on the lattice");
}

template class DashpotSurfaceSolve<1>;
template class DashpotSurfaceSolve<2>;
template class DashpotSurfaceSolve<3>;

}  // namespace mfwave
