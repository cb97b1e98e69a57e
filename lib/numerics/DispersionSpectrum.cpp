#include "numerics/DispersionSpectrum.hpp"

#include "core/Error.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mfwave {

namespace {

constexpr Real kNoValue = std::numeric_limits<Real>::quiet_NaN();

// Eigenpairs of T = M^{-1} S with left eigenvectors: V^{-1} T V = diag(lambda).
struct Decomposition {
  Eigen::VectorXcd values;
  Eigen::MatrixXcd right, left;  // left = V^{-1}
};

// Hermitian T (every lumped symmetric stencil, and collocation whose mass symbol is a real multiple
// of the identity) goes to the self-adjoint solver, whose eigenvectors stay orthonormal in a
// degenerate pair; anything else to the general complex solver.
Decomposition decompose(const Eigen::MatrixXcd& T) {
  Decomposition result;
  const Real scale = std::max<Real>(T.cwiseAbs().maxCoeff(), std::numeric_limits<Real>::min());
  if ((T - T.adjoint()).cwiseAbs().maxCoeff() <= 1e-12 * scale) {
    const Eigen::MatrixXcd hermitian = 0.5 * (T + T.adjoint());
    HermitianEigenpairs solver = hermitianEigenpairs(hermitian, "dispersion spectrum (Hermitian symbol)");
    result.values = solver.values.cast<std::complex<Real>>();
    result.right = std::move(solver.vectors);
    result.left = result.right.adjoint();
  } else {
    GeneralEigenpairs solver = generalEigenpairs(T, true, "dispersion spectrum (symbol)");
    result.values = std::move(solver.values);
    result.right = std::move(solver.vectors);
    result.left = result.right.inverse();
  }
  return result;
}

template <int D>
Real alignment(const Eigen::VectorXcd& v, const Vec<D>& n) {
  if (v.size() != D) return 1;
  std::complex<Real> along = 0;
  for (int d = 0; d < D; ++d) along += v(d) * n(d);
  const Real norm = v.norm();
  return norm > 0 ? std::abs(along) / norm : 0;
}

}  // namespace

const char* latticeDirectionName(LatticeDirection direction) {
  return direction == LatticeDirection::Axis ? "axis" : "diagonal";
}

LatticeDirection parseLatticeDirection(const std::string& name, const std::string& key) {
  if (name == "axis") return LatticeDirection::Axis;
  if (name == "diagonal") return LatticeDirection::Diagonal;
  throw InputError(key, "unknown direction '" + name + "' (axis, diagonal)");
}

template <int D>
Vec<D> latticeDirectionVector(LatticeDirection direction) {
  return direction == LatticeDirection::Axis ? latticeAxis<D>() : latticeDiagonal<D>();
}

template <int D>
std::array<int, D> lineIndex(LatticeDirection direction, int j) {
  std::array<int, D> m{};
  m[0] = j;
  if (direction == LatticeDirection::Diagonal) m.fill(j);
  return m;
}

template <int D>
DispersionSpectrum<D>::DispersionSpectrum(const PeriodicLatticeOperator<D>& op)
    : cells_(op.cells), components_(op.components()), spacing_(op.spacing), points_(op.nodes()),
      lumped_(op.lumped()) {
  // Re-check what the planes rely on (an operator built without makePeriodicLatticeOperator).
  const PeriodicLatticeOperator<D> checked =
      makePeriodicLatticeOperator<D>(op.acceleration, op.spacing, op.cells, op.mass);
  transform(checked.acceleration, -1, symbol_, symbolDerivative_);
  if (!lumped_) transform(checked.mass, 1, mass_, massDerivative_);
}

// planes[p c + q] = FFT(sign h_pq), derivative planes FFT(-sign i x_j h_pq), h_pq(x) the
// p-component response at x to a unit impulse in component q at node 0 (see the header).
template <int D>
void DispersionSpectrum<D>::transform(const LatticeStencil<D>& stencil, Real sign, std::vector<ComplexVector>& planes,
                                      std::array<std::vector<ComplexVector>, D>& derivatives) const {
  const int c = components_;
  const auto n = static_cast<std::size_t>(points_);
  planes.assign(static_cast<std::size_t>(c * c), ComplexVector(n, 0));
  for (auto& axis : derivatives) axis.assign(static_cast<std::size_t>(c * c), ComplexVector(n, 0));
  // The response to a unit impulse in component q at node 0: row a of the periodic operator reads
  // G_b at node a + r_b, so the impulse reaches node a = -r_b with block column G_b(:, q). Placing
  // the blocks there is the same as a column of periodicMatrix without forming N^D rows.
  const auto steps = latticeSteps(stencil, spacing_);
  const std::complex<Real> i(0, 1);
  for (std::size_t b = 0; b < steps.size(); ++b) {
    std::array<int, D> at{};
    for (int d = 0; d < D; ++d) at[static_cast<std::size_t>(d)] = -steps[b][static_cast<std::size_t>(d)];
    const auto node = static_cast<std::size_t>(periodicNode<D>(at, cells_));
    for (int p = 0; p < c; ++p)
      for (int q = 0; q < c; ++q) {
        const Real g = stencil.blocks[b](p, q);
        const auto plane = static_cast<std::size_t>(p * c + q);
        planes[plane][node] += sign * g;
        // x = -r_b is the nearest periodic image of the node (the stencil reaches < N/2).
        for (int d = 0; d < D; ++d)
          derivatives[static_cast<std::size_t>(d)][plane][node] +=
              -sign * i * (at[static_cast<std::size_t>(d)] * spacing_) * g;
      }
  }
  for (auto& plane : planes) forwardFourierTransform(plane, D, cells_);
  for (auto& axis : derivatives)
    for (auto& plane : axis) forwardFourierTransform(plane, D, cells_);
}

template <int D>
std::size_t DispersionSpectrum<D>::index(const std::array<int, D>& m) const {
  for (int v : m)
    if (v < 0 || v >= cells_)
      throw InputError("wavenumber_index", std::to_string(v) + " is outside [0, " + std::to_string(cells_) + ")");
  return static_cast<std::size_t>(periodicNode<D>(m, cells_));
}

template <int D>
Eigen::MatrixXcd DispersionSpectrum<D>::gather(const std::vector<ComplexVector>& planes,
                                               const std::array<int, D>& m) const {
  const std::size_t at = index(m);
  Eigen::MatrixXcd result(components_, components_);
  for (int p = 0; p < components_; ++p)
    for (int q = 0; q < components_; ++q) result(p, q) = planes[static_cast<std::size_t>(p * components_ + q)][at];
  return result;
}

template <int D>
Vec<D> DispersionSpectrum<D>::wavevector(const std::array<int, D>& m) const {
  Vec<D> k;
  for (int d = 0; d < D; ++d) {
    int v = m[static_cast<std::size_t>(d)];
    if (v > cells_ / 2) v -= cells_;
    k(d) = 2 * kPi * v / (cells_ * spacing_);
  }
  return k;
}

template <int D>
Eigen::MatrixXcd DispersionSpectrum<D>::symbol(const std::array<int, D>& m) const {
  return gather(symbol_, m);
}

template <int D>
Eigen::MatrixXcd DispersionSpectrum<D>::massSymbol(const std::array<int, D>& m) const {
  if (lumped_) {
    index(m);
    return Eigen::MatrixXcd::Identity(components_, components_);
  }
  return gather(mass_, m);
}

template <int D>
Eigen::MatrixXcd DispersionSpectrum<D>::symbolDerivative(const std::array<int, D>& m, int axis) const {
  if (axis < 0 || axis >= D) throw InputError("axis", "must be in [0, " + std::to_string(D) + ")");
  return gather(symbolDerivative_[static_cast<std::size_t>(axis)], m);
}

template <int D>
Eigen::MatrixXcd DispersionSpectrum<D>::massSymbolDerivative(const std::array<int, D>& m, int axis) const {
  if (axis < 0 || axis >= D) throw InputError("axis", "must be in [0, " + std::to_string(D) + ")");
  if (lumped_) {
    index(m);
    return Eigen::MatrixXcd::Zero(components_, components_);
  }
  return gather(massDerivative_[static_cast<std::size_t>(axis)], m);
}

template <int D>
std::vector<LatticeMode> DispersionSpectrum<D>::modes(const std::array<int, D>& m, const Vec<D>& direction) const {
  const Real length = direction.norm();
  if (!(length > 0)) throw InputError("direction", "must not be zero");
  const Vec<D> n = direction / length;
  const Eigen::MatrixXcd S = symbol(m);
  Eigen::MatrixXcd T = S, dT = Eigen::MatrixXcd::Zero(components_, components_);
  for (int d = 0; d < D; ++d) dT += n(d) * symbolDerivative(m, d);
  if (!lumped_) {
    const Eigen::PartialPivLU<Eigen::MatrixXcd> mass(massSymbol(m));
    T = mass.solve(S);
    Eigen::MatrixXcd dM = Eigen::MatrixXcd::Zero(components_, components_);
    for (int d = 0; d < D; ++d) dM += n(d) * massSymbolDerivative(m, d);
    dT = mass.solve(dT - dM * T);
  }
  const Decomposition eig = decompose(T);
  const Eigen::MatrixXcd dLambda = eig.left * dT * eig.right;
  const Vec<D> k = wavevector(m);
  const Real wavenumber = k.norm();

  std::vector<LatticeMode> result;
  for (int b = 0; b < components_; ++b) {
    LatticeMode mode;
    mode.omegaSquared = eig.values(b).real();
    mode.complexPair = std::abs(eig.values(b).imag()) > 1e-9 * std::max<Real>(1, std::abs(eig.values(b)));
    mode.omega = mode.omegaSquared >= 0 && !mode.complexPair ? std::sqrt(mode.omegaSquared) : kNoValue;
    mode.phaseSpeed = wavenumber > 0 ? mode.omega / wavenumber : 0;
    mode.groupSpeed = wavenumber > 0 ? dLambda(b, b).real() / (2 * mode.omega) : 0;
    const Eigen::VectorXcd v = eig.right.col(b);
    mode.alignment = alignment<D>(v, n);
    // A real representative of the polarisation: the eigenvector times the phase of its largest entry.
    Index largest = 0;
    v.cwiseAbs().maxCoeff(&largest);
    const std::complex<Real> phase = std::abs(v(largest)) > 0 ? std::conj(v(largest)) / std::abs(v(largest)) : 1;
    mode.polarisation = (v * phase).real();
    const Real norm = mode.polarisation.norm();
    if (norm > 0) mode.polarisation /= norm;
    result.push_back(std::move(mode));
  }
  std::sort(result.begin(), result.end(),
            [](const LatticeMode& a, const LatticeMode& b) { return a.omegaSquared < b.omegaSquared; });
  return result;
}

template <int D>
typename DispersionSpectrum<D>::Extremes DispersionSpectrum<D>::extremes() const {
  Extremes result;
  result.largestOmegaSquared = -std::numeric_limits<Real>::infinity();
  result.smallestOmegaSquared = std::numeric_limits<Real>::infinity();
  Real imaginary = 0, modulus = 0;
  long smallestAt = 0;
  const auto total = static_cast<long>(points_);
#pragma omp parallel
  {
    Real largest = -std::numeric_limits<Real>::infinity(), smallest = std::numeric_limits<Real>::infinity();
    Real localImaginary = 0, localModulus = 0;
    long localAt = 0;
#pragma omp for schedule(static) nowait
    for (long at = 0; at < total; ++at) {
      const std::array<int, D> m = latticeCoordinates<D>(at, cells_);
      Eigen::MatrixXcd T = symbol(m);
      if (!lumped_) T = massSymbol(m).partialPivLu().solve(T);
      const Eigen::VectorXcd values = decompose(T).values;
      for (Index b = 0; b < values.size(); ++b) {
        largest = std::max(largest, values(b).real());
        if (values(b).real() < smallest) {
          smallest = values(b).real();
          localAt = at;
        }
        localImaginary = std::max(localImaginary, std::abs(values(b).imag()));
        localModulus = std::max(localModulus, std::abs(values(b)));
      }
    }
#pragma omp critical(mfwave_spectrum_extremes)
    {
      result.largestOmegaSquared = std::max(result.largestOmegaSquared, largest);
      // The first grid point of the smallest value, whatever the thread count.
      if (smallest < result.smallestOmegaSquared ||
          (smallest == result.smallestOmegaSquared && localAt < smallestAt)) {
        result.smallestOmegaSquared = smallest;
        smallestAt = localAt;
      }
      imaginary = std::max(imaginary, localImaginary);
      modulus = std::max(modulus, localModulus);
    }
  }
  result.smallestAt = wavevector(latticeCoordinates<D>(smallestAt, cells_));
  result.largestImaginaryRatio = modulus > 0 ? imaginary / modulus : 0;
  return result;
}

template <int D>
std::vector<DispersionSample> spectrumLine(const DispersionSpectrum<D>& spectrum, LatticeDirection direction,
                                           Polarisation polarisation, Real referenceSpeed) {
  if (!(referenceSpeed > 0)) throw InputError("reference_speed", "must be positive");
  checkPolarisationExists<D>(spectrum.components(), polarisation);
  const Vec<D> n = latticeDirectionVector<D>(direction);
  std::vector<DispersionSample> line;
  for (int j = 1; j <= spectrum.cells() / 2; ++j) {
    const std::array<int, D> m = lineIndex<D>(direction, j);
    const std::vector<LatticeMode> modes = spectrum.modes(m, n);
    const LatticeMode& mode = modes[polarisationBranch(modes, polarisation)];
    DispersionSample sample;
    sample.wavenumber = spectrum.wavevector(m).norm();
    sample.kdx = sample.wavenumber * spectrum.spacing();
    sample.phaseSpeedRatio = mode.phaseSpeed / referenceSpeed;
    sample.groupSpeedRatio = mode.groupSpeed / referenceSpeed;
    sample.alignment = mode.alignment;
    line.push_back(sample);
  }
  return line;
}

AccuracyResolution lineAccuracy(const std::vector<DispersionSample>& line, Real tolerance) {
  if (!(tolerance > 0)) throw InputError("tolerance", "must be positive");
  AccuracyResolution result;
  auto error = [](const DispersionSample& s) {
    const Real e = std::abs(s.phaseSpeedRatio - 1);
    return std::isfinite(e) ? e : std::numeric_limits<Real>::infinity();
  };
  if (line.empty() || error(line.front()) >= tolerance) {
    result.pointsPerWavelength = std::numeric_limits<Real>::infinity();
    return result;
  }
  result.attained = true;
  for (std::size_t s = 1; s < line.size(); ++s) {
    const Real e0 = error(line[s - 1]), e1 = error(line[s]);
    if (e1 >= tolerance) {
      const Real t = std::isfinite(e1) ? (tolerance - e0) / (e1 - e0) : 0;
      result.kdx = line[s - 1].kdx + t * (line[s].kdx - line[s - 1].kdx);
      result.pointsPerWavelength = 2 * kPi / result.kdx;
      return result;
    }
  }
  result.wholeBand = true;
  result.kdx = line.back().kdx;
  result.pointsPerWavelength = 2 * kPi / result.kdx;
  return result;
}

std::vector<AnisotropySample> anisotropy(const std::vector<DispersionSample>& axis,
                                         const std::vector<DispersionSample>& diagonal) {
  std::vector<AnisotropySample> result;
  if (axis.size() < 2) return result;
  for (const DispersionSample& d : diagonal) {
    if (d.kdx < axis.front().kdx || d.kdx > axis.back().kdx) continue;
    std::size_t s = 1;
    while (s + 1 < axis.size() && axis[s].kdx < d.kdx) ++s;
    const Real t = (d.kdx - axis[s - 1].kdx) / (axis[s].kdx - axis[s - 1].kdx);
    const Real p = axis[s - 1].phaseSpeedRatio + t * (axis[s].phaseSpeedRatio - axis[s - 1].phaseSpeedRatio);
    result.push_back({d.kdx, d.phaseSpeedRatio / p - 1});
  }
  return result;
}

#define MFWAVE_DISPERSION_SPECTRUM(D)                                                                    \
  template Vec<D> latticeDirectionVector<D>(LatticeDirection);                                         \
  template std::array<int, D> lineIndex<D>(LatticeDirection, int);                                     \
  template class DispersionSpectrum<D>;                                                                  \
  template std::vector<DispersionSample> spectrumLine<D>(const DispersionSpectrum<D>&, LatticeDirection, \
                                                         Polarisation, Real);
MFWAVE_DISPERSION_SPECTRUM(1)
MFWAVE_DISPERSION_SPECTRUM(2)
MFWAVE_DISPERSION_SPECTRUM(3)
#undef MFWAVE_DISPERSION_SPECTRUM

}  // namespace mfwave
