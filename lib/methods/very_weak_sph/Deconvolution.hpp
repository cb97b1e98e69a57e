#pragma once
// Deconvolution of a kernel estimate, Ding-Long-Wu eq. (35). The state advanced by eq. (23) is the
// kernel estimate u^h_a = sum_b u_b W_ab V_b / s_a, s_a = sum_b W_ab V_b (eq. (17) with the
// corrected kernel of eqs. (28)-(29), i.e. u^h = S u with S of ConservativeSmoothing.hpp). Solving
// for the self term and taking u_b ~ u^h_b for b != a gives
//   u_a = (s_a u^h_a - sum_{b != a} u^h_b W_ab V_b) / (W(0) V_a)                 (normalised)
// which reproduces a constant at every particle. The paper prints it without s_a,
//   u_a = (u^h_a - sum_{b != a} u^h_b W_ab V_b) / (W(0) V_a)                      (plain)
// which reproduces a constant only where s_a = 1 (interior with complete supports): on a face it
// maps 1 to 1 + (1 - s_a) / (W(0) V_a). Both are linear, so they are sparse matrices D with u = D u^h:
// with S_ab as above, D_ab = -S_ab / S_aa (b != a) and D_aa = 1 / S_aa (normalised) or
// 1 / (s_a S_aa) = 1 / (W(0) V_a) (plain).
//
// For a smooth field (S-symbol lambda = 1 - eps) the normalised form turns the error eps of the
// estimate into -eps (1 - S_aa) / S_aa + O(eps^2): it reduces the error only where S_aa > 1/2
// (1-D cubic spline, h = dx: S_aa = 2/3, error halved) and increases it otherwise (3-D, h = dx:
// S_aa = 0.3183, error times 2.14 with the opposite sign in the long-wave limit, 2.05 at k h = 0.45).
// It sharpens; it is not an inverse of S.

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "methods/very_weak_sph/ConservativeSmoothing.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

#include <vector>

namespace mfwave {

enum class DeconvolutionForm {
  Normalised,  // with s_a: reproduces constants everywhere (the default)
  Plain,       // eq. (35) as printed: fails at the surface
};

// D with u = D u^h over the physical particles (`volumes`: V_b of the physical particles).
// Throws InputError("volumes") for a wrong length (and the checks of checkVeryWeakInputs).
template <int D>
ParticleMatrix deconvolutionMatrix(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                   const Kernel& kernel, const std::vector<Real>& volumes,
                                   DeconvolutionForm form = DeconvolutionForm::Normalised);

// u = D u^h for an interleaved field (dof = particle * dimension + component). Throws
// InputError("field") when the length does not match.
Vector deconvolve(const ParticleMatrix& matrix, const Vector& field, int dimension);

// One entry of deconvolve(matrix, field, dimension): a probe reads one particle for the cost of one
// row. Throws InputError("particle") / InputError("component") / InputError("field").
Real deconvolveAt(const ParticleMatrix& matrix, Index particle, const Vector& field, int dimension, int component);

}  // namespace mfwave
