#pragma once
// The second-order finite-difference Laplacian on a lattice, as a method of the pipeline:
// particles and neighbours in, a LinearSecondOrderSystem for rho u_tt = E Lap(u) out.
//
// Why it is here: its discrete symbol is known in closed form,
// omega(k) = (2 c / dx) sqrt(sum_axes sin^2(k_j dx / 2)), so the whole pipeline (lattice,
// neighbour search, assembly, integrators, observers) and later the dispersion tools can be
// checked against exact numbers before the papers' methods exist.

#include "core/Types.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <cstdint>

namespace mfwave {

struct FiniteDifferenceWaveOptions {
  Real spacing = 0;      // lattice spacing dx (> 0)
  Real density = 1;      // rho (> 0)
  Real modulus = 1;      // E in rho u_tt = E Lap(u), so c = sqrt(E / rho) (> 0)
  // Box faces (BoxFace bits) whose particles are held at u = 0. Their rows and columns are
  // removed from K, so K stays symmetric and 1/2 u^T K u is the discrete strain energy.
  std::uint8_t fixedFaces = 0;
};

// Scalar unknown per physical particle. Neighbours must contain every lattice neighbour at
// distance dx (a radius between dx and sqrt(2) dx picks exactly the axis neighbours; farther
// neighbours are ignored). Ghost particles are not allowed (throws InputError).
template <int D>
LinearSecondOrderSystem assembleFiniteDifferenceWave(const ParticleSet<D>& particles,
                                                     const NeighbourList& neighbours,
                                                     const FiniteDifferenceWaveOptions& options);

// The closed-form angular frequency of the semi-discrete scheme for a wave along one axis.
Real finiteDifferenceFrequency(Real wavenumber, Real spacing, Real waveSpeed);

}  // namespace mfwave
