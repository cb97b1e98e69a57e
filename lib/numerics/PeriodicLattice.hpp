#pragma once
// A translation-invariant linear operator made periodic: the interior stencil of an assembled
// method (LatticeDispersion.hpp's LatticeStencil, blocks G_b at offsets r_b) repeated on every node
// of an N^D periodic lattice of spacing dx. This is the lattice on which the FFT dispersion spectrum
// (DispersionSpectrum.hpp) and the simulated spectrum (SimulatedDispersion.hpp) are computed:
//
//   M u'' = A u,   (A u)_a = sum_b G_b u_{a + r_b},   (M u)_a = sum_b M_b u_{a + r_b}
//
// with M the identity for a lumped method (very weak SPH, finite differences, the linearised
// updated-Lagrangian SPH) and the collocation mass psi_b(x_a) for RK / RB collocation. Unknowns are
// numbered node * components + component, nodes x-fastest: node = i_0 + N (i_1 + N i_2).

#include "numerics/LatticeDispersion.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <array>
#include <memory>

namespace mfwave {

template <int D>
struct PeriodicLatticeOperator {
  LatticeStencil<D> acceleration;  // G_b (components x components)
  LatticeStencil<D> mass;          // M_b; no offsets means the identity (a lumped method)
  Real spacing = 1;
  int cells = 0;                   // N nodes per axis

  int components() const { return acceleration.components; }
  bool lumped() const { return mass.size() == 0; }
  Index nodes() const;             // N^D
  Index size() const { return nodes() * components(); }
};

// Checks and wraps the stencils. Throws InputError("spacing") for spacing <= 0,
// InputError("stencil") for an empty stencil, offsets off the lattice (further than 1e-6 dx from a
// lattice vector) or a mass stencil with other components, InputError("cells") when N is odd or
// the stencils reach N/2 nodes or further along an axis (the periodic images would overlap).
template <int D>
PeriodicLatticeOperator<D> makePeriodicLatticeOperator(LatticeStencil<D> acceleration, Real spacing, int cells,
                                                       LatticeStencil<D> mass = {});

// The offsets of a stencil in lattice steps (rounded; checked by makePeriodicLatticeOperator).
template <int D>
std::vector<std::array<int, D>> latticeSteps(const LatticeStencil<D>& stencil, Real spacing);

// The stencil assembled on the periodic lattice: a size() x size() sparse matrix (A or M).
template <int D>
SparseMatrix periodicMatrix(const LatticeStencil<D>& stencil, Real spacing, int cells);

// M u'' = A u as the system the integrators step: mass M (the identity for a lumped method; a
// consistent one is solved every explicit step), no damping, stiffness K = -A.
template <int D>
LinearSecondOrderSystem periodicLatticeSystem(const PeriodicLatticeOperator<D>& op);

// The same system matrix-free (lib/lattice/PeriodicStencilSystem: the stencil applied by lattice
// arithmetic, no matrix), for a lumped operator with 1 or D components. Throws InputError("mass") for
// a consistent mass (solving it needs the matrix), InputError("stencil") for other components.
template <int D>
std::unique_ptr<LinearOperatorSystem> periodicStencilSystem(const PeriodicLatticeOperator<D>& op);

// Node index of lattice coordinates (each taken modulo N), and the coordinates in [0, N) of a node:
// the numbering of every lattice array here, the FFT grids included (x fastest).
template <int D>
Index periodicNode(const std::array<int, D>& coordinates, int cells);
template <int D>
std::array<int, D> latticeCoordinates(Index node, int cells);

// The largest |offset| along any axis, in lattice steps.
template <int D>
int stencilReach(const LatticeStencil<D>& stencil, Real spacing);

}  // namespace mfwave
