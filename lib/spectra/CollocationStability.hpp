#pragma once
// Stability and dispersion of explicit strong-form collocation in 1-D (Luo-Liu-Huang 2011,
// eqs. (34)-(45)), three ways:
//
//  1. von Neumann on a uniform node line (eqs. (34)-(41)): M_ij = psi_j(xi_i), A_ij = psi_j,xx(xi_i),
//     G = A M^{-1}, D(k) = sum_j G_mj exp(i (j - m) k h) for an interior row m of a line long enough
//     that the row is translation invariant; D >= 0 for some k: unconditionally unstable, otherwise
//     dt_crit = (1/c) sqrt(-4 / D_min), D_min the most negative D over k in (0, pi/h].
//  2. The eigenvalues of the assembled, constrained bar (u(0) = 0, E u_x(L) = 0; collocation points
//     at the nodes, boundary points carry only their constraint rows): U'' = -K U with K over the
//     interior nodal values. Real non-negative spectrum: dt_crit = 2 / sqrt(lambda_max); a complex
//     pair (or a negative eigenvalue): central difference grows at every dt.
//  3. Bisection on actual central-difference runs of that system from a random initial state.
//
// Dispersion (eqs. (42)-(45)): the normalised phase speed p(kh) = omega / (c k) with
// omega^2 = c^2 sum_i K_{m,m+i} cos(k i h) / sum_i M_{m,m+i} cos(k i h), K_IJ = -psi_I,xx(x_J),
// M_IJ = psi_I(x_J), and the group speed d omega / dk / c, both from explicit stencils so that a
// closed form (the 3-point finite-difference Laplacian) can check them.

#include "core/Types.hpp"
#include "methods/collocation/ShapeFunctions.hpp"
#include "particles/ParticleSet.hpp"

#include <Eigen/Core>
#include <complex>
#include <cstdint>
#include <string>
#include <vector>

namespace mfwave {

// A translation-invariant row: weights[q] multiplies the node at offset offsets[q] from the centre.
struct Stencil {
  std::vector<int> offsets;
  std::vector<Real> weights;

  // sum_q w_q exp(i o_q theta), theta = k h.
  std::complex<Real> symbol(Real theta) const;
  // sum_q w_q cos(o_q theta) and its derivative with respect to theta.
  Real cosineSum(Real theta) const;
  Real cosineSumDerivative(Real theta) const;
  // Stencil of row `centre` of a matrix (row = true) or of its column (row = false), offsets
  // relative to `centre`; entries with |w| <= dropBelow * max|w| are left out.
  static Stencil fromRow(const Eigen::MatrixXd& matrix, Index centre, Real dropBelow = 0);
  static Stencil fromColumn(const Eigen::MatrixXd& matrix, Index centre, Real dropBelow = 0);
};

// Uniform node line x_i = i h, i = 0..count-1.
Coordinates<1> uniformLine(Index count, Real spacing);

// The collocation rows of node `centre` on a line with collocation points at the nodes:
// mass (M row), laplacian (A row), amplification (row of G = A M^{-1}), plus the columns used by
// eq. (45) (massColumn: psi_m(x_{m+i}), stiffnessColumn: -psi_m,xx(x_{m+i})).
struct CollocationRows {
  Real spacing = 0;
  Stencil mass, laplacian, amplification, massColumn, stiffnessColumn;
};
CollocationRows collocationRows(const ShapeFunctions<1>& shapes, const Coordinates<1>& nodes, Index centre,
                                Real spacing);

struct VonNeumannResult {
  bool unconditionallyUnstable = false;
  Real dMin = 0;          // most negative Re D over the sweep [1/length^2]
  Real khAtMin = 0;       // k h where it is reached
  Real dMax = 0;          // largest Re D (>= 0 within tolerance: unstable)
  Real khAtMax = 0;
  Real maxImaginary = 0;  // largest |Im D| (0 for a symmetric row)
  Real criticalStep = 0;  // (1/c) sqrt(-4 / dMin); 0 when unconditionally unstable
};
// Sweeps theta = k h over (0, pi] on `samples` points, refines the minimum by golden section.
// D counts as >= 0 when Re D > positiveTolerance * |dMin| (round-off in a consistent row makes
// D(k -> 0) ~ 1e-13 instead of -k^2).
VonNeumannResult vonNeumannStability(const Stencil& amplification, Real spacing, Real waveSpeed, int samples = 4000,
                                     Real positiveTolerance = 1e-9);

// Normalised phase speed p = omega / (c k) and group speed (d omega / dk) / c from eq. (45), with
// explicit stiffness (K) and mass (M) stencils in consistent units (K ~ 1/h^2). NaN when the
// ratio is negative (no real frequency).
Real phaseSpeed(const Stencil& stiffness, const Stencil& mass, Real kh, Real spacing);
Real groupSpeed(const Stencil& stiffness, const Stencil& mass, Real kh, Real spacing);

// ---- the constrained bar of Luo-Liu-Huang section 4
struct BarProblem {
  Real length = 10;
  Index nodes = 21;
  Real modulus = 10;
  Real density = 1;
  Real waveSpeed() const;
  Real spacing() const { return length / static_cast<Real>(nodes - 1); }
};

// K (interior nodes x interior nodes) such that U'' = -K U for zero loads, U the values at the
// interior collocation points: C = [Psi(x_1..x_{N-2}); psi(x_0); E psi_x(x_{N-1})],
// K = -c^2 A_I C^{-1}[:, interior].
Eigen::MatrixXd constrainedBarStiffness(const ShapeFunctions<1>& shapes, const BarProblem& bar);

struct EigenvalueStability {
  bool unconditionallyUnstable = false;
  Real lambdaMax = 0;        // largest real part
  Real largestModulus = 0;   // max |lambda|
  Real lambdaMinReal = 0;    // smallest real part
  Real maxImaginaryRatio = 0;  // max |Im lambda| / max |lambda|
  Real growthRate = 0;       // max Im sqrt(lambda) [1/time]: e-folding rate of the unstable mode
  Real criticalStep = 0;     // 2 / sqrt(lambdaMax); 0 when unconditionally unstable
  std::string verdict() const;  // "dt_crit = ..." or "unconditionally unstable (complex pair, growth rate ...)"
};
EigenvalueStability eigenvalueStability(const Eigen::MatrixXd& stiffness, Real imaginaryTolerance = 1e-9);

struct BoundedRun {
  bool bounded = true;
  long steps = 0;
  std::string message;  // the StabilityMonitor's message when stopped
};
// Central difference on U'' = -K U from a seeded random (u0, v0) of unit size, for
// max(minSteps, horizon / dt) steps, with the StabilityMonitor (absolute limit growthLimit).
BoundedRun runCentralDifference(const Eigen::MatrixXd& stiffness, Real dt, long minSteps, Real horizon,
                                Real growthLimit = 1e6, std::uint32_t seed = 12345);

struct BisectionOptions {
  long minSteps = 20000;
  Real horizon = 0;              // simulated time each run covers at least (0: minSteps * guess)
  Real relativeTolerance = 1e-4;
  Real smallestFraction = 1e-2;  // stop searching down below this fraction of the guess
  Real growthLimit = 1e6;
};
struct BisectionResult {
  bool unconditionallyUnstable = false;  // unstable down to smallestFraction * guess
  Real criticalStep = 0;                 // largest dt found bounded
  Real smallestTried = 0;
  int runs = 0;
};
BisectionResult bisectCriticalStep(const Eigen::MatrixXd& stiffness, Real guess, const BisectionOptions& options = {});

}  // namespace mfwave
