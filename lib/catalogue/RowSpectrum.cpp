#include "catalogue/RowSpectrum.hpp"

#include "core/Error.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace mfwave {
namespace {

// The branches omega_h^2 at wavevector k (ascending) and their polarisations: eig(M(k)^-1 S(k)).
// M(k) = -stencilSymbol(mass).real, since the symbol of a stencil is -sum_b G_b exp(i k . r_b).
template <int D>
Eigen::EigenSolver<Eigen::MatrixXd> branches(const MethodLatticeStencil<D>& row, const Vec<D>& k) {
  Eigen::MatrixXd s = stencilSymbol(row.acceleration, k).real;
  if (row.mass.size() > 0) {
    const Eigen::MatrixXd m = -stencilSymbol(row.mass, k).real;
    s = m.partialPivLu().solve(s);
  }
  return Eigen::EigenSolver<Eigen::MatrixXd>(s);
}

template <int D>
Vec<D> gridWavevector(const std::array<int, D>& index, int samples, Real spacing) {
  Vec<D> k;
  for (int a = 0; a < D; ++a) k[a] = kPi * index[static_cast<std::size_t>(a)] / (samples - 1) / spacing;
  return k;
}

}  // namespace

template <int D>
RowSpectrum rowSpectrum(const MethodLatticeStencil<D>& row, Real spacing, int samplesPerAxis) {
  const int n = samplesPerAxis > 0 ? samplesPerAxis : (D == 1 ? 257 : D == 2 ? 49 : 17);
  RowSpectrum out;
  Real smallest = std::numeric_limits<Real>::infinity(), largest = 0;
  std::array<int, D> index{};
  Index total = 1;
  for (int a = 0; a < D; ++a) total *= n;
  for (Index flat = 0; flat < total; ++flat) {
    Index rest = flat;
    for (int a = 0; a < D; ++a) {
      index[static_cast<std::size_t>(a)] = static_cast<int>(rest % n);
      rest /= n;
    }
    const auto solver = branches<D>(row, gridWavevector<D>(index, n, spacing));
    for (Index b = 0; b < solver.eigenvalues().size(); ++b) {
      const std::complex<Real> lambda = solver.eigenvalues()[b];
      largest = std::max(largest, std::abs(lambda));
      smallest = std::min(smallest, lambda.real());
    }
  }
  out.omegaMax = std::sqrt(largest);
  out.growing = smallest < -1e-10 * largest;
  return out;
}

Real discreteFrequency(Real omega, Real dt, IntegratorKind integrator) {
  const Real x = omega * dt / 2;
  switch (integrator) {
    case IntegratorKind::CentralDifference:
    case IntegratorKind::Leapfrog:
      return x < 1 ? 2 / dt * std::asin(x) : std::numeric_limits<Real>::quiet_NaN();
    case IntegratorKind::Newmark: return 2 / dt * std::atan(x);
    default: return omega;  // Runge-Kutta tables: higher-order phase error
  }
}

Real planeWaveError(Real error, Real periods) { return 2 * std::abs(std::sin(kPi * periods * error)); }

template <int D>
RowPhaseError wavePhaseError(const MethodLatticeStencil<D>& row, const Vec<D>& wavevector, bool shear, Real speed,
                             Real dt, IntegratorKind integrator) {
  const Real k = wavevector.norm();
  if (!(k > 0)) throw InputError("wavevector", "must not be zero");
  const Vec<D> n = wavevector / k;
  const bool scalar = row.acceleration.components == 1;
  const auto solver = branches<D>(row, wavevector);
  // The branch of the wave by LatticeDispersion's rule (polarisationBranch: P the most aligned with n,
  // S the slowest of the others, the scalar row's only one), on the branches in ascending omega^2.
  std::vector<LatticeMode> modes;
  std::vector<Index> order;
  for (Index b = 0; b < solver.eigenvalues().size(); ++b) order.push_back(b);
  std::sort(order.begin(), order.end(), [&solver](Index a, Index b) {
    return solver.eigenvalues()[a].real() < solver.eigenvalues()[b].real();
  });
  for (const Index b : order) {
    LatticeMode m;
    m.omegaSquared = solver.eigenvalues()[b].real();
    const Eigen::VectorXd v = solver.eigenvectors().col(b).real().normalized();
    for (int a = 0; a < D && v.size() == D; ++a) m.alignment += v[a] * n[a];
    m.alignment = std::abs(m.alignment);
    modes.push_back(m);
  }
  const Polarisation polarisation = scalar ? Polarisation::Scalar : shear ? Polarisation::S : Polarisation::P;
  const Real omega2 = modes[polarisationBranch(modes, polarisation)].omegaSquared;
  const Real omegaH = omega2 > 0 ? std::sqrt(omega2) : std::numeric_limits<Real>::quiet_NaN();
  const Real exact = speed * k;
  RowPhaseError out;
  out.spatial = std::abs(omegaH / exact - 1);
  out.total = std::abs(discreteFrequency(omegaH, dt, integrator) / exact - 1);
  if (std::isnan(out.spatial)) out.spatial = std::numeric_limits<Real>::infinity();
  if (std::isnan(out.total)) out.total = std::numeric_limits<Real>::infinity();
  out.pointsPerWavelength = 2 * kPi / k;  // in units of length; divided by dx by the caller
  return out;
}

template <int D>
RowPhaseError rowPhaseError(const MethodLatticeStencil<D>& row, const Material& material, Real spacing,
                            Real frequency, Real dt, IntegratorKind integrator) {
  if (!(frequency > 0)) throw InputError("frequency", "must be positive");
  const bool scalar = row.acceleration.components == 1;
  Vec<D> axis = Vec<D>::Zero();
  axis[0] = 1;
  const Vec<D> diagonal = Vec<D>::Ones().normalized();
  struct Wave {
    const char* name;
    Real speed;
    bool shear;
  };
  std::vector<Wave> waves;
  if (scalar) waves.push_back({"the scalar wave", material.pWaveSpeed(), false});
  else {
    waves.push_back({"P", material.pWaveSpeed(), false});
    if (D > 1) waves.push_back({"S", material.sWaveSpeed(), true});
  }
  RowPhaseError worst;
  worst.total = -1;
  for (const Wave& w : waves)
    for (int direction = 0; direction < (D > 1 ? 2 : 1); ++direction) {
      const Vec<D> n = direction == 0 ? axis : diagonal;
      const Real k = 2 * kPi * frequency / w.speed;
      RowPhaseError e = wavePhaseError<D>(row, Vec<D>(k * n), w.shear, w.speed, dt, integrator);
      if (e.total > worst.total) {
        worst = e;
        worst.pointsPerWavelength = w.speed / frequency / spacing;
        worst.wave = std::string(w.name) + (D > 1 ? (direction == 0 ? " along an axis" : " along the diagonal") : "");
      }
    }
  return worst;
}

template RowSpectrum rowSpectrum<1>(const MethodLatticeStencil<1>&, Real, int);
template RowSpectrum rowSpectrum<2>(const MethodLatticeStencil<2>&, Real, int);
template RowSpectrum rowSpectrum<3>(const MethodLatticeStencil<3>&, Real, int);
template RowPhaseError wavePhaseError<1>(const MethodLatticeStencil<1>&, const Vec<1>&, bool, Real, Real, IntegratorKind);
template RowPhaseError wavePhaseError<2>(const MethodLatticeStencil<2>&, const Vec<2>&, bool, Real, Real, IntegratorKind);
template RowPhaseError wavePhaseError<3>(const MethodLatticeStencil<3>&, const Vec<3>&, bool, Real, Real, IntegratorKind);
template RowPhaseError rowPhaseError<1>(const MethodLatticeStencil<1>&, const Material&, Real, Real, Real, IntegratorKind);
template RowPhaseError rowPhaseError<2>(const MethodLatticeStencil<2>&, const Material&, Real, Real, Real, IntegratorKind);
template RowPhaseError rowPhaseError<3>(const MethodLatticeStencil<3>&, const Material&, Real, Real, Real, IntegratorKind);

}  // namespace mfwave
