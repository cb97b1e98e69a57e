#pragma once
// The discrete dispersion relation omega(k) of a linear method for every wavenumber of a periodic
// lattice at once, from the FFT of the assembled operator's response to a unit impulse.
//
// On the periodic lattice (PeriodicLattice.hpp) the impulse response of component q at node 0 is
// the column h_q(x) = (A e_{0,q})(x) = G_{-x}(:, q). Its discrete Fourier transform is
//   sum_x h(x) exp(-i k . x) = sum_b G_b exp(i k . r_b) = -S(k),
// the symbol of LatticeDispersion.hpp, at every k = 2 pi m / (N dx), m in [0, N)^D. The same
// transform of i x_j h(x) gives dS/dk_j exactly (no finite differences), and likewise for the mass
// M(k). A plane wave u = U exp(i (k . x - omega t)) solves M u'' = A u when
//   omega^2 M(k) U = S(k) U,
// so the branches are the eigenvalues of M(k)^{-1} S(k), and the group speed along n follows from
// first-order perturbation of that eigenvalue (the left eigenvectors are the rows of V^{-1}):
//   d omega^2 / d|k| = (V^{-1} M^{-1} (dS_n - dM_n M^{-1} S) V)_ii,   d omega / d|k| = that / (2 omega).
// For a degenerate pair (the two S waves along a cube axis) this holds because the symmetry keeps
// the pair degenerate along the axis.
//
// Lines: along an axis, m = (j, 0, 0), |k| dx = 2 pi j / N for j = 1 .. N/2 (up to pi); along the
// diagonal, m = (j, j, j), |k| dx = sqrt(D) 2 pi j / N (the Brillouin zone corner at j = N/2).

#include "numerics/FourierTransform.hpp"
#include "numerics/LatticeDispersion.hpp"
#include "numerics/PeriodicLattice.hpp"

#include <complex>
#include <vector>

namespace mfwave {

enum class LatticeDirection { Axis, Diagonal };
const char* latticeDirectionName(LatticeDirection direction);  // "axis", "diagonal"
// Throws InputError(key) for a name other than "axis" or "diagonal".
LatticeDirection parseLatticeDirection(const std::string& name, const std::string& key = "direction");
template <int D>
Vec<D> latticeDirectionVector(LatticeDirection direction);  // unit vector

// Grid index of sample j of a line: (j, 0, 0) along the axis, (j, j, j) along the diagonal.
template <int D>
std::array<int, D> lineIndex(LatticeDirection direction, int j);

template <int D>
class DispersionSpectrum {
 public:
  // Transforms the impulse responses of the operator (components^2 transforms of N^D points, and
  // D more for each derivative; the same again for a mass stencil).
  explicit DispersionSpectrum(const PeriodicLatticeOperator<D>& op);

  int cells() const { return cells_; }
  int components() const { return components_; }
  Real spacing() const { return spacing_; }
  Index points() const { return points_; }  // N^D

  // The wavevector of grid point m (entries in [0, N)): k_j = 2 pi m_j / (N dx), taken in
  // (-pi/dx, pi/dx] so that |k| is the shortest equivalent wavevector.
  Vec<D> wavevector(const std::array<int, D>& m) const;
  // S(k), M(k) (identity when lumped), dS/dk_j and dM/dk_j at grid point m.
  Eigen::MatrixXcd symbol(const std::array<int, D>& m) const;
  Eigen::MatrixXcd massSymbol(const std::array<int, D>& m) const;
  Eigen::MatrixXcd symbolDerivative(const std::array<int, D>& m, int axis) const;
  Eigen::MatrixXcd massSymbolDerivative(const std::array<int, D>& m, int axis) const;

  // Every branch at grid point m, with group speeds along `direction` (normalised here); ascending
  // omega^2. At m = 0 the group speeds are 0.
  std::vector<LatticeMode> modes(const std::array<int, D>& m, const Vec<D>& direction) const;

  // Over the whole grid: the extreme eigenvalues of M^{-1} S and the largest |Im| of an eigenvalue
  // (relative to the largest |omega^2|): a stable, non-dissipative method has
  // smallestOmegaSquared >= 0 (to round-off) and no imaginary part.
  struct Extremes {
    Real largestOmegaSquared = 0;
    Real smallestOmegaSquared = 0;
    Vec<D> smallestAt = Vec<D>::Zero();  // the wavevector where omega^2 is smallest (first on ties)
    Real largestImaginaryRatio = 0;
  };
  Extremes extremes() const;

 private:
  std::size_t index(const std::array<int, D>& m) const;
  Eigen::MatrixXcd gather(const std::vector<ComplexVector>& planes, const std::array<int, D>& m) const;
  void transform(const LatticeStencil<D>& stencil, Real sign, std::vector<ComplexVector>& planes,
                 std::array<std::vector<ComplexVector>, D>& derivatives) const;

  int cells_ = 0;
  int components_ = 0;
  Real spacing_ = 1;
  Index points_ = 0;
  bool lumped_ = true;
  // planes[p * c + q][grid point]: S_pq; derivative planes per axis likewise.
  std::vector<ComplexVector> symbol_, mass_;
  std::array<std::vector<ComplexVector>, D> symbolDerivative_, massDerivative_;
};

// One branch along a lattice line (j = 1 .. N/2), speeds over referenceSpeed. Throws
// InputError("polarisation") as latticeMode does, InputError("reference_speed") for <= 0.
template <int D>
std::vector<DispersionSample> spectrumLine(const DispersionSpectrum<D>& spectrum, LatticeDirection direction,
                                           Polarisation polarisation, Real referenceSpeed);

// Points per wavelength for a phase error below `tolerance` from a line: the first |k| dx where
// |p - 1| reaches the tolerance, interpolated linearly between samples (so accurate to the line's
// spacing 2 pi / N in |k| dx). attained = false when the first sample already misses it.
AccuracyResolution lineAccuracy(const std::vector<DispersionSample>& line, Real tolerance);

// Anisotropy: the diagonal phase speed over the axis phase speed at the same |k| dx, minus 1, at
// each diagonal sample within the axis line's range (the axis line interpolated linearly).
struct AnisotropySample {
  Real kdx = 0;
  Real ratioMinusOne = 0;
};
std::vector<AnisotropySample> anisotropy(const std::vector<DispersionSample>& axis,
                                         const std::vector<DispersionSample>& diagonal);

}  // namespace mfwave
