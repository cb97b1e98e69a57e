#include "systems/SparseLoads.hpp"

namespace mfwave {

void addSparseLoads(const std::vector<SparseLoad>& loads, Real t, Real* f) {
  for (const SparseLoad& load : loads) {
    const Real scale = (*load.history)(t);
    if (scale == 0) continue;
    for (std::size_t k = 0; k < load.dofs.size(); ++k) f[load.dofs[k]] += scale * load.values[k];
  }
}

SparseLoad nonzeroLoad(const Vector& force, const TimeFunction* history) {
  SparseLoad load;
  load.history = history;
  for (Index i = 0; i < force.size(); ++i)
    if (force[i] != 0) {
      load.dofs.push_back(i);
      load.values.push_back(force[i]);
    }
  return load;
}

}  // namespace mfwave
