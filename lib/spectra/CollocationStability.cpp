#include "spectra/CollocationStability.hpp"

#include "core/Material.hpp"
#include "methods/collocation/CollocationSystem.hpp"
#include "methods/collocation/ConstrainedCollocationSystem.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include "core/Error.hpp"
#include "integrators/CentralDifference.hpp"
#include "methods/collocation/ShapeFunctionMatrix.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>

namespace mfwave {

namespace {


Stencil stencilOf(const Eigen::VectorXd& entries, Index centre, Real dropBelow) {
  Stencil s;
  const Real largest = entries.cwiseAbs().maxCoeff();
  for (Index j = 0; j < entries.size(); ++j) {
    const Real w = entries[j];
    if (w == 0 || std::abs(w) <= dropBelow * largest) continue;
    s.offsets.push_back(static_cast<int>(j - centre));
    s.weights.push_back(w);
  }
  return s;
}

Real realD(const Stencil& g, Real theta) { return g.symbol(theta).real(); }

}  // namespace

std::complex<Real> Stencil::symbol(Real theta) const {
  std::complex<Real> sum = 0;
  for (std::size_t q = 0; q < offsets.size(); ++q)
    sum += weights[q] * std::polar(Real(1), offsets[q] * theta);
  return sum;
}

Real Stencil::cosineSum(Real theta) const {
  Real sum = 0;
  for (std::size_t q = 0; q < offsets.size(); ++q) sum += weights[q] * std::cos(offsets[q] * theta);
  return sum;
}

Real Stencil::cosineSumDerivative(Real theta) const {
  Real sum = 0;
  for (std::size_t q = 0; q < offsets.size(); ++q) sum -= weights[q] * offsets[q] * std::sin(offsets[q] * theta);
  return sum;
}

Stencil Stencil::fromRow(const Eigen::MatrixXd& matrix, Index centre, Real dropBelow) {
  return stencilOf(matrix.row(centre).transpose(), centre, dropBelow);
}

Stencil Stencil::fromColumn(const Eigen::MatrixXd& matrix, Index centre, Real dropBelow) {
  return stencilOf(matrix.col(centre), centre, dropBelow);
}

Coordinates<1> uniformLine(Index count, Real spacing) {
  if (count < 2) throw InputError("study.nodes", "a node line needs at least 2 nodes");
  if (!(spacing > 0) || !std::isfinite(spacing)) throw InputError("study.spacing", "must be positive and finite");
  Coordinates<1> nodes;
  nodes[0].resize(static_cast<std::size_t>(count));
  for (Index i = 0; i < count; ++i) nodes[0][static_cast<std::size_t>(i)] = static_cast<Real>(i) * spacing;
  return nodes;
}

CollocationRows collocationRows(const ShapeFunctions<1>& shapes, const Coordinates<1>& nodes, Index centre,
                                Real spacing) {
  const auto points = pointsOf<1>(nodes);
  const Eigen::MatrixXd m = denseShapeFunctionMatrix(shapes, points, ShapeDerivative::value());
  const Eigen::MatrixXd a = denseShapeFunctionMatrix(shapes, points, ShapeDerivative::hessian(0, 0));
  // G = A M^{-1}: solve M^T G^T = A^T.
  const Eigen::MatrixXd g = m.transpose().partialPivLu().solve(a.transpose()).transpose();
  CollocationRows rows;
  rows.spacing = spacing;
  rows.mass = Stencil::fromRow(m, centre);
  rows.laplacian = Stencil::fromRow(a, centre);
  rows.amplification = Stencil::fromRow(g, centre);
  rows.massColumn = Stencil::fromColumn(m, centre);
  rows.stiffnessColumn = Stencil::fromColumn(-a, centre);
  return rows;
}

VonNeumannResult vonNeumannStability(const Stencil& amplification, Real spacing, Real waveSpeed, int samples,
                                     Real positiveTolerance) {
  if (samples < 8) throw InputError("study.samples", "at least 8 wavenumbers");
  VonNeumannResult r;
  r.dMin = std::numeric_limits<Real>::infinity();
  r.dMax = -std::numeric_limits<Real>::infinity();
  int argMin = 1;
  for (int s = 1; s <= samples; ++s) {
    const Real theta = kPi * s / samples;
    const std::complex<Real> d = amplification.symbol(theta);
    r.maxImaginary = std::max(r.maxImaginary, std::abs(d.imag()));
    if (d.real() < r.dMin) {
      r.dMin = d.real();
      argMin = s;
    }
    if (d.real() > r.dMax) {
      r.dMax = d.real();
      r.khAtMax = theta;
    }
  }
  // Golden-section refinement of the minimum on the bracket around the best sample.
  Real lo = kPi * std::max(argMin - 1, 0) / samples, hi = kPi * std::min(argMin + 1, samples) / samples;
  const Real ratio = (std::sqrt(5.0) - 1) / 2;
  Real x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  Real f1 = realD(amplification, x1), f2 = realD(amplification, x2);
  for (int it = 0; it < 100 && hi - lo > 1e-14; ++it) {
    if (f1 < f2) {
      hi = x2; x2 = x1; f2 = f1; x1 = hi - ratio * (hi - lo); f1 = realD(amplification, x1);
    } else {
      lo = x1; x1 = x2; f1 = f2; x2 = lo + ratio * (hi - lo); f2 = realD(amplification, x2);
    }
  }
  r.khAtMin = kPi * argMin / samples;
  const Real theta = 0.5 * (lo + hi);
  if (realD(amplification, theta) < r.dMin) {
    r.dMin = realD(amplification, theta);
    r.khAtMin = theta;
  }
  r.unconditionallyUnstable = !(r.dMin < 0) || r.dMax > positiveTolerance * std::abs(r.dMin);
  r.criticalStep = r.unconditionallyUnstable ? 0 : std::sqrt(-4 / r.dMin) / waveSpeed;
  (void)spacing;
  return r;
}

Real phaseSpeed(const Stencil& stiffness, const Stencil& mass, Real kh, Real spacing) {
  const Real ratio = stiffness.cosineSum(kh) / mass.cosineSum(kh);  // omega^2 / c^2
  if (ratio < 0) return std::numeric_limits<Real>::quiet_NaN();
  return std::sqrt(ratio) * spacing / kh;
}

Real groupSpeed(const Stencil& stiffness, const Stencil& mass, Real kh, Real spacing) {
  // w(theta) = omega / c = sqrt(K(theta) / M(theta)); d omega / dk / c = h dw/dtheta.
  const Real k = stiffness.cosineSum(kh), m = mass.cosineSum(kh);
  const Real ratio = k / m;
  if (!(ratio > 0)) return std::numeric_limits<Real>::quiet_NaN();
  const Real dRatio = (stiffness.cosineSumDerivative(kh) * m - k * mass.cosineSumDerivative(kh)) / (m * m);
  return spacing * dRatio / (2 * std::sqrt(ratio));
}

Real BarProblem::waveSpeed() const { return std::sqrt(modulus / density); }

Eigen::MatrixXd constrainedBarStiffness(const ShapeFunctions<1>& shapes, const BarProblem& bar) {
  if (bar.nodes < 4) throw InputError("study.nodes", "the bar needs at least 4 nodes");
  if (shapes.nodeCount() != bar.nodes)
    throw InputError("study.nodes", "the shape functions must be built on the bar's nodes");
  // The bar's constrained system as the bar1d study assembles it: interior rows, u(0) = 0 and
  // E u_x(L) = 0 as constraints (ConstrainedCollocationSystem::denseStiffness).
  const Material material = Material::fromYoung(bar.modulus, 0, bar.density);
  const Coordinates<1> nodes = uniformLine(bar.nodes, bar.spacing());
  return ConstrainedCollocationSystem(assembleCollocation<1>(shapes, fixedFreeBarPoints(nodes), material))
      .denseStiffness();
}

std::string EigenvalueStability::verdict() const {
  std::ostringstream s;
  s.precision(4);
  if (unconditionallyUnstable) {
    if (maxImaginaryRatio > 0)
      s << "unconditionally unstable (complex pair, growth rate " << growthRate << " 1/s)";
    else
      s << "unconditionally unstable (negative eigenvalue, growth rate " << growthRate << " 1/s)";
  } else {
    s << "dt_crit = " << criticalStep;
  }
  return s.str();
}

EigenvalueStability eigenvalueStability(const Eigen::MatrixXd& stiffness, Real imaginaryTolerance) {
  const Eigen::VectorXcd lambda = generalEigenvalues(stiffness, "eigenvalueStability");
  EigenvalueStability r;
  const Real largest = lambda.cwiseAbs().maxCoeff();
  r.largestModulus = largest;
  r.lambdaMax = -std::numeric_limits<Real>::infinity();
  r.lambdaMinReal = std::numeric_limits<Real>::infinity();
  for (Index i = 0; i < lambda.size(); ++i) {
    r.lambdaMax = std::max(r.lambdaMax, lambda[i].real());
    r.lambdaMinReal = std::min(r.lambdaMinReal, lambda[i].real());
    r.maxImaginaryRatio = std::max(r.maxImaginaryRatio, std::abs(lambda[i].imag()) / largest);
    r.growthRate = std::max(r.growthRate, std::abs(std::sqrt(lambda[i]).imag()));
  }
  const bool complexPair = r.maxImaginaryRatio > imaginaryTolerance;
  const bool negative = r.lambdaMinReal < -imaginaryTolerance * largest;
  r.unconditionallyUnstable = complexPair || negative;
  if (!complexPair) r.maxImaginaryRatio = 0;
  if (!r.unconditionallyUnstable) r.growthRate = 0;
  r.criticalStep = r.unconditionallyUnstable ? 0 : 2 / std::sqrt(r.lambdaMax);
  return r;
}

BoundedRun runCentralDifference(const Eigen::MatrixXd& stiffness, Real dt, long minSteps, Real horizon,
                                Real growthLimit, std::uint32_t seed) {
  const Index n = stiffness.rows();
  SparseMatrix mass(n, n);
  mass.setIdentity();
  LinearSecondOrderSystem system(mass, SparseMatrix(), stiffness.sparseView());
  std::mt19937 generator(seed);
  std::uniform_real_distribution<Real> uniform(-1, 1);
  Vector u0(n), v0(n);
  for (Index i = 0; i < n; ++i) u0[i] = uniform(generator);
  for (Index i = 0; i < n; ++i) v0[i] = uniform(generator);
  CentralDifference integrator;
  integrator.initialise(system, 0, u0, v0, dt);
  StabilityMonitorOptions options;
  // Velocities of the highest stable mode reach omega_max |u| ~ 2 / dt: scale the limit with it.
  options.absoluteLimit = growthLimit * std::max<Real>(1, 2 / dt);
  StabilityMonitor monitor(options);
  TimeLoop loop;
  loop.add(monitor);
  const long steps = std::max(minSteps, static_cast<long>(std::ceil(horizon / dt)));
  BoundedRun run;
  try {
    run.steps = loop.run(integrator, static_cast<Real>(steps) * dt).steps;
  } catch (const InstabilityError& e) {
    run.bounded = false;
    run.steps = e.step();
    run.message = e.what();
  }
  return run;
}

BisectionResult bisectCriticalStep(const Eigen::MatrixXd& stiffness, Real guess, const BisectionOptions& options) {
  if (!(guess > 0)) throw InputError("study.guess", "the starting step must be positive");
  const Real horizon = options.horizon > 0 ? options.horizon : static_cast<Real>(options.minSteps) * guess;
  BisectionResult r;
  auto bounded = [&](Real dt) {
    ++r.runs;
    return runCentralDifference(stiffness, dt, options.minSteps, horizon, options.growthLimit).bounded;
  };
  Real stable = 0, unstable = 0;
  if (bounded(guess)) {
    stable = guess;
    unstable = guess * 1.25;
    while (bounded(unstable)) {
      stable = unstable;
      unstable *= 1.25;
    }
  } else {
    unstable = guess;
    stable = guess * 0.8;
    while (!bounded(stable)) {
      unstable = stable;
      stable *= 0.8;
      if (stable < options.smallestFraction * guess) {
        r.unconditionallyUnstable = true;
        r.smallestTried = unstable;
        return r;
      }
    }
  }
  while (unstable - stable > options.relativeTolerance * stable) {
    const Real mid = 0.5 * (stable + unstable);
    (bounded(mid) ? stable : unstable) = mid;
  }
  r.criticalStep = stable;
  r.smallestTried = stable;
  return r;
}

}  // namespace mfwave
