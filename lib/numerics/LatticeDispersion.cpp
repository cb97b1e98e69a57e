#include "numerics/LatticeDispersion.hpp"

#include "core/Error.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>

namespace mfwave {

namespace {

constexpr Real kNoRatio = std::numeric_limits<Real>::quiet_NaN();
constexpr Real kInf = std::numeric_limits<Real>::infinity();
constexpr Real kTwoPi = 6.28318530717958647692;

using RowMajorMatrix = Eigen::SparseMatrix<Real, Eigen::RowMajor, int>;

template <int D>
Real blockScale(const LatticeStencil<D>& stencil) {
  Real scale = 0;
  for (const auto& g : stencil.blocks) scale += g.cwiseAbs().maxCoeff();
  return scale;
}

template <int D>
Vec<D> unitDirection(const Vec<D>& direction) {
  const Real norm = direction.norm();
  if (!(norm > 0) || !std::isfinite(norm)) throw InputError("direction", "must be a finite non-zero vector");
  return direction / norm;
}

template <int D>
void checkStencil(const LatticeStencil<D>& stencil) {
  if (stencil.components < 1 || stencil.blocks.empty() || stencil.blocks.size() != stencil.offsets.size())
    throw InputError("stencil", "is empty or its offsets and blocks differ in number");
}

// One eigenpair of a small real matrix with its derivative along a parameter, dMatrix the
// derivative of the matrix.
struct EigenPair {
  Real value = 0;
  Real derivative = 0;
  bool complexPair = false;
  Eigen::VectorXd vector;
};

std::vector<EigenPair> eigenPairs(const Eigen::MatrixXd& matrix, const Eigen::MatrixXd& dMatrix, bool symmetric,
                                  Real scale) {
  const Index n = matrix.rows();
  std::vector<EigenPair> pairs(static_cast<std::size_t>(n));
  if (symmetric) {
    const Eigen::MatrixXd sym = 0.5 * (matrix + matrix.transpose());
    const Eigen::MatrixXd dSym = 0.5 * (dMatrix + dMatrix.transpose());
    const SymmetricEigenpairs solver = symmetricEigenpairs(sym, "lattice dispersion (symmetric symbol)");
    for (Index j = 0; j < n; ++j) {
      auto& p = pairs[static_cast<std::size_t>(j)];
      p.vector = solver.vectors.col(j);
      p.value = solver.values(j);
      p.derivative = p.vector.dot(dSym * p.vector);
    }
    return pairs;
  }
  const GeneralEigenpairs solver = generalEigenpairs(matrix, true, "lattice dispersion (symbol)");
  const Eigen::MatrixXcd& right = solver.vectors;
  const Eigen::MatrixXcd left = right.inverse();  // rows: left eigenvectors with left * right = I
  const Eigen::MatrixXcd dProjected = left * dMatrix.cast<std::complex<Real>>() * right;
  for (Index j = 0; j < n; ++j) {
    auto& p = pairs[static_cast<std::size_t>(j)];
    const std::complex<Real> value = solver.values(j);
    p.value = value.real();
    p.complexPair = std::abs(value.imag()) > 1e-12 * std::max(scale, std::abs(value));
    p.derivative = dProjected(j, j).real();
    Eigen::VectorXcd v = right.col(j);
    // A real eigenvector of a real eigenvalue, up to a complex phase: rotate it real.
    Index big = 0;
    v.cwiseAbs().maxCoeff(&big);
    if (std::abs(v(big)) > 0) v *= std::conj(v(big)) / std::abs(v(big));
    p.vector = v.real();
    const Real norm = p.vector.norm();
    if (norm > 0) p.vector /= norm;
  }
  std::sort(pairs.begin(), pairs.end(), [](const EigenPair& a, const EigenPair& b) { return a.value < b.value; });
  return pairs;
}

template <int D>
Real alignmentOf(const Eigen::VectorXd& v, const Vec<D>& n, int components) {
  if (components != D) return components == 1 && D == 1 ? 1 : kNoRatio;
  const Real norm = v.norm();
  if (!(norm > 0)) return 0;
  Real dot = 0;
  for (int i = 0; i < D; ++i) dot += v(i) * n(i);
  return std::abs(dot) / norm;
}

}  // namespace

template <int D>
void checkPolarisationExists(int components, Polarisation polarisation) {
  const bool ok = (polarisation == Polarisation::Scalar && components == 1) ||
                  (polarisation == Polarisation::P && components == D) ||
                  (polarisation == Polarisation::S && components == D && D >= 2);
  if (!ok) {
    std::ostringstream s;
    s << polarisationName(polarisation) << " does not exist for " << components << " component(s) per particle in "
      << D << "-D";
    throw InputError("polarisation", s.str());
  }
}

std::size_t polarisationBranch(const std::vector<LatticeMode>& modes, Polarisation polarisation) {
  if (polarisation == Polarisation::Scalar || modes.size() <= 1) return 0;
  std::size_t p = 0;
  for (std::size_t j = 1; j < modes.size(); ++j)
    if (modes[j].alignment > modes[p].alignment + 1e-12) p = j;
  if (polarisation == Polarisation::P) return p;
  return p == 0 ? 1 : 0;  // the slowest branch other than P (ascending order)
}

template <int D>
Eigen::MatrixXd LatticeStencil<D>::rowSum() const {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(components, components);
  for (const auto& g : blocks) sum += g;
  return sum;
}

template <int D>
LatticeStencil<D> LatticeStencil<D>::withRowSumCorrection() const {
  LatticeStencil corrected = *this;
  for (std::size_t b = 0; b < offsets.size(); ++b)
    if (offsets[b].norm() == 0) {
      corrected.blocks[b] -= rowSum();
      return corrected;
    }
  throw InputError("stencil", "has no self block to correct");
}

template <int D>
LatticeStencil<D> extractLatticeStencil(const LinearSecondOrderSystem& system, const ParticleSet<D>& particles,
                                        Index particle, Real dropBelow) {
  const Index n = particles.physicalCount();
  if (particle < 0 || particle >= n) throw InputError("particle", "is not a physical particle of the set");
  if (n == 0 || system.size() % n != 0)
    throw InputError("system", "its size is not a multiple of the number of physical particles");
  const int c = static_cast<int>(system.size() / n);
  const RowMajorMatrix stiffness = system.stiffness();
  const RowMajorMatrix mass = system.mass();

  LatticeStencil<D> stencil;
  stencil.components = c;
  const Vec<D> xa = particles.position(particle);
  std::vector<Index> columns;  // neighbour particle of each block
  std::vector<Real> diagonal(static_cast<std::size_t>(c));
  for (int i = 0; i < c; ++i) {
    const int row = static_cast<int>(particle * c + i);
    Real m = 0;
    for (RowMajorMatrix::InnerIterator it(mass, row); it; ++it) {
      if (it.col() != row && it.value() != 0)
        throw InputError("system", "the mass matrix is not diagonal in the row of the particle");
      if (it.col() == row) m = it.value();
    }
    if (!(m > 0)) throw InputError("system", "the mass of the particle is not positive");
    diagonal[static_cast<std::size_t>(i)] = m;
  }
  for (int i = 0; i < c; ++i) {
    const int row = static_cast<int>(particle * c + i);
    for (RowMajorMatrix::InnerIterator it(stiffness, row); it; ++it) {
      const Index b = it.col() / c;
      const int k = static_cast<int>(it.col() % c);
      auto found = std::find(columns.begin(), columns.end(), b);
      std::size_t slot = static_cast<std::size_t>(found - columns.begin());
      if (found == columns.end()) {
        columns.push_back(b);
        stencil.offsets.push_back(particles.position(b) - xa);
        stencil.blocks.push_back(Eigen::MatrixXd::Zero(c, c));
      }
      stencil.blocks[slot](i, k) = -it.value() / diagonal[static_cast<std::size_t>(i)];
    }
  }
  if (dropBelow > 0 && !stencil.blocks.empty()) {
    Real largest = 0;
    for (const auto& g : stencil.blocks) largest = std::max(largest, g.cwiseAbs().maxCoeff());
    LatticeStencil<D> kept;
    kept.components = c;
    for (std::size_t b = 0; b < stencil.blocks.size(); ++b)
      if (stencil.blocks[b].cwiseAbs().maxCoeff() > dropBelow * largest) {
        kept.offsets.push_back(stencil.offsets[b]);
        kept.blocks.push_back(stencil.blocks[b]);
      }
    return kept;
  }
  return stencil;
}

template <int D>
Real stencilDifference(const LatticeStencil<D>& first, const LatticeStencil<D>& second, Real offsetTolerance,
                       bool commonOffsetsOnly) {
  if (first.components != second.components) return kInf;
  if (!commonOffsetsOnly && first.size() != second.size()) return kInf;
  Real largest = 0, difference = 0;
  for (std::size_t b = 0; b < first.offsets.size(); ++b) {
    largest = std::max(largest, first.blocks[b].cwiseAbs().maxCoeff());
    std::size_t match = second.offsets.size();
    for (std::size_t q = 0; q < second.offsets.size(); ++q)
      if ((second.offsets[q] - first.offsets[b]).norm() <= offsetTolerance) {
        match = q;
        break;
      }
    if (match == second.offsets.size()) {
      if (commonOffsetsOnly) continue;
      return kInf;
    }
    difference = std::max(difference, (first.blocks[b] - second.blocks[match]).cwiseAbs().maxCoeff());
  }
  return largest > 0 ? difference / largest : difference;
}

template <int D>
StencilSymbol stencilSymbol(const LatticeStencil<D>& stencil, const Vec<D>& wavevector) {
  checkStencil(stencil);
  const int c = stencil.components;
  // Re S = -sum_b G_b cos(theta_b) = S(0) + sum_b G_b 2 sin^2(theta_b / 2): the second form keeps
  // the long waves free of the cancellation between the self block and its neighbours.
  Eigen::MatrixXd re = -stencil.rowSum(), im = Eigen::MatrixXd::Zero(c, c);
  for (std::size_t b = 0; b < stencil.offsets.size(); ++b) {
    const Real theta = wavevector.dot(stencil.offsets[b]);
    const Real half = std::sin(theta / 2);
    re += 2 * half * half * stencil.blocks[b];
    im -= std::sin(theta) * stencil.blocks[b];
  }
  const Real scale = blockScale(stencil);
  StencilSymbol symbol;
  symbol.real = re;
  symbol.imaginaryRatio = scale > 0 ? im.cwiseAbs().maxCoeff() / scale : 0;
  symbol.asymmetryRatio = scale > 0 ? (re - re.transpose()).cwiseAbs().maxCoeff() / scale : 0;
  return symbol;
}

const char* polarisationName(Polarisation polarisation) {
  switch (polarisation) {
    case Polarisation::P: return "P";
    case Polarisation::S: return "S";
    case Polarisation::Scalar: return "scalar";
  }
  return "?";
}

template <int D>
std::vector<LatticeMode> latticeModes(const LatticeStencil<D>& stencil, const Vec<D>& direction, Real wavenumber,
                                      Real imaginaryTolerance) {
  checkStencil(stencil);
  if (!(wavenumber > 0) || !std::isfinite(wavenumber)) throw InputError("wavenumber", "must be positive and finite");
  const Vec<D> n = unitDirection(direction);
  const StencilSymbol symbol = stencilSymbol(stencil, Vec<D>(wavenumber * n));
  if (symbol.imaginaryRatio > imaginaryTolerance) {
    std::ostringstream s;
    s << "is not symmetric: the imaginary part of its symbol is " << symbol.imaginaryRatio
      << " of its scale (tolerance " << imaginaryTolerance << ")";
    throw InputError("stencil", s.str());
  }
  // d Re S / d|k| = sum_b G_b (n . r_b) sin(|k| n . r_b).
  const int c = stencil.components;
  Eigen::MatrixXd derivative = Eigen::MatrixXd::Zero(c, c);
  for (std::size_t b = 0; b < stencil.offsets.size(); ++b) {
    const Real s = n.dot(stencil.offsets[b]);
    derivative += s * std::sin(wavenumber * s) * stencil.blocks[b];
  }
  const bool symmetric = symbol.asymmetryRatio <= 1e-12;
  const auto pairs = eigenPairs(symbol.real, derivative, symmetric, blockScale(stencil));
  std::vector<LatticeMode> modes;
  for (const auto& p : pairs) {
    LatticeMode m;
    m.omegaSquared = p.value;
    m.complexPair = p.complexPair;
    m.omega = (p.value >= 0 && !p.complexPair) ? std::sqrt(p.value) : kNoRatio;
    m.phaseSpeed = m.omega / wavenumber;
    m.groupSpeed = m.omega > 0 ? p.derivative / (2 * m.omega) : kNoRatio;
    m.polarisation = p.vector;
    m.alignment = alignmentOf<D>(p.vector, n, c);
    modes.push_back(m);
  }
  return modes;
}

template <int D>
LatticeMode latticeMode(const LatticeStencil<D>& stencil, const Vec<D>& direction, Real wavenumber,
                        Polarisation polarisation, Real imaginaryTolerance) {
  checkStencil(stencil);
  checkPolarisationExists<D>(stencil.components, polarisation);
  const auto modes = latticeModes(stencil, direction, wavenumber, imaginaryTolerance);
  return modes[polarisationBranch(modes, polarisation)];
}

template <int D>
LongWaveLimit longWaveLimit(const LatticeStencil<D>& stencil, const Vec<D>& direction, Polarisation polarisation) {
  checkStencil(stencil);
  checkPolarisationExists<D>(stencil.components, polarisation);
  const Vec<D> n = unitDirection(direction);
  const int c = stencil.components;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(c, c);
  for (std::size_t b = 0; b < stencil.offsets.size(); ++b) {
    const Real s = n.dot(stencil.offsets[b]);
    a += 0.5 * s * s * stencil.blocks[b];
  }
  const Eigen::MatrixXd s0 = -stencil.rowSum();
  const Real scale = blockScale(stencil);
  const bool symmetric = (a - a.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * std::max(scale, a.cwiseAbs().maxCoeff());
  // The eigenpairs of A, with v . S0 v riding along as the "derivative" slot.
  const auto pairs = eigenPairs(a, s0, symmetric, a.cwiseAbs().maxCoeff());
  std::vector<LatticeMode> branches(pairs.size());
  for (std::size_t b = 0; b < pairs.size(); ++b) branches[b].alignment = alignmentOf<D>(pairs[b].vector, n, c);
  const std::size_t j = polarisationBranch(branches, polarisation);
  LongWaveLimit limit;
  const Real gapSquared = pairs[j].derivative;
  // Round-off in the row sum of an exact row leaves |v . S0 v| ~ 1e-16 scale: a gap of zero.
  if (std::abs(gapSquared) <= 1e-12 * scale) limit.gap = 0;
  else limit.gap = gapSquared > 0 ? std::sqrt(gapSquared) : kNoRatio;
  limit.speed = (pairs[j].value >= 0 && !pairs[j].complexPair) ? std::sqrt(pairs[j].value) : kNoRatio;
  limit.alignment = branches[j].alignment;
  return limit;
}

template <int D>
std::vector<DispersionSample> dispersionCurve(const LatticeStencil<D>& stencil, const Vec<D>& direction,
                                              Polarisation polarisation, Real referenceSpeed, Real spacing,
                                              Real kdxMin, Real kdxMax, int points) {
  if (!(spacing > 0) || !std::isfinite(spacing)) throw InputError("spacing", "must be positive and finite");
  if (!(referenceSpeed > 0) || !std::isfinite(referenceSpeed))
    throw InputError("reference_speed", "must be positive and finite");
  if (!(kdxMin > 0) || !(kdxMax > kdxMin) || !std::isfinite(kdxMax))
    throw InputError("kdx", "need 0 < kdxMin < kdxMax");
  if (points < 2) throw InputError("points", "need at least 2");
  std::vector<DispersionSample> curve;
  for (int s = 0; s < points; ++s) {
    DispersionSample sample;
    sample.kdx = kdxMin + (kdxMax - kdxMin) * s / (points - 1);
    sample.wavenumber = sample.kdx / spacing;
    const LatticeMode m = latticeMode(stencil, direction, sample.wavenumber, polarisation);
    sample.phaseSpeedRatio = m.phaseSpeed / referenceSpeed;
    sample.groupSpeedRatio = m.groupSpeed / referenceSpeed;
    sample.alignment = m.alignment;
    curve.push_back(sample);
  }
  return curve;
}

template <int D>
AccuracyResolution pointsPerWavelength(const LatticeStencil<D>& stencil, const Vec<D>& direction,
                                       Polarisation polarisation, Real referenceSpeed, Real spacing, Real tolerance,
                                       Real kdxMin, Real kdxMax, int samples) {
  if (!(tolerance > 0)) throw InputError("tolerance", "must be positive");
  if (!(spacing > 0) || !std::isfinite(spacing)) throw InputError("spacing", "must be positive and finite");
  if (!(referenceSpeed > 0)) throw InputError("reference_speed", "must be positive");
  if (!(kdxMin > 0) || !(kdxMax > kdxMin)) throw InputError("kdx", "need 0 < kdxMin < kdxMax");
  if (samples < 2) throw InputError("samples", "need at least 2");
  auto fails = [&](Real kdx) {
    const Real p = latticeMode(stencil, direction, kdx / spacing, polarisation).phaseSpeed / referenceSpeed;
    return !(std::abs(p - 1) < tolerance);
  };
  AccuracyResolution result;
  if (fails(kdxMin)) {
    result.pointsPerWavelength = kInf;
    return result;
  }
  result.attained = true;
  Real below = kdxMin;
  for (int s = 1; s < samples; ++s) {
    const Real kdx = kdxMin + (kdxMax - kdxMin) * s / (samples - 1);
    if (!fails(kdx)) {
      below = kdx;
      continue;
    }
    Real above = kdx;
    for (int it = 0; it < 60 && above - below > 1e-13 * above; ++it) {
      const Real mid = 0.5 * (below + above);
      (fails(mid) ? above : below) = mid;
    }
    result.kdx = below;
    result.pointsPerWavelength = kTwoPi / below;
    return result;
  }
  result.wholeBand = true;
  result.kdx = kdxMax;
  result.pointsPerWavelength = kTwoPi / kdxMax;
  return result;
}

template <int D>
Vec<D> latticeAxis() {
  Vec<D> n = Vec<D>::Zero();
  n(0) = 1;
  return n;
}

template <int D>
Vec<D> latticeDiagonal() {
  return Vec<D>::Constant(1 / std::sqrt(static_cast<Real>(D)));
}

template <int D>
SymbolExtremes<D> symbolExtremes(const LatticeStencil<D>& stencil, Real spacing, int samplesPerAxis) {
  if (samplesPerAxis < 1) throw InputError("samples_per_axis", "must be at least 1");
  SymbolExtremes<D> e;
  e.smallest = std::numeric_limits<Real>::infinity();
  e.largest = -std::numeric_limits<Real>::infinity();
  const long points = static_cast<long>(std::pow(samplesPerAxis + 1, D));
  for (long p = 0; p < points; ++p) {
    Vec<D> kdx;
    long rest = p;
    for (int a = 0; a < D; ++a) {
      kdx(a) = kPi * static_cast<Real>(rest % (samplesPerAxis + 1)) / samplesPerAxis;
      rest /= samplesPerAxis + 1;
    }
    const StencilSymbol symbol = stencilSymbol(stencil, Vec<D>(kdx / spacing));
    const Eigen::MatrixXd symmetric = 0.5 * (symbol.real + symbol.real.transpose());
    const Eigen::VectorXd omega2 = symmetricEigenvalues(symmetric, "lattice stencil extremes");
    if (omega2.minCoeff() < e.smallest) {
      e.smallest = omega2.minCoeff();
      e.smallestAt = kdx;
    }
    e.largest = std::max(e.largest, omega2.maxCoeff());
    e.largestImaginaryRatio = std::max(e.largestImaginaryRatio, symbol.imaginaryRatio);
    e.largestAsymmetryRatio = std::max(e.largestAsymmetryRatio, symbol.asymmetryRatio);
  }
  return e;
}

#define MFWAVE_LATTICE_DISPERSION(D)                                                                               \
  template struct LatticeStencil<D>;                                                                               \
  template LatticeStencil<D> extractLatticeStencil<D>(const LinearSecondOrderSystem&, const ParticleSet<D>&, Index, \
                                                      Real);                                                       \
  template Real stencilDifference<D>(const LatticeStencil<D>&, const LatticeStencil<D>&, Real, bool);              \
  template StencilSymbol stencilSymbol<D>(const LatticeStencil<D>&, const Vec<D>&);                                \
  template std::vector<LatticeMode> latticeModes<D>(const LatticeStencil<D>&, const Vec<D>&, Real, Real);          \
  template LatticeMode latticeMode<D>(const LatticeStencil<D>&, const Vec<D>&, Real, Polarisation, Real);          \
  template LongWaveLimit longWaveLimit<D>(const LatticeStencil<D>&, const Vec<D>&, Polarisation);                  \
  template std::vector<DispersionSample> dispersionCurve<D>(const LatticeStencil<D>&, const Vec<D>&, Polarisation, \
                                                            Real, Real, Real, Real, int);                         \
  template AccuracyResolution pointsPerWavelength<D>(const LatticeStencil<D>&, const Vec<D>&, Polarisation, Real,  \
                                                     Real, Real, Real, Real, int);                                 \
  template Vec<D> latticeAxis<D>();                                                                                \
  template void checkPolarisationExists<D>(int, Polarisation);                                                     \
  template Vec<D> latticeDiagonal<D>();                                                                             \
  template struct SymbolExtremes<D>;                                                                               \
  template SymbolExtremes<D> symbolExtremes<D>(const LatticeStencil<D>&, Real, int);

MFWAVE_LATTICE_DISPERSION(1)
MFWAVE_LATTICE_DISPERSION(2)
MFWAVE_LATTICE_DISPERSION(3)

#undef MFWAVE_LATTICE_DISPERSION

}  // namespace mfwave
