#pragma once
// The dispersion relation measured from a simulation, to check the FFT symbol (DispersionSpectrum)
// and the time integrator's dispersion on top of it.
//
// The periodic lattice operator (lumped: u'' = A u) is integrated from a unit impulse at node 0
// (components weighted 1, 1/2, 1/4 so that every polarisation is excited on the axis and the
// diagonal) at rest: a broadband pulse holding every lattice wavenumber. Each step the field is
// Fourier transformed in space; along the chosen line the P part (projection on the direction n)
// and the S part (projection on a fixed unit vector normal to n) are recorded. Each recorded
// signal is then transformed in time (Hann window, FFT, and the peak refined on the windowed
// discrete-time Fourier transform by golden-section search): together the 2-D space-time transform
// whose peaks are omega(k). A linear mode at rest starts as cos(omega~ t), where omega~ is the
// integrator's discrete frequency for the spatial omega:
//   central difference / leapfrog:   sin(omega~ dt / 2) = omega dt / 2
//   Newmark, beta = 1/4, gamma = 1/2: tan(omega~ dt / 2) = omega dt / 2
// so the measured peaks test both the symbol and that relation.

#include "numerics/DispersionSpectrum.hpp"

#include <string>
#include <vector>

namespace mfwave {

struct SimulatedDispersionOptions {
  LatticeDirection direction = LatticeDirection::Axis;
  std::string integrator = "central_difference";  // makeSecondOrderIntegrator names
  Real stepFraction = 0.5;  // dt over the central-difference limit 2 / omega_max of the whole spectrum
  int steps = 2048;         // recorded steps (the time transform's length)
  int edgeBins = 4;         // peaks within this many frequency bins of 0 or of pi / dt are not reported
};

struct SimulatedDispersionPoint {
  Real kdx = 0;
  Polarisation polarisation = Polarisation::Scalar;
  Real omegaSymbol = 0;     // the spatial relation (FFT symbol)
  Real omegaExpected = 0;   // the integrator's discrete relation for omegaSymbol (NaN when not known)
  Real omegaMeasured = 0;   // the simulation's spectral peak
  // |measured - expected| / expected (against omegaSymbol when there is no expected relation).
  Real relativeError = 0;
};

struct SimulatedDispersionResult {
  Real timeStep = 0;
  Real criticalStep = 0;         // 2 / omega_max
  int steps = 0;
  Real frequencyResolution = 0;  // 2 pi / (steps dt): the FFT bin
  Real largestError = 0;         // over the points
  std::vector<SimulatedDispersionPoint> points;
};

// The discrete frequency of `integrator` for a mode of spatial frequency omega at step dt: the
// relations above; NaN for other integrators, and for central difference beyond its limit.
Real integratorFrequency(const std::string& integrator, Real omega, Real dt);

// Throws InputError("mass") for a collocation (non-lumped) operator, InputError("steps") for fewer
// than 64 steps, InputError("step_fraction") outside (0, 1] for central difference and leapfrog
// (or <= 0 for others), and what makeSecondOrderIntegrator throws for an unknown integrator.
template <int D>
SimulatedDispersionResult simulateDispersion(const PeriodicLatticeOperator<D>& op,
                                             const DispersionSpectrum<D>& spectrum,
                                             const SimulatedDispersionOptions& options = {});

}  // namespace mfwave
