#pragma once
// Discrete dispersion of an assembled method on a regular lattice, from the interior stencil.
//
// Given a LinearSecondOrderSystem M u'' + K_sys u = f (M diagonal, dof = particle * components +
// component) on a lattice, the row of a particle far from every boundary is translation
// invariant: row a reads u''_a = sum_b G_b u_b with the stencil blocks
//   G_b = -K_sys(a, b) / M_aa  (components x components),  at offsets r_b = x_b - x_a.
// A plane wave u_b = U exp(i (k . x_b - omega t)) solves it when
//   omega^2 U = S(k) U,   S(k) = -sum_b G_b exp(i k . r_b)                 (the symbol)
// For a symmetric stencil (G_{-r} = G_r, each block symmetric) S is real and symmetric; the
// imaginary part left by round-off is checked. For a wave along the unit direction n the
// eigenpairs of S(|k| n) give the branches; the P branch is the one whose polarisation is most
// nearly along n, the S branch the slowest of the others. The phase speed is omega / |k|, the
// group speed d omega / d|k| = (d lambda / d|k|) / (2 omega) from the analytic derivative of the
// symbol, dS/d|k| = -sum_b G_b i (n . r_b) exp(i k . r_b) (Hellmann-Feynman, with left
// eigenvectors when S is not symmetric).
//
// The long-wave limit: S(k n) = S0 + |k|^2 A(n) + O(|k|^4) with
//   S0 = -sum_b G_b  (zero for a translation-exact row),  A(n) = 1/2 sum_b G_b (n . r_b)^2.
// A row that is not translation exact has omega(k -> 0) = sqrt(v . S0 v) > 0 (a spurious elastic
// foundation, the "gap"), and sqrt(eig A) is then the speed the branch approaches once |k| is large
// against the gap (omega^2 = gap^2 + c^2 k^2 to leading order). For an exact row it is the long-wave
// phase speed itself. The gap assumes S0 commutes with A (isotropic S0, as on a cubic lattice).

#include "core/Types.hpp"
#include "particles/ParticleSet.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <Eigen/Core>
#include <vector>

namespace mfwave {

template <int D>
struct LatticeStencil {
  int components = 0;                   // unknowns per particle (D for elasticity, 1 for a scalar wave)
  std::vector<Vec<D>> offsets;          // r_b = x_b - x_a (the self offset 0 included)
  std::vector<Eigen::MatrixXd> blocks;  // G_b = -K_sys(a, b) / M_aa, components x components

  Index size() const { return static_cast<Index>(offsets.size()); }
  // sum_b G_b = -S(0): zero for a row that reproduces a rigid translation.
  Eigen::MatrixXd rowSum() const;
  // The same stencil with the self block minus rowSum(), so that it sums to zero (the row-sum, or
  // diagonal, correction): S(k) - S(0) of this stencil. Throws InputError("stencil") when there is
  // no self block.
  LatticeStencil withRowSumCorrection() const;
};

// The stencil of row `particle` (a physical particle) of the system, offsets from the particle
// positions. Blocks whose largest entry is <= dropBelow times the largest entry of the row are left
// out. Throws InputError("system") when system.size() is not a multiple of physicalCount() or M has
// off-diagonal entries in the row, InputError("particle") for an index out of range.
template <int D>
LatticeStencil<D> extractLatticeStencil(const LinearSecondOrderSystem& system, const ParticleSet<D>& particles,
                                        Index particle, Real dropBelow = 0);

// Largest |G_b - G'_b| over the blocks of two stencils, matched by offset (within offsetTolerance),
// divided by the largest |G_b|: ~1e-16 for two interior rows of a translation-invariant lattice.
// Infinity when the offsets or the component counts differ.
template <int D>
// With commonOffsetsOnly, blocks of `first` without a partner in `second` are skipped instead (rows
// of a global method, whose reach is the lattice block and so shifts with the row).
Real stencilDifference(const LatticeStencil<D>& first, const LatticeStencil<D>& second, Real offsetTolerance = 1e-9,
                       bool commonOffsetsOnly = false);

struct StencilSymbol {
  Eigen::MatrixXd real;       // Re S(k)
  Real imaginaryRatio = 0;    // max |Im S| / sum_b max |G_b|
  Real asymmetryRatio = 0;    // max |Re S - Re S^T| / sum_b max |G_b|
};

// S(k) = -sum_b G_b exp(i k . r_b).
template <int D>
StencilSymbol stencilSymbol(const LatticeStencil<D>& stencil, const Vec<D>& wavevector);

enum class Polarisation {
  P,       // along the direction of propagation (largest |v . n|); needs components == D
  S,       // the slowest of the other branches; needs components == D >= 2
  Scalar,  // the only branch of a scalar system (components == 1)
};
const char* polarisationName(Polarisation polarisation);  // "P", "S", "scalar"

// Throws InputError("polarisation") when the polarisation does not exist for `components` unknowns
// per particle in D dimensions (S in 1-D, P or S for a scalar system, Scalar for a vector one).
template <int D>
void checkPolarisationExists(int components, Polarisation polarisation);

struct LatticeMode;
// Index of the branch of `polarisation` among modes sorted by ascending omega^2, from their
// alignments: P the most aligned with the direction, S the slowest of the others, Scalar the only one.
std::size_t polarisationBranch(const std::vector<LatticeMode>& modes, Polarisation polarisation);

struct LatticeMode {
  Real omegaSquared = 0;        // eigenvalue of S(k) (real part)
  Real omega = 0;               // sqrt(omegaSquared); NaN when negative or complex
  Real phaseSpeed = 0;          // omega / |k|
  Real groupSpeed = 0;          // d omega / d|k|
  Real alignment = 0;           // |v . n| / |v|: 1 for a pure P wave, 0 for a pure S wave
  bool complexPair = false;     // S(k) not symmetric and this eigenvalue complex
  Eigen::VectorXd polarisation; // unit eigenvector (components entries)
};

// Every branch at wavenumber |k| = wavenumber > 0 along `direction` (normalised here), ascending
// omega^2. Throws InputError("wavenumber") for wavenumber <= 0, InputError("direction") for a zero
// direction, InputError("stencil") when the imaginary part of S exceeds imaginaryTolerance (a
// stencil that is not symmetric: S is then not real and this analysis does not apply).
template <int D>
std::vector<LatticeMode> latticeModes(const LatticeStencil<D>& stencil, const Vec<D>& direction, Real wavenumber,
                                      Real imaginaryTolerance = 1e-9);

// The branch of one polarisation. Throws InputError("polarisation") when the polarisation does not
// exist for the stencil (S in 1-D, P or S for a scalar system in 2-D / 3-D, Scalar for a vector).
template <int D>
LatticeMode latticeMode(const LatticeStencil<D>& stencil, const Vec<D>& direction, Real wavenumber,
                        Polarisation polarisation, Real imaginaryTolerance = 1e-9);

struct LongWaveLimit {
  Real gap = 0;        // omega(k -> 0) [1/time]: 0 for a translation-exact row
  Real speed = 0;      // sqrt of the |k|^2 coefficient of omega^2 (the long-wave phase speed if gap = 0)
  Real alignment = 0;  // |v . n| of the branch's polarisation
};

// The long-wave limit of one branch from S0 and A(n) (no small-k round-off).
template <int D>
LongWaveLimit longWaveLimit(const LatticeStencil<D>& stencil, const Vec<D>& direction, Polarisation polarisation);

struct DispersionSample {
  Real kdx = 0;              // |k| times the lattice spacing
  Real wavenumber = 0;       // |k|
  Real phaseSpeedRatio = 0;  // omega / (|k| c)
  Real groupSpeedRatio = 0;  // (d omega / d|k|) / c
  Real alignment = 0;
};

// `points` samples of |k| dx evenly on [kdxMin, kdxMax] (points >= 2), speeds over referenceSpeed.
// Throws InputError("spacing"), InputError("reference_speed"), InputError("kdx") (need
// 0 < kdxMin < kdxMax), InputError("points").
template <int D>
std::vector<DispersionSample> dispersionCurve(const LatticeStencil<D>& stencil, const Vec<D>& direction,
                                              Polarisation polarisation, Real referenceSpeed, Real spacing,
                                              Real kdxMin, Real kdxMax, int points);

struct AccuracyResolution {
  // attained: the phase error stays below the tolerance for every |k| dx in [kdxMin, kdx].
  // Not attained: the error is at least the tolerance already at kdxMin (a speed error in the
  // long-wave limit, or a gap): no resolution is fine enough; kdx = 0, pointsPerWavelength = inf.
  bool attained = false;
  bool wholeBand = false;          // below the tolerance up to kdxMax (then kdx = kdxMax)
  Real kdx = 0;                    // the largest |k| dx with |p - 1| < tolerance below it
  Real pointsPerWavelength = 0;    // 2 pi / kdx: the wavelength in lattice spacings
};

// Points per wavelength for a phase-speed error |omega / (|k| c) - 1| below `tolerance`: scans
// `samples` values of |k| dx on [kdxMin, kdxMax] and bisects the first crossing. A NaN phase speed
// counts as an error above tolerance.
template <int D>
AccuracyResolution pointsPerWavelength(const LatticeStencil<D>& stencil, const Vec<D>& direction,
                                       Polarisation polarisation, Real referenceSpeed, Real spacing,
                                       Real tolerance = 0.01, Real kdxMin = 1e-3, Real kdxMax = kPi,
                                       int samples = 4000);

// The extremes of omega^2 (the eigenvalues of Re S(k)) over the Brillouin zone, sampled at
// k dx = pi j / n, j = 0..n, on every axis (k and -k give the same values for the lattice's
// reflection-symmetric stencils, so [0, pi]^D covers the zone). A stencil is stable for central
// difference only when smallest >= 0 (to round-off) and the symbol is real (imaginaryRatio ~ 0).
template <int D>
struct SymbolExtremes {
  Real smallest = 0, largest = 0;  // of omega^2
  Vec<D> smallestAt = Vec<D>::Zero();  // k dx where omega^2 is smallest
  Real largestImaginaryRatio = 0;
  Real largestAsymmetryRatio = 0;
};
template <int D>
SymbolExtremes<D> symbolExtremes(const LatticeStencil<D>& stencil, Real spacing, int samplesPerAxis);

// Unit directions of the lattice: [1, 0, 0] and [1, 1, 1] / sqrt(D) ([1] for both in 1-D).
template <int D>
Vec<D> latticeAxis();
template <int D>
Vec<D> latticeDiagonal();

}  // namespace mfwave
