#pragma once
// Loads kept as their nonzero entries, each scaled by its own history: f(t) = sum_l h_l(t) f_l.
// What a lattice system stores of its nodal forces (a patch of the surface, a face), and what lets
// a rank keep only the entries of the nodes it owns (lib/decomposition).

#include "core/TimeFunction.hpp"
#include "core/Types.hpp"

#include <vector>

namespace mfwave {

struct SparseLoad {
  std::vector<Index> dofs;
  std::vector<Real> values;
  const TimeFunction* history = nullptr;  // must outlive the load
};

// f[dofs] += h(t) values, load by load in order (a load whose history is zero at t adds nothing).
void addSparseLoads(const std::vector<SparseLoad>& loads, Real t, Real* f);

// The nonzero entries of `force` as one load with `history`.
SparseLoad nonzeroLoad(const Vector& force, const TimeFunction* history);

}  // namespace mfwave
