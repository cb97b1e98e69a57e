#pragma once
// What a method's interior row says about a run before it runs: the largest frequency of the
// lattice (the stable step), whether any mode grows, and the phase error of a wave of a given
// frequency after space and time are both discretised.
//
// The row is the lattice tools' interior stencil (spectra/LatticeMethods: u'' = sum_b G_b u_b, with a
// mass stencil for collocation's consistent mass). Its symbol S(k) = -sum_b G_b exp(i k . r_b) and
// mass symbol M(k) give the branches omega_h^2 = eig(M(k)^-1 S(k)) (LatticeDispersion.hpp).
//   - omega_max: the largest omega_h over the Brillouin zone k dx in [0, pi]^D, sampled on a grid
//     (k and -k give the same values for the lattice's reflection-symmetric rows).
//   - The phase error at frequency nu: k = 2 pi nu / c for the P and the S wave (the S wave alone
//     for the scalar finite difference: its one wave travels at c_p), along a lattice axis and the
//     diagonal; the time integrator then maps omega_h to the frequency of the fully discrete
//     scheme: central difference and leapfrog (2 / dt) asin(omega_h dt / 2), the trapezoidal
//     Newmark (2 / dt) atan(omega_h dt / 2), an explicit Runge-Kutta table omega_h (its phase error
//     is of higher order). The error is |omega / (c k) - 1|, the worst of the waves and directions.
// A plane wave that has travelled P periods is then off by a phase 2 pi P error, and its relative
// L2 error is 2 |sin(pi P error)| (planeWaveError).

#include "core/Material.hpp"
#include "integrators/IntegratorKind.hpp"
#include "spectra/MethodLatticeStencils.hpp"

#include <string>

namespace mfwave {

struct RowSpectrum {
  Real omegaMax = 0;            // rad/s
  bool growing = false;         // omega_h^2 < 0 somewhere in the zone (beyond round-off)
};

struct RowPhaseError {
  Real spatial = 0;             // |omega_h / (c k) - 1|, the row alone
  Real total = 0;               // with the integrator's own error at the step
  Real pointsPerWavelength = 0; // of the wave that gives `total`
  std::string wave;             // "S along the diagonal"
};

template <int D>
RowSpectrum rowSpectrum(const MethodLatticeStencil<D>& row, Real spacing, int samplesPerAxis = 0);

// The phase error of one plane wave: wavevector k, the P wave (shear = false; the scalar row's only
// wave) or the slowest other branch (shear = true), exact speed `speed`, stepped at dt by `integrator`.
template <int D>
RowPhaseError wavePhaseError(const MethodLatticeStencil<D>& row, const Vec<D>& wavevector, bool shear, Real speed,
                             Real dt, IntegratorKind integrator);

// The worst phase error of the waves of frequency `frequency` (Hz) on the row at spacing dx (P and
// S, along an axis and the diagonal; a one-component row's one wave travels at c_p), stepped at dt.
template <int D>
RowPhaseError rowPhaseError(const MethodLatticeStencil<D>& row, const Material& material, Real spacing,
                            Real frequency, Real dt, IntegratorKind integrator);

// omega_h mapped to the fully discrete frequency of `integrator` at step dt (above).
Real discreteFrequency(Real omega, Real dt, IntegratorKind integrator);

// The relative L2 error of a plane wave that has travelled `periods` periods with phase error `error`.
Real planeWaveError(Real error, Real periods);

}  // namespace mfwave
