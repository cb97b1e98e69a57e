#include "numerics/PeriodicLattice.hpp"

#include "core/Error.hpp"
#include "lattice/PeriodicStencilSystem.hpp"

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace mfwave {

template <int D>
Index PeriodicLatticeOperator<D>::nodes() const {
  Index n = 1;
  for (int d = 0; d < D; ++d) n *= cells;
  return n;
}

template <int D>
std::vector<std::array<int, D>> latticeSteps(const LatticeStencil<D>& stencil, Real spacing) {
  std::vector<std::array<int, D>> steps;
  steps.reserve(stencil.offsets.size());
  for (const Vec<D>& r : stencil.offsets) {
    std::array<int, D> s{};
    for (int d = 0; d < D; ++d) {
      const Real x = r(d) / spacing;
      s[static_cast<std::size_t>(d)] = static_cast<int>(std::lround(x));
      if (std::abs(x - s[static_cast<std::size_t>(d)]) > 1e-6)
        throw InputError("stencil", "offset " + std::to_string(r(d)) + " is not a multiple of the spacing " +
                                        std::to_string(spacing));
    }
    steps.push_back(s);
  }
  return steps;
}

template <int D>
int stencilReach(const LatticeStencil<D>& stencil, Real spacing) {
  int reach = 0;
  for (const auto& s : latticeSteps(stencil, spacing))
    for (int v : s) reach = std::max(reach, std::abs(v));
  return reach;
}

template <int D>
Index periodicNode(const std::array<int, D>& coordinates, int cells) {
  Index node = 0;
  for (int d = D - 1; d >= 0; --d) {
    const int c = ((coordinates[static_cast<std::size_t>(d)] % cells) + cells) % cells;
    node = node * cells + c;
  }
  return node;
}

template <int D>
std::array<int, D> latticeCoordinates(Index node, int cells) {
  std::array<int, D> coordinates{};
  for (int d = 0; d < D; ++d) {
    coordinates[static_cast<std::size_t>(d)] = static_cast<int>(node % cells);
    node /= cells;
  }
  return coordinates;
}

template <int D>
PeriodicLatticeOperator<D> makePeriodicLatticeOperator(LatticeStencil<D> acceleration, Real spacing, int cells,
                                                       LatticeStencil<D> mass) {
  if (!(spacing > 0) || !std::isfinite(spacing)) throw InputError("spacing", "must be positive and finite");
  if (acceleration.size() == 0 || acceleration.components < 1)
    throw InputError("stencil", "the acceleration stencil is empty");
  if (mass.size() > 0 && mass.components != acceleration.components)
    throw InputError("stencil", "the mass stencil has " + std::to_string(mass.components) +
                                    " components, the acceleration stencil " +
                                    std::to_string(acceleration.components));
  if (cells < 2 || cells % 2 != 0) throw InputError("cells", "must be even and at least 2, got " + std::to_string(cells));
  const int reach = std::max(stencilReach(acceleration, spacing), mass.size() > 0 ? stencilReach(mass, spacing) : 0);
  if (2 * reach >= cells)
    throw InputError("cells", std::to_string(cells) + " nodes per axis are too few for a stencil reaching " +
                                  std::to_string(reach) + " spacings: need more than " + std::to_string(2 * reach));
  PeriodicLatticeOperator<D> op;
  op.acceleration = std::move(acceleration);
  op.mass = std::move(mass);
  op.spacing = spacing;
  op.cells = cells;
  return op;
}

template <int D>
SparseMatrix periodicMatrix(const LatticeStencil<D>& stencil, Real spacing, int cells) {
  const auto steps = latticeSteps(stencil, spacing);
  const int c = stencil.components;
  Index nodes = 1;
  for (int d = 0; d < D; ++d) nodes *= cells;
  std::vector<Eigen::Triplet<Real>> triplets;
  triplets.reserve(static_cast<std::size_t>(nodes) * steps.size() * static_cast<std::size_t>(c * c));
  for (Index node = 0; node < nodes; ++node) {
    const std::array<int, D> at = latticeCoordinates<D>(node, cells);
    for (std::size_t b = 0; b < steps.size(); ++b) {
      std::array<int, D> to = at;
      for (int d = 0; d < D; ++d) to[static_cast<std::size_t>(d)] += steps[b][static_cast<std::size_t>(d)];
      const Index column = periodicNode<D>(to, cells);
      for (int p = 0; p < c; ++p)
        for (int q = 0; q < c; ++q) {
          const Real g = stencil.blocks[b](p, q);
          if (g != 0) triplets.emplace_back(node * c + p, column * c + q, g);
        }
    }
  }
  SparseMatrix matrix(nodes * c, nodes * c);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

template <int D>
LinearSecondOrderSystem periodicLatticeSystem(const PeriodicLatticeOperator<D>& op) {
  SparseMatrix mass(op.size(), op.size());
  if (op.lumped())
    mass.setIdentity();
  else
    mass = periodicMatrix(op.mass, op.spacing, op.cells);
  return LinearSecondOrderSystem(mass, SparseMatrix(), -periodicMatrix(op.acceleration, op.spacing, op.cells));
}

template <int D>
std::unique_ptr<LinearOperatorSystem> periodicStencilSystem(const PeriodicLatticeOperator<D>& op) {
  if (!op.lumped())
    throw InputError("mass", "a consistent mass is solved every step from its matrix: use periodicLatticeSystem");
  const int c = op.components();
  std::vector<Real> blocks;
  blocks.reserve(static_cast<std::size_t>(op.acceleration.size() * c * c));
  for (const Eigen::MatrixXd& g : op.acceleration.blocks)
    for (int p = 0; p < c; ++p)
      for (int q = 0; q < c; ++q) blocks.push_back(g(p, q));
  const auto steps = latticeSteps(op.acceleration, op.spacing);
  if (c == 1) return std::make_unique<PeriodicStencilSystem<D, 1>>(op.cells, steps, blocks);
  if constexpr (D > 1)
    if (c == D) return std::make_unique<PeriodicStencilSystem<D, D>>(op.cells, steps, blocks);
  throw InputError("stencil", std::to_string(c) + " components: the matrix-free periodic system takes 1 or " +
                                  std::to_string(D));
}

#define MFWAVE_PERIODIC_LATTICE(D)                                                                              \
  template struct PeriodicLatticeOperator<D>;                                                                   \
  template PeriodicLatticeOperator<D> makePeriodicLatticeOperator<D>(LatticeStencil<D>, Real, int, LatticeStencil<D>); \
  template std::vector<std::array<int, D>> latticeSteps<D>(const LatticeStencil<D>&, Real);                     \
  template SparseMatrix periodicMatrix<D>(const LatticeStencil<D>&, Real, int);                                 \
  template LinearSecondOrderSystem periodicLatticeSystem<D>(const PeriodicLatticeOperator<D>&);                 \
  template std::unique_ptr<LinearOperatorSystem> periodicStencilSystem<D>(const PeriodicLatticeOperator<D>&);   \
  template Index periodicNode<D>(const std::array<int, D>&, int);                                               \
  template std::array<int, D> latticeCoordinates<D>(Index, int);                                                \
  template int stencilReach<D>(const LatticeStencil<D>&, Real);
MFWAVE_PERIODIC_LATTICE(1)
MFWAVE_PERIODIC_LATTICE(2)
MFWAVE_PERIODIC_LATTICE(3)
#undef MFWAVE_PERIODIC_LATTICE

}  // namespace mfwave
