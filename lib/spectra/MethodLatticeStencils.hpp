#pragma once
// The interior row of each linear(ised) method on a regular lattice, as a LatticeStencil in
// acceleration form (and a mass stencil for collocation), ready to be made periodic
// (PeriodicLattice.hpp) for the FFT dispersion spectrum. The very weak form SPH has its own builder
// (VeryWeakSphDispersion.hpp: ghost layers, variants). Every builder assembles the method on a
// lattice block large enough that the centre row sees no boundary, and reports how much the row of
// the centre's neighbour at +dx differs from it (stencilDifference: ~1e-16 for an interior row).

#include "numerics/LatticeDispersion.hpp"
#include "core/Material.hpp"
#include "methods/collocation/ShapeFunctions.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSphOptions.hpp"

#include <functional>

namespace mfwave {

template <int D>
struct MethodLatticeStencil {
  LatticeStencil<D> acceleration;  // G_b: u''_a = sum_b G_b u_b (M u'' = ... with a mass stencil)
  LatticeStencil<D> mass;          // empty for a lumped method
  int halfWidth = 0;               // the block is [-halfWidth dx, halfWidth dx]^D
  Real translationDifference = 0;
};

// The scalar second-order finite-difference wave u_tt = c^2 Lap u (closed-form symbol; the
// reference that checks the FFT machinery). Throws InputError("spacing"), InputError("wave_speed").
template <int D>
MethodLatticeStencil<D> finiteDifferenceInteriorStencil(Real spacing, Real waveSpeed);

enum class CollocationBasis { ReproducingKernel, RadialBasis };

// Strong-form collocation of rho u'' = (lambda + mu) grad div u + mu Lap u (Luo-Liu-Huang eq. (12);
// in 1-D (lambda + 2 mu) u,xx) at the centre node: mass blocks psi_b(0) I and acceleration blocks
// ((lambda + mu) H_b + mu tr(H_b) I) / rho, H_b the Hessian of psi_b at the centre.
// ReproducingKernel: cubic B-spline RK of basis order `order`, support radius ratio * dx.
// RadialBasis: inverse multiquadric with shape parameter ratio * dx (global: every node of the
// block is in the row; the block's edge still perturbs it, see translationDifference).
// halfWidth 0 picks ceil(ratio) + 2 for RK and 40 (1-D) / 10 (2-D, 3-D) for RB.
// Throws InputError("support_ratio"), InputError("spacing"), InputError("order") (RK: 1..3).
template <int D>
MethodLatticeStencil<D> collocationInteriorStencil(CollocationBasis basis, int order, Real ratio,
                                                   const Material& material, Real spacing, int halfWidth = 0);

// The collocation row at x (Luo-Liu-Huang eq. (12)): for each node b whose shape function reaches
// x, psi_b(x) (the mass block is psi_b I) and the acceleration block
// ((lambda + mu) H_b + mu tr(H_b) I) / rho, H_b the Hessian of psi_b at x.
template <int D>
void collocationRowBlocks(const ShapeFunctions<D>& shapes, const Vec<D>& x, const Material& material,
                          const std::function<void(Index node, Real psi, const Mat<D>& acceleration)>& block);

// The options with what does not act about rest switched off: viscosity (nothing moves) and the
// artificial stress (not differentiable at zero stress).
UpdatedLagrangianSphOptions linearisedAboutRest(UpdatedLagrangianSphOptions options);

// The updated-Lagrangian SPH linearised about rest (RestModes.hpp: v'' = A v): the centre's rows of
// A, D x D blocks. Viscosity and artificial stress are switched off (nothing to act on at rest; the
// artificial stress is not differentiable at zero stress); the kernel, h / dp, the density update
// and the kernel-gradient correction come from `options`. Throws InputError("spacing").
template <int D>
MethodLatticeStencil<D> updatedLagrangianSphInteriorStencil(UpdatedLagrangianSphOptions options, Real spacing);

}  // namespace mfwave
