#pragma once
// The per-particle pair sums of the rate passes (PairSweep.hpp), kept by the system between
// evaluations so no pass allocates: 13 values in 2-D, 20 in 3-D.

#include "core/Types.hpp"

namespace mfwave {

template <int D>
struct PairSums {
  Mat<D> gradient = Mat<D>::Zero();      // sum_j V_j (v_j - v_i) (C_i grad_i W_ij)^T
  Vec<D> smoothing = Vec<D>::Zero();     // sum_j m_j 2 W_ij / (rho_i + rho_j) (v_j - v_i)
  Vec<D> acceleration = Vec<D>::Zero();  // sum_j m_j M_ij grad_i W_ij
  Real densityRate = 0;                  // -sum_j m_j (v_j - v_i) . C_i grad_i W_ij
  Real energyRate = 0;                   // de_i/dt without the artificial-stress work
  Real viscousWork = 0;                  // sum_j m_j Pi_ij v_ij . grad_i W_ij
  Real artificialWork = 0;               // sum_j m_j v_ij . f_ij^n (R_i + R_j) grad_i W_ij
  Real largestMu = 0;                    // max_j |mu_ij|
};

}  // namespace mfwave
