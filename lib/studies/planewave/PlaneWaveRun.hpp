#pragma once
// The planewave study's one run: a plane P or S wave in a periodic box by a linear method's interior
// row repeated on the periodic lattice (finite differences, very weak SPH published, consistent and
// Galerkin, RK collocation, the updated-Lagrangian SPH linearised about rest) or by the spectral
// elements with periodic faces, against the exact solution u = U e cos(k . x - omega t). The step
// is a fraction of the central-difference limit 2 / omega_max of the whole discrete spectrum (FFT,
// DispersionSpectrum; for the spectral elements a power iteration on a periodic block of their
// elements); a spectrum with omega^2 < 0 (exit 3) or a step beyond the integrator's own limit
// (exit 2) is refused before any work.

#include "numerics/DispersionSpectrum.hpp"
#include "spectra/LatticeMethods.hpp"
#include "io/run/StudyCases.hpp"

#include <string>

namespace mfwave::planewave {

struct Settings {
  int dimension = 2;
  std::string method, integrator;
  LatticeDirection direction = LatticeDirection::Axis;
  bool shear = false;  // the S wave (polarisation "S"), else the P wave
  int cells = 32, wavelengths = 2;
  Real periods = 2, cfl = 0.5;
  LatticeMethodSettings lattice;
  int semOrder = 4;  // spectral_element: GLL order N, elements N spacings wide
};

// What a run gave: its canonical record (particles, steps, dt, the limit, end time, times) and error.
struct Outcome : StudyCase {
  Real error = 0;
};

// Runs the wave of `s` (its dimension 1, 2 or 3); throws InputError naming the key for a
// combination the method or the integrator cannot run, InstabilityError for growth.
Outcome runPlaneWave(const Settings& s);

}  // namespace mfwave::planewave
