#pragma once
// The lowest eigenvalues of K x = lambda M x (K symmetric, M diagonal and positive: a lumped-mass
// linear system) on the assembled matrices, without running the system. Used to show that an
// operator has no growing mode: with K symmetric, M positive and dashpots C symmetric positive
// semi-definite, every mode exp(s t) of M u'' + C u' + K u = 0 has Re s <= 0 exactly when no lambda
// is negative (s^2 x*Mx + s x*Cx + x*Kx = 0 has non-negative real coefficients).
//
// Two results, of different strength:
//  - the factorisation K + shift M = L L^T (CHOLMOD supernodal) succeeds exactly when every
//    eigenvalue is above -shift: a proof over the whole spectrum, up to the factorisation's
//    round-off;
//  - shift-invert subspace iteration on M^(1/2) (K + shift M)^-1 M^(1/2) with Rayleigh-Ritz gives the
//    `count` lowest eigenvalues with their residuals, so a user sees the rigid-body modes (lambda
//    near 0, multiplicity kept, unlike single-vector Lanczos) and the lowest elastic one.

#include "core/Types.hpp"

#include <vector>

namespace mfwave {

struct LowestModes {
  Real shift = 0;
  bool shiftedMatrixPositiveDefinite = false;  // K + shift M = L L^T succeeded: no eigenvalue below -shift
  std::vector<Real> eigenvalues;               // ascending, `count` of them (empty when the factorisation failed)
  std::vector<Real> residuals;                 // |K x - lambda M x|_{M^-1} / ((|lambda| + shift) |x|_M) per eigenvalue
  int iterations = 0;
  bool converged = false;
};

// `massDiagonal` holds M's diagonal (positive). Iterates a block of count + guard vectors from a fixed
// pseudo-random start until every wanted residual is below `tolerance`. Throws InputError("count") if
// count < 1 or count + guard exceeds the size, InputError("mass") on a non-positive mass entry.
LowestModes lowestModes(const SparseMatrix& stiffness, const Vector& massDiagonal, int count, Real shift,
                        Real tolerance = 1e-8, int maximumIterations = 500, int guard = 8);

}  // namespace mfwave
