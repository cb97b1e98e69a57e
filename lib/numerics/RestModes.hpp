#pragma once
// Small vibrations of a split first-order system about a rest state: the linearised second-order
// operator on the velocities and its eigenfrequencies. For q' = Q(t, y), p' = P(t, y) at a state
// y0 at rest (zero velocities, zero stresses), perturbing the velocities v gives, to first order,
//   q' = (dQ/dv) v,   v' = (dP_v/dq) q,   so   v'' = A v,   A = (dP_v/dq)(dQ/dv),
// and the eigenvalues of A are -omega^2 for the oscillation modes. A is built column by column:
// dQ/dv e_k exactly (Q is linear in v at rest: the strain rate, the continuity rate, dx/dt = v),
// then dP_v/dq times it by a central difference. This is how the updated-Lagrangian SPH plate's
// discrete bending period is measured without amplitude, artificial terms or time integration
// (docs/studies/sph-solids.md); any SplitFirstOrderSystem works.

#include "core/Types.hpp"
#include "systems/SplitFirstOrderSystem.hpp"

#include <vector>

namespace mfwave {

// A (m x m, m = velocityEntries.size()): entries are indices into y (the velocity components of
// the moving particles; leave out clamped ones, whose rows would only add zero modes).
// relativePerturbation scales the central difference in q against max(1, |q0|_inf).
Eigen::MatrixXd restOperator(SplitFirstOrderSystem& system, Real t, const Vector& restState,
                             const std::vector<Index>& velocityEntries, Real relativePerturbation = 1e-7);

// Only some rows of A: row r of the result is row rows[r] of restOperator (rows index into
// velocityEntries). The cost is the same number of rate evaluations, the storage rows x m: enough
// for the interior stencil of a large lattice (MethodLatticeStencils.hpp). Throws InputError("rows").
Eigen::MatrixXd restOperatorRows(SplitFirstOrderSystem& system, Real t, const Vector& restState,
                                 const std::vector<Index>& velocityEntries, const std::vector<Index>& rows,
                                 Real relativePerturbation = 1e-7);

// Only some columns of A: column j of the result is column columns[j] of restOperator (columns
// index into velocityEntries), at one rate evaluation per column instead of one per unknown. On a
// translation-invariant lattice a column holds the whole stencil, G_r = A(c - r, c)
// (MethodLatticeStencils.hpp). Throws InputError("columns").
Eigen::MatrixXd restOperatorColumns(SplitFirstOrderSystem& system, Real t, const Vector& restState,
                                    const std::vector<Index>& velocityEntries, const std::vector<Index>& columns,
                                    Real relativePerturbation = 1e-7);

// A times chosen directions, read at chosen rows: entry (r, j) is (A d_j)[rows[r]] for the columns
// d_j of `directions` (m x k, sparse). One rate evaluation per direction, whatever its support: a
// direction that moves a periodic site and all its copies together gives the folded (periodic)
// operator's column at once (JitteredCloud.cpp), and a smooth field gives A u without the matrix.
// The central difference in q is taken along the whole direction, so A d_j is exact to the same
// order as a single column. Throws InputError("directions") or ("rows").
Eigen::MatrixXd restOperatorProducts(SplitFirstOrderSystem& system, Real t, const Vector& restState,
                                     const std::vector<Index>& velocityEntries, const SparseMatrix& directions,
                                     const std::vector<Index>& rows, Real relativePerturbation = 1e-7);

struct RestModes {
  std::vector<Real> frequencies;  // omega = sqrt(-Re lambda) of the eigenvalues with Re lambda < 0, ascending
  Real largestGrowthRate = 0;     // max over eigenvalues of sqrt(Re lambda) (Re > 0) and of the flutter
                                  // rate Im sqrt(lambda) (complex lambda): 0 for a stable operator
  Index zeroModes = 0;            // eigenvalues with |lambda| <= zeroTolerance * max |lambda|
};

// Eigenvalues with |lambda| or |Im lambda| below zeroTolerance * max |lambda| are taken as zero or
// real: the finite differences of restOperator leave noise of about that size.
RestModes restModes(const Eigen::MatrixXd& restOperator, Real zeroTolerance = 1e-7);

}  // namespace mfwave
