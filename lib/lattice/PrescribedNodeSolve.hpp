#pragma once
// Prescribed displacements (Ding-Long-Wu eq. (30)) inside the central-difference solve of eq. (32)
// when M + dt/2 C is block diagonal (a lumped mass, dashpots on a node's own dofs): at a node with
// prescribed components those take their accelerations, and the node's free components are solved
// again from the node's C x C block with the prescribed ones known. The serial lattice system and a
// rank's share of it (lib/decomposition) both apply it after their fused solve, node by node in the
// same order, so both keep the same bits.

#include "core/Types.hpp"
#include "lattice/LatticeStencils.hpp"

#include <Eigen/LU>

#include <array>
#include <map>
#include <vector>

namespace mfwave {

template <int D, int C = D>
class PrescribedNodeSolve {
 public:
  PrescribedNodeSolve() = default;
  // `dofs` (node * C + component, the list's order is the prescribed accelerations' order) of a
  // state of `size` unknowns. Throws InputError("prescribed_displacement") for a dof outside it.
  PrescribedNodeSolve(const std::vector<Index>& dofs, Index size);

  bool empty() const { return nodes_.empty(); }

  // a holds (M + dt/2 C)^-1 r at every node (r the row's right-hand side); at the nodes with
  // prescribed components it becomes their accelerations and the free components' solution with
  // those known. `typeOf(node)` is the node's row type in `mass` and `damping` (damping may be empty).
  template <class TypeOf>
  void apply(const LatticeStencils<D, C>& mass, const LatticeStencils<D, C>& damping, Real halfStep, TypeOf&& typeOf,
             const Vector& prescribedAcceleration, Real* a) const {
    using Block = Eigen::Matrix<Real, C, C, Eigen::RowMajor>;
    for (const auto& [node, prescribed] : nodes_) {
      const Index type = typeOf(node);
      Block m, c;
      mass.typeSum(type, m.data());
      damping.typeSum(type, c.data());
      const Block matrix = m + halfStep * c;
      Eigen::Matrix<Real, C, 1> solution = Eigen::Map<const Eigen::Matrix<Real, C, 1>>(a + C * node);
      const Eigen::Matrix<Real, C, 1> rhs = matrix * solution;  // the row's right-hand side, recovered
      std::vector<int> free;
      for (int k = 0; k < C; ++k) {
        if (prescribed[static_cast<std::size_t>(k)] >= 0)
          solution[k] = prescribedAcceleration[prescribed[static_cast<std::size_t>(k)]];
        else
          free.push_back(k);
      }
      if (!free.empty()) {
        const auto n = static_cast<Index>(free.size());
        Eigen::MatrixXd reduced(n, n);
        Eigen::VectorXd right(n);
        for (Index i = 0; i < n; ++i) {
          const int row = free[static_cast<std::size_t>(i)];
          right[i] = rhs[row];
          for (int k = 0; k < C; ++k)
            if (prescribed[static_cast<std::size_t>(k)] >= 0) right[i] -= matrix(row, k) * solution[k];
          for (Index j = 0; j < n; ++j) reduced(i, j) = matrix(row, free[static_cast<std::size_t>(j)]);
        }
        const Eigen::VectorXd x = reduced.partialPivLu().solve(right);
        for (Index i = 0; i < n; ++i) solution[free[static_cast<std::size_t>(i)]] = x[i];
      }
      Eigen::Map<Eigen::Matrix<Real, C, 1>>(a + C * node) = solution;
    }
  }

 private:
  // per node with a prescribed component: each component's place in the prescribed list, or -1
  std::map<Index, std::array<Index, C>> nodes_;
};

}  // namespace mfwave
