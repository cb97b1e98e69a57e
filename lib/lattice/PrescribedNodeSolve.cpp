#include "lattice/PrescribedNodeSolve.hpp"

#include "core/Error.hpp"

#include <string>

namespace mfwave {

template <int D, int C>
PrescribedNodeSolve<D, C>::PrescribedNodeSolve(const std::vector<Index>& dofs, Index size) {
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const Index dof = dofs[i];
    if (dof < 0 || dof >= size)
      throw InputError("prescribed_displacement", "dof " + std::to_string(dof) + " is outside the system's " +
                                                      std::to_string(size) + " unknowns");
    auto [entry, added] = nodes_.try_emplace(dof / C);
    if (added) entry->second.fill(-1);
    entry->second[static_cast<std::size_t>(dof % C)] = static_cast<Index>(i);
  }
}

template class PrescribedNodeSolve<1>;
template class PrescribedNodeSolve<2>;
template class PrescribedNodeSolve<3>;
template class PrescribedNodeSolve<2, 1>;
template class PrescribedNodeSolve<3, 1>;

}  // namespace mfwave
