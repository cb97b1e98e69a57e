#include "spectra/JitteredCloud.hpp"

#include "numerics/RestModes.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "kernels/KernelFactory.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"
#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/BoxFace.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <complex>
#include <cmath>
#include <random>

namespace mfwave {

namespace {

using RowMatrix = Eigen::SparseMatrix<Real, Eigen::RowMajor, int>;

// The periodic cloud around one tile: the tile's sites first (cloud index = site index), then the
// copies of sites within `physicalMargin` of the tile (per axis), then, as ghosts that only complete
// kernel sums, those within a further `ghostMargin`. base[c] is the site cloud particle c copies.
// With `flagFaces`, the physical particles in the outermost spacing carry box-face flags, so that
// the very weak SPH treats them as the boundary rows they are (its consistent correction cannot
// complete an interior row there); no tile row reaches them.
template <int D>
struct TiledCloud {
  ParticleSet<D> particles;
  std::vector<Index> base;
};

template <int D>
TiledCloud<D> tiledCloud(int cells, Real jitter, std::uint64_t seed, Real physicalMargin, Real ghostMargin,
                         bool flagFaces) {
  Index sites = 1;
  for (int a = 0; a < D; ++a) sites *= cells;
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<Real> offset(-jitter, jitter);
  std::vector<Vec<D>> tile(static_cast<std::size_t>(sites));
  for (Index i = 0; i < sites; ++i) {
    Index rest = i;
    for (int a = 0; a < D; ++a) {
      tile[static_cast<std::size_t>(i)](a) = static_cast<Real>(rest % cells) + offset(random);
      rest /= cells;
    }
  }
  // Copies shifted by -2 .. 2 tiles per axis, sorted into physical and ghost by their distance
  // outside the tile's box [0, cells - 1]^D.
  TiledCloud<D> cloud;
  struct Copy {
    Vec<D> x;
    Index site;
    std::uint8_t faces;
  };
  std::vector<Copy> physical, ghosts;
  Index copies = 1;
  for (int a = 0; a < D; ++a) copies *= 5;
  for (Index copy = 0; copy < copies; ++copy) {
    Vec<D> shift;
    Index rest = copy;
    bool central = true;
    for (int a = 0; a < D; ++a) {
      shift(a) = static_cast<Real>((rest % 5 - 2) * cells);
      central = central && rest % 5 == 2;
      rest /= 5;
    }
    if (central) continue;
    for (Index i = 0; i < sites; ++i) {
      const Vec<D> x = tile[static_cast<std::size_t>(i)] + shift;
      Real outside = 0;
      std::uint8_t faces = 0;
      for (int a = 0; a < D; ++a) {
        outside = std::max({outside, -x(a), x(a) - (cells - 1)});
        if (flagFaces && -x(a) > physicalMargin - 1) faces |= faceBit(2 * a);
        if (flagFaces && x(a) - (cells - 1) > physicalMargin - 1) faces |= faceBit(2 * a + 1);
      }
      if (outside <= physicalMargin) physical.push_back({x, i, faces});
      else if (outside <= physicalMargin + ghostMargin) ghosts.push_back({x, i, 0});
    }
  }
  cloud.particles.reserve(sites + static_cast<Index>(physical.size() + ghosts.size()));
  for (Index i = 0; i < sites; ++i) {
    cloud.particles.add(tile[static_cast<std::size_t>(i)], 1.0);
    cloud.base.push_back(i);
  }
  for (const Copy& c : physical) {
    cloud.particles.add(c.x, 1.0, ParticleKind::Physical, c.faces);
    cloud.base.push_back(c.site);
  }
  for (const Copy& c : ghosts) {
    cloud.particles.add(c.x, 1.0, ParticleKind::Ghost);
    cloud.base.push_back(c.site);
  }
  return cloud;
}

// Folds the central rows (columns over the cloud's unknowns) onto the tile: column c D + q goes
// to base[c] D + q.
template <int D>
Eigen::MatrixXd fold(const RowMatrix& rows, const std::vector<Index>& base, Index sites) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(rows.rows(), sites * D);
  for (Index r = 0; r < rows.outerSize(); ++r)
    for (RowMatrix::InnerIterator it(rows, static_cast<int>(r)); it; ++it) {
      const Index c = it.col();
      out(r, base[static_cast<std::size_t>(c / D)] * D + c % D) += it.value();
    }
  return out;
}

RowMatrix centralRows(const SparseMatrix& matrix, Index rows) {
  return RowMatrix(matrix.topRows(static_cast<int>(rows)));
}

// The central rows of M a = A u for one method on the cloud (M empty: lumped identity).
struct CloudRows {
  RowMatrix acceleration, mass;
};

// What the spectrum needs from a method on the cloud: the operator folded onto the tile (M^-1 A
// of the periodic cloud, M empty: lumped identity) and the tile rows of A u - M a for the
// quadratic field (u, a) given over the cloud's physical particles.
struct CloudOperator {
  Eigen::MatrixXd acceleration, mass;
  Vector quadraticResidual;
};

template <int D>
CloudOperator foldedOperator(const CloudRows& rows, const std::vector<Index>& base, Index sites, const Vector& u,
                             const Vector& a) {
  CloudOperator out;
  out.acceleration = fold<D>(rows.acceleration, base, sites);
  const bool lumped = rows.mass.nonZeros() == 0;
  if (!lumped) out.mass = fold<D>(rows.mass, base, sites);
  out.quadraticResidual = lumped ? Vector(rows.acceleration * u - a.head(sites * D))
                                 : Vector(rows.acceleration * u - rows.mass * a);
  return out;
}

template <int D>
CloudRows veryWeakSphRows(const std::string& method, const LatticeMethodSettings& s, const ParticleSet<D>& cloud,
                             Index rows) {
  VeryWeakSphOptions options;
  options.material = s.material;
  if (method == "vwsph_consistent") options.variant = VeryWeakSphVariant::Consistent;
  const auto kernel = makeKernel(s.kernel, D, s.smoothingLengthRatio);
  const NeighbourList neighbours =
      buildNeighbourList(CellList<D>(cloud, kernel->supportRadius()), cloud.physicalCount());
  const VeryWeakSph<D> method_ = assembleVeryWeakSph(cloud, neighbours, *kernel, options);
  CloudRows out;
  out.acceleration = -centralRows(method_.system.stiffness(), rows);
  out.mass = centralRows(method_.system.mass(), rows);
  return out;
}

template <int D>
CloudRows collocationRows(const LatticeMethodSettings& s, const ParticleSet<D>& cloud, Index sites) {
  const ReproducingKernelShapeFunctions<D> shapes(cloud.coordinates(), s.rkOrder, s.rkSupportRatio);
  std::vector<Eigen::Triplet<Real>> a, m;
  for (Index i = 0; i < sites; ++i)
    collocationRowBlocks<D>(shapes, cloud.position(i), s.material, [&](Index node, Real psi, const Mat<D>& g) {
      for (int p = 0; p < D; ++p) {
        m.emplace_back(static_cast<int>(i * D + p), static_cast<int>(node * D + p), psi);
        for (int q = 0; q < D; ++q)
          a.emplace_back(static_cast<int>(i * D + p), static_cast<int>(node * D + q), g(p, q));
      }
    });
  CloudRows out;
  out.acceleration.resize(static_cast<int>(sites * D), static_cast<int>(cloud.physicalCount() * D));
  out.mass.resize(out.acceleration.rows(), out.acceleration.cols());
  out.acceleration.setFromTriplets(a.begin(), a.end());
  out.mass.setFromTriplets(m.begin(), m.end());
  return out;
}

// The updated-Lagrangian SPH linearised about rest has no matrix: its folded column for site s and
// component q is the response of the tile rows to s and all its copies moving together along q (a
// periodic velocity field), one rate evaluation per tile unknown instead of one per unknown of the
// whole cloud (RestModes.hpp); the quadratic field is one more direction.
template <int D>
CloudOperator updatedLagrangianOperator(const std::string& method, const LatticeMethodSettings& s,
                                        const ParticleSet<D>& cloud, const std::vector<Index>& base, Index sites,
                                        const Vector& u, const Vector& a) {
  UpdatedLagrangianSph<D> system(cloud, linearisedAboutRest(updatedLagrangianSphSettings(method, s)));
  const Vector rest = system.initialState(Vector());
  const Index physical = cloud.physicalCount();
  std::vector<Index> velocities, rows;
  for (Index i = 0; i < physical; ++i)
    for (int q = 0; q < D; ++q) velocities.push_back(system.layout().velocity(i, q));
  for (Index r = 0; r < sites * D; ++r) rows.push_back(r);
  std::vector<Eigen::Triplet<Real>> entries;
  for (Index i = 0; i < physical; ++i)
    for (int q = 0; q < D; ++q) {
      entries.emplace_back(static_cast<int>(i * D + q), static_cast<int>(base[static_cast<std::size_t>(i)] * D + q), 1.0);
      if (u(i * D + q) != 0) entries.emplace_back(static_cast<int>(i * D + q), static_cast<int>(sites * D), u(i * D + q));
    }
  SparseMatrix directions(static_cast<int>(physical * D), static_cast<int>(sites * D + 1));
  directions.setFromTriplets(entries.begin(), entries.end());
  const Eigen::MatrixXd products = restOperatorProducts(system, 0, rest, velocities, directions, rows);
  CloudOperator out;
  out.acceleration = products.leftCols(sites * D);
  out.quadraticResidual = products.col(sites * D) - a.head(sites * D);
  return out;
}

// How far a central row's coefficients reach (in dx): what the copies must cover.
Real dependencyReach(const std::string& method, const LatticeMethodSettings& s, int dimension) {
  if (method == "rkcm") return s.rkSupportRatio;
  // SPH: the row reads its neighbours' volumes, corrections or stress rates.
  return 2 * makeKernel(s.kernel, dimension, s.smoothingLengthRatio)->supportRadius();
}

template <int D>
Real closestPair(const ParticleSet<D>& cloud, Index sites) {
  Real closest = std::numeric_limits<Real>::infinity();
  for (Index i = 0; i < sites; ++i)
    for (Index j = 0; j < cloud.physicalCount(); ++j)
      if (j != i) closest = std::min(closest, (cloud.position(j) - cloud.position(i)).norm());
  return closest;
}

// Central difference on u'' = A u at 0.9 of the limit 2 / omega_max, from random displacements:
// the amplitude's growth over the run against the spectrum's prediction, the largest root of
// z^2 - (2 + dt^2 lambda) z + 1 = 0 over the eigenvalues, raised to the number of steps.
void confirmByRun(const Eigen::MatrixXd& A, const Eigen::VectorXcd& lambda, Real omegaMax, long steps,
                  std::uint64_t seed, JitteredCloudReport& report) {
  const Real dt = 0.9 * 2 / omegaMax;
  Real largestRoot = 1;
  for (Index k = 0; k < lambda.size(); ++k) {
    const std::complex<double> b = 2.0 + dt * dt * lambda(k);
    const std::complex<double> root = std::sqrt(b * b - 4.0);
    largestRoot = std::max({largestRoot, std::abs((b + root) / 2.0), std::abs((b - root) / 2.0)});
  }
  report.predictedLogGrowth = static_cast<Real>(steps) * std::log(largestRoot);
  std::mt19937_64 random(seed + 1000);
  std::uniform_real_distribution<Real> uniform(-1, 1);
  Vector previous(A.rows()), current(A.rows());
  for (Index i = 0; i < previous.size(); ++i) previous(i) = uniform(random);
  current = previous + 0.5 * dt * dt * (A * previous);  // from rest
  const Real initial = previous.cwiseAbs().maxCoeff();
  Real largest = initial;
  for (long n = 1; n < steps; ++n) {
    Vector next = 2 * current - previous + dt * dt * (A * current);
    previous.swap(current);
    current.swap(next);
    largest = std::max(largest, current.cwiseAbs().maxCoeff());
    if (!std::isfinite(largest) || largest > 1e150) break;
  }
  report.measuredLogGrowth = std::log(largest / initial);
  // A mode predicted to grow by e^12 or more must show at least half of it (random data give it
  // about 1 / sqrt(unknowns) of the start) or pass 1e150; one predicted below e^0.05 must stay
  // within 100 x.
  if (report.predictedLogGrowth >= 12)
    report.confirmation = report.measuredLogGrowth >= std::min(report.predictedLogGrowth / 2, Real(300))
                              ? "grew as predicted"
                              : "CONTRADICTS: did not grow";
  else if (report.predictedLogGrowth <= 0.05)
    report.confirmation = report.measuredLogGrowth <= std::log(100.0) ? "bounded as predicted"
                                                                       : "CONTRADICTS: grew";
  else
    report.confirmation = "too slow to tell";
}

}  // namespace

const std::vector<std::string>& jitteredCloudMethodNames() {
  static const std::vector<std::string> names = {"vwsph_published", "vwsph_consistent", "rkcm", "ulsph",
                                                 "ulsph_corrected"};
  return names;
}

bool jitteredCloudMethodAvailable(const std::string& method) {
  const auto& names = jitteredCloudMethodNames();
  return std::find(names.begin(), names.end(), method) != names.end();
}

template <int D>
JitteredCloudReport jitteredCloudSpectrum(const std::string& method, const LatticeMethodSettings& settings, int cells,
                                          Real jitter, std::uint64_t seed, long confirmSteps) {
  if (!jitteredCloudMethodAvailable(method)) {
    std::string offered;
    for (const std::string& name : jitteredCloudMethodNames()) offered += (offered.empty() ? "" : ", ") + name;
    throw InputError("method", "'" + method + "' is not assembled on irregular clouds here (" + offered + ")");
  }
  if (!(jitter >= 0 && jitter < 0.5)) throw InputError("jitter", "must be in [0, 0.5) of the spacing");
  if (cells < 4 || cells > 64) throw InputError("cells", "must be 4 to 64 per axis");
  const Stopwatch clock;
  JitteredCloudReport report;
  report.cells = cells;
  Index sites = 1;
  for (int a = 0; a < D; ++a) sites *= cells;
  report.unknowns = sites * D;
  const bool finiteDifferenced = method.rfind("ulsph", 0) == 0;
  // The noise of the eigenvalues: rounding for assembled matrices, the central difference of
  // restOperator for the updated-Lagrangian rows (RestModes.hpp).
  report.tolerance = finiteDifferenced ? 1e-6 : 1e-9;
  const Real reach = dependencyReach(method, settings, D);
  if (reach + 2 * jitter > cells)
    throw InputError("cells", "a row depends on particles up to " + std::to_string(reach) +
                                  " dx away: the tile needs more than " + std::to_string(cells) + " cells per axis");
  try {
    // Physical copies as far as a central row reaches (and one spacing more); the very weak SPH's
    // ghosts beyond them (one support, reach / 2, and a spacing) keep its edge rows (never used)
    // from failing, as ghost layers do on a block.
    const bool veryWeak = method.rfind("vwsph", 0) == 0;
    const TiledCloud<D> tiled = tiledCloud<D>(cells, jitter, seed, reach + 1, veryWeak ? reach / 2 + 1 : 0, veryWeak);
    const ParticleSet<D>& cloud = tiled.particles;
    report.closestPair = closestPair<D>(cloud, sites);
    // Consistency: the quadratic field u = x^2 / 2 e_x (about the tile's centre) has the exact
    // acceleration c_p^2 e_x everywhere.
    const Real cp2 = settings.material.pWaveSpeed() * settings.material.pWaveSpeed();
    const Index columns = cloud.physicalCount();
    Vector u = Vector::Zero(columns * D), a = Vector::Zero(columns * D);
    for (Index i = 0; i < columns; ++i) {
      const Real x = cloud.position(i)(0) - 0.5 * (cells - 1);
      u(i * D) = 0.5 * x * x;
      a(i * D) = cp2;
    }
    const CloudOperator op =
        method == "rkcm" ? foldedOperator<D>(collocationRows<D>(settings, cloud, sites), tiled.base, sites, u, a)
        : veryWeak ? foldedOperator<D>(veryWeakSphRows<D>(method, settings, cloud, sites * D), tiled.base, sites, u, a)
                   : updatedLagrangianOperator<D>(method, settings, cloud, tiled.base, sites, u, a);
    report.quadraticResidual = op.quadraticResidual.cwiseAbs().maxCoeff() / cp2;

    // The spectrum of the periodic cloud: M^-1 A folded, lambda = -omega^2.
    Eigen::MatrixXd A = op.acceleration;
    if (op.mass.size() > 0) A = Eigen::PartialPivLU<Eigen::MatrixXd>(op.mass).solve(A);
    const GeneralEigenpairs eigen = generalEigenpairs(A, true, "jittered cloud spectrum");
    const Eigen::VectorXcd& lambda = eigen.values;
    const Real largest = lambda.cwiseAbs().maxCoeff();
    // The box's lowest modes: k = 2 pi / (cells dx) along each axis, cos and sin; shear (D - 1
    // polarisations; 1-D: the only wave) sits below every P mode for any Poisson's ratio.
    const Real exact = (D == 1 ? settings.material.pWaveSpeed() : settings.material.sWaveSpeed()) * 2 * kPi / cells;
    Real largestOmega2 = 0, smallestOmega2 = 0, largestImaginary = 0;
    Index low = 0;
    for (Index k = 0; k < lambda.size(); ++k) {
      largestImaginary = std::max(largestImaginary, std::abs(lambda(k).imag()));
      const Real w2 = -lambda(k).real();
      largestOmega2 = std::max(largestOmega2, w2);
      if (std::abs(lambda(k)) > report.tolerance * largest) smallestOmega2 = std::min(smallestOmega2, w2);
      if (w2 < 0.25 * exact * exact) ++low;
    }
    report.smallestOverLargest = smallestOmega2 / largestOmega2;
    report.imaginaryRatio = largestImaginary / largest;
    report.courant = 2 / std::sqrt(largestOmega2) * settings.material.pWaveSpeed();
    report.spuriousLowModes = std::max<Index>(0, low - D);
    // Each exact lowest mode is matched to the eigenvector it overlaps most (spurious low modes of
    // a method would otherwise pass for it), and that eigenvalue's frequency is compared.
    const Eigen::MatrixXcd& vectors = eigen.vectors;
    for (int axis = 0; axis < D; ++axis)
      for (int polarisation = 0; polarisation < D; ++polarisation) {
        if (D > 1 && polarisation == axis) continue;
        for (int phase = 0; phase < 2; ++phase) {
          Eigen::VectorXcd mode = Eigen::VectorXcd::Zero(sites * D);
          for (Index i = 0; i < sites; ++i) {
            const Real theta = 2 * kPi / cells * cloud.position(i)(axis);
            mode(i * D + polarisation) = phase == 0 ? std::cos(theta) : std::sin(theta);
          }
          Index best = 0;
          (vectors.adjoint() * mode).cwiseAbs().maxCoeff(&best);
          const Real w2 = -lambda(best).real();
          report.lowestModeError =
              std::max(report.lowestModeError, w2 > 0 ? std::abs(std::sqrt(w2) / exact - 1) : Real(1));
        }
      }
    if (report.smallestOverLargest < -report.tolerance || report.imaginaryRatio > report.tolerance)
      report.status = "growing";
    if (confirmSteps > 0) confirmByRun(A, lambda, std::sqrt(largestOmega2), confirmSteps, seed, report);
  } catch (const Error& e) {
    report.status = std::string("fails: ") + e.what();
  }
  report.seconds = clock.seconds();
  return report;
}

template JitteredCloudReport jitteredCloudSpectrum<1>(const std::string&, const LatticeMethodSettings&, int, Real,
                                                      std::uint64_t, long);
template JitteredCloudReport jitteredCloudSpectrum<2>(const std::string&, const LatticeMethodSettings&, int, Real,
                                                      std::uint64_t, long);
template JitteredCloudReport jitteredCloudSpectrum<3>(const std::string&, const LatticeMethodSettings&, int, Real,
                                                      std::uint64_t, long);

}  // namespace mfwave
