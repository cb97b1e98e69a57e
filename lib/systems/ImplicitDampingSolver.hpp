#pragma once
// The implicit dashpot term of central difference on a linear system M u'' + C u' + K u = f(t),
// Ding-Long-Wu eq. (32): with the centred velocity (32b) v_n = (v_{n-1/2} + v_{n+1/2}) / 2 and
// a_n = (v_{n+1/2} - v_{n-1/2}) / dt, the equation of motion at t_n,
//   M a_n + C v_n = f(t_n) - K u_n,
// becomes, with v_n = v_{n-1/2} + dt/2 a_n,
//   (M + dt/2 C) a_n = f(t_n) - K u_n - C v_{n-1/2}.
// This is (M/dt + C/2) v_{n+1/2} = (M/dt - C/2) v_{n-1/2} + f_n - K u_n multiplied by dt and
// solved for the increment a_n instead of v_{n+1/2}, so that no digits are lost to cancellation.
// M + dt/2 C is factorised once (diagonal, 2 x 2 / 3 x 3 block-diagonal or UMFPACK: see
// FactorisedMatrix); a step costs one product with K, one with C and one solve.
//
// Prescribed dofs (whose acceleration is known) are eliminated: their rows and columns become the
// identity, their known accelerations are moved to the right-hand side of the free rows that C
// couples to them.

#include "solvers/FactorisedMatrix.hpp"
#include "systems/LinearOperatorSystem.hpp"

#include <vector>

namespace mfwave {

class LinearSecondOrderSystem;

class ImplicitDampingSolver : public CentredDampingSolve {
 public:
  // Factorises M + dt/2 C with the rows and columns of prescribedDofs replaced by the identity.
  // The system must outlive the solver.
  void factorise(const LinearSecondOrderSystem& system, Real dt, const std::vector<Index>& prescribedDofs);

  // a_n from (M + dt/2 C) a_n = f(t) - K u - C vHalf, with a_n[prescribedDofs] = prescribedAcceleration
  // (size prescribedDofs.size(), ignored when there are none).
  void acceleration(Real t, const Vector& u, const Vector& vHalf, const Vector& prescribedAcceleration,
                    Vector& a) override;

 private:
  const LinearSecondOrderSystem* system_ = nullptr;
  std::vector<Index> prescribedDofs_;
  FactorisedMatrix matrix_;
  SparseMatrix coupling_;  // (M + dt/2 C)[free rows, prescribed columns]; n x prescribed, zero rows for prescribed
  Vector rhs_;
};

}  // namespace mfwave
