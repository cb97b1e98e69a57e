#pragma once
// Stability and consistency of a meshfree method on an irregular particle cloud: the whole
// spectrum of its operator on a periodic jittered cloud, where a lattice's FFT cannot reach.
//
// The cloud is one tile of cells^D lattice sites, each moved by a uniform random offset of up to
// jitter x dx per axis, made periodic by translated copies of it as far as a tile row reaches (two
// supports for SPH, whose volumes, corrections and stress rates read the neighbours' neighbours;
// one for RK collocation), plus ghost layers for the very weak SPH. The method is assembled on this
// cloud as on any particle set, the tile's rows are kept, and each column is folded onto the tile
// particle it is a copy of: the folded matrices are exactly the method's operator on the periodic
// cloud; with no jitter they are the lattice operator whose FFT spectrum the stability
// atlas takes (a check of both). The dense eigenvalues of M^-1 A (at most a few thousand unknowns)
// give what the atlas records on lattices; the lowest modes of the box give the accuracy at
// `cells` points per wavelength; the central rows applied to a quadratic field give consistency.
// Results: docs/studies/stability-atlas.md ("Irregular clouds").

#include "spectra/LatticeMethods.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace mfwave {

struct JitteredCloudReport {
  std::string status = "ok";     // "ok", "growing" or "fails: <why>"
  int cells = 0;                 // tile cells per axis (points per wavelength of the lowest modes)
  Index unknowns = 0;            // cells^D x D
  Real closestPair = 0;          // smallest distance between two particles of the periodic cloud / dx
  Real smallestOverLargest = 0;  // most negative Re omega^2 / omega^2_max (below -tolerance: growing)
  Real imaginaryRatio = 0;       // largest |Im omega^2| / largest |omega^2| (above tolerance: flutter)
  Real courant = 0;              // central-difference limit 2 / omega_max as c_p dt / dx
  Index spuriousLowModes = 0;    // modes below half the lowest exact frequency, beyond the D rigid
                                 // translations (zero-energy modes and their near relatives)
  Real lowestModeError = 0;      // largest |omega / omega_exact - 1| over the box's lowest shear modes
                                 // (1-D: the lowest modes), omega_exact = c k with k = 2 pi / (cells dx),
                                 // each matched to the eigenvector it overlaps most
  Real quadraticResidual = 0;    // max over central rows of |A u - M a| / c_p^2 for u = x^2 / 2 e_x,
                                 // whose exact acceleration is a = c_p^2 e_x
  Real tolerance = 0;            // the eigenvalue noise level used for the verdicts
  // With confirmSteps > 0: central difference at 0.9 of its limit from random displacements.
  Real predictedLogGrowth = 0;   // ln of the largest amplification per step, times the steps
  Real measuredLogGrowth = 0;    // ln(largest |u| / initial largest |u|) over the run
  std::string confirmation;      // "grew as predicted", "bounded as predicted", "too slow to tell",
                                 // "CONTRADICTS: ..."; empty without a run
  Real seconds = 0;
};

// The methods assembled on irregular clouds: vwsph_published, vwsph_consistent, rkcm, ulsph,
// ulsph_corrected. Not finite_difference and vwsph_galerkin (lattice schemes by construction) nor
// rbcm (its global functions see the tiled cloud's edge, so folding is not exact).
const std::vector<std::string>& jitteredCloudMethodNames();
bool jitteredCloudMethodAvailable(const std::string& method);

// The report for one method, tile size, jitter (fraction of dx, in [0, 0.5)) and random seed, at
// dx = 1. Failures of the method on the cloud (too few neighbours for a correction, a singular
// moment matrix) come back as status "fails: ...". Throws InputError("method") for a method not
// available, InputError("jitter"), and InputError("cells") also when a row reaches past the copies.
// confirmSteps > 0 also runs central difference on the folded operator and compares its growth
// with the spectrum's prediction (the confirmation fields).
template <int D>
JitteredCloudReport jitteredCloudSpectrum(const std::string& method, const LatticeMethodSettings& settings, int cells,
                                          Real jitter, std::uint64_t seed, long confirmSteps = 0);

}  // namespace mfwave
