#include "numerics/SimulatedDispersion.hpp"

#include "core/Error.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <string>

namespace mfwave {

namespace {

constexpr Real kNoFrequency = std::numeric_limits<Real>::quiet_NaN();

// A unit vector normal to n on which the S part is read: (-n_y, n_x) in 2-D, (0, 1, 0) on the
// 3-D axis and (1, -1, 0) / sqrt(2) on the 3-D diagonal.
template <int D>
Vec<D> transverse(LatticeDirection direction) {
  Vec<D> s = Vec<D>::Zero();
  if constexpr (D == 2) {
    const Vec<D> n = latticeDirectionVector<D>(direction);
    s << -n(1), n(0);
  } else if constexpr (D == 3) {
    if (direction == LatticeDirection::Axis)
      s(1) = 1;
    else
      s << 1 / std::sqrt(2.0), -1 / std::sqrt(2.0), 0;
  }
  return s;
}

// |sum_n w_n s_n exp(-i omega n dt)| at the frequency `bin` (in FFT bins, fractional allowed).
Real windowedMagnitude(const ComplexVector& windowed, Real bin) {
  const Real theta = -2 * kPi * bin / static_cast<Real>(windowed.size());
  std::complex<Real> sum = 0;
  const std::complex<Real> rotation(std::cos(theta), std::sin(theta));
  std::complex<Real> phase = 1;
  for (std::size_t n = 0; n < windowed.size(); ++n) {
    sum += windowed[n] * phase;
    phase *= rotation;
    if (n % 256 == 255) phase /= std::abs(phase);  // keep the recurrence on the unit circle
  }
  return std::abs(sum);
}

// The peak frequency of a signal in FFT bins, or NaN when it lies within edgeBins of 0 or Nyquist.
Real peakBin(const ComplexVector& signal, int edgeBins) {
  const std::size_t T = signal.size();
  ComplexVector windowed(T);
  for (std::size_t n = 0; n < T; ++n) {
    const Real w = 0.5 - 0.5 * std::cos(2 * kPi * static_cast<Real>(n) / static_cast<Real>(T));
    windowed[n] = w * signal[n];
  }
  ComplexVector spectrum = windowed;
  forwardFourierTransform(spectrum, 1, static_cast<int>(T));
  std::size_t best = 1;
  for (std::size_t b = 1; b <= T / 2; ++b)
    if (std::abs(spectrum[b]) > std::abs(spectrum[best])) best = b;
  if (best < static_cast<std::size_t>(edgeBins) || best + static_cast<std::size_t>(edgeBins) > T / 2) return kNoFrequency;
  // Golden-section search for the maximum of the continuous transform within one bin either side.
  const Real golden = (std::sqrt(5.0) - 1) / 2;
  Real a = static_cast<Real>(best) - 1, b = static_cast<Real>(best) + 1;
  Real x1 = b - golden * (b - a), x2 = a + golden * (b - a);
  Real f1 = windowedMagnitude(windowed, x1), f2 = windowedMagnitude(windowed, x2);
  while (b - a > 1e-9) {
    if (f1 > f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - golden * (b - a);
      f1 = windowedMagnitude(windowed, x1);
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + golden * (b - a);
      f2 = windowedMagnitude(windowed, x2);
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

Real integratorFrequency(const std::string& integrator, Real omega, Real dt) {
  const Real half = omega * dt / 2;
  if (integrator == "central_difference" || integrator == "leapfrog")
    return half <= 1 ? 2 * std::asin(half) / dt : kNoFrequency;
  if (integrator == "newmark") return 2 * std::atan(half) / dt;
  return kNoFrequency;
}

template <int D>
SimulatedDispersionResult simulateDispersion(const PeriodicLatticeOperator<D>& op,
                                             const DispersionSpectrum<D>& spectrum,
                                             const SimulatedDispersionOptions& options) {
  if (!op.lumped())
    throw InputError("mass", "the simulated spectrum integrates u'' = A u explicitly; a collocation mass is not lumped");
  if (options.steps < 64) throw InputError("steps", "need at least 64 recorded steps, got " + std::to_string(options.steps));
  const bool explicitLimit = options.integrator == "central_difference" || options.integrator == "leapfrog";
  if (!(options.stepFraction > 0) || (explicitLimit && options.stepFraction > 1))
    throw InputError("step_fraction", "must be in (0, 1] of the central-difference limit, got " +
                                          std::to_string(options.stepFraction));
  if (spectrum.cells() != op.cells || spectrum.components() != op.components())
    throw InputError("spectrum", "was computed for another lattice");

  const int c = op.components();
  const typename DispersionSpectrum<D>::Extremes extremes = spectrum.extremes();
  if (!(extremes.largestOmegaSquared > 0)) throw InputError("operator", "has no positive omega^2: nothing oscillates");
  SimulatedDispersionResult result;
  result.criticalStep = 2 / std::sqrt(extremes.largestOmegaSquared);
  result.timeStep = options.stepFraction * result.criticalStep;
  result.steps = options.steps;
  result.frequencyResolution = 2 * kPi / (options.steps * result.timeStep);

  // M u'' + K u = 0 with M = I, K = -A.
  const Index n = op.size();
  LinearSecondOrderSystem system = periodicLatticeSystem(op);
  Vector u0 = Vector::Zero(n), v0 = Vector::Zero(n);
  for (int q = 0; q < c; ++q) u0(q) = std::pow(0.5, q);
  std::unique_ptr<SecondOrderIntegrator> integrator = makeSecondOrderIntegrator(options.integrator);
  integrator->initialise(system, 0, u0, v0, result.timeStep);

  const int samples = op.cells / 2;
  const Vec<D> along = latticeDirectionVector<D>(options.direction);
  const Vec<D> across = transverse<D>(options.direction);
  std::vector<Polarisation> polarisations;
  if (c == 1)
    polarisations = {Polarisation::Scalar};
  else if (D == 1)
    polarisations = {Polarisation::P};
  else
    polarisations = {Polarisation::P, Polarisation::S};
  // signals[polarisation][sample j - 1][step]
  std::vector<std::vector<ComplexVector>> signals(
      polarisations.size(), std::vector<ComplexVector>(static_cast<std::size_t>(samples),
                                                       ComplexVector(static_cast<std::size_t>(options.steps))));
  std::vector<ComplexVector> planes(static_cast<std::size_t>(c), ComplexVector(static_cast<std::size_t>(op.nodes())));
  std::vector<std::size_t> lineAt(static_cast<std::size_t>(samples));
  for (int j = 1; j <= samples; ++j)
    lineAt[static_cast<std::size_t>(j - 1)] =
        static_cast<std::size_t>(periodicNode<D>(lineIndex<D>(options.direction, j), op.cells));
  for (int step = 0; step < options.steps; ++step) {
    if (step > 0) integrator->step();
    const Vector& u = integrator->state().displacement;
    if (!u.allFinite())
      throw Error("simulateDispersion: the field is not finite at step " + std::to_string(step) + " (t = " +
                  std::to_string(integrator->time()) + "); the step is beyond the integrator's limit");
    for (int q = 0; q < c; ++q) {
      ComplexVector& plane = planes[static_cast<std::size_t>(q)];
      for (Index node = 0; node < op.nodes(); ++node) plane[static_cast<std::size_t>(node)] = u(node * c + q);
      forwardFourierTransform(plane, D, op.cells);
    }
    for (std::size_t p = 0; p < polarisations.size(); ++p)
      for (int j = 0; j < samples; ++j) {
        std::complex<Real> value = 0;
        const std::size_t at = lineAt[static_cast<std::size_t>(j)];
        for (int q = 0; q < c; ++q) {
          const Real weight = polarisations[p] == Polarisation::S ? across(q)
                              : polarisations[p] == Polarisation::P ? along(q)
                                                                     : 1;
          value += weight * planes[static_cast<std::size_t>(q)][at];
        }
        signals[p][static_cast<std::size_t>(j)][static_cast<std::size_t>(step)] = value;
      }
  }

  for (std::size_t p = 0; p < polarisations.size(); ++p)
    for (int j = 1; j <= samples; ++j) {
      const Real bin = peakBin(signals[p][static_cast<std::size_t>(j - 1)], options.edgeBins);
      if (!std::isfinite(bin)) continue;
      const std::array<int, D> m = lineIndex<D>(options.direction, j);
      const std::vector<LatticeMode> modes = spectrum.modes(m, along);
      SimulatedDispersionPoint point;
      point.kdx = spectrum.wavevector(m).norm() * op.spacing;
      point.polarisation = polarisations[p];
      point.omegaSymbol = modes[polarisationBranch(modes, polarisations[p])].omega;
      point.omegaExpected = integratorFrequency(options.integrator, point.omegaSymbol, result.timeStep);
      point.omegaMeasured = bin * result.frequencyResolution;
      const Real reference = std::isfinite(point.omegaExpected) ? point.omegaExpected : point.omegaSymbol;
      point.relativeError = std::abs(point.omegaMeasured - reference) / reference;
      result.largestError = std::max(result.largestError, point.relativeError);
      result.points.push_back(point);
    }
  return result;
}

template SimulatedDispersionResult simulateDispersion<1>(const PeriodicLatticeOperator<1>&,
                                                         const DispersionSpectrum<1>&,
                                                         const SimulatedDispersionOptions&);
template SimulatedDispersionResult simulateDispersion<2>(const PeriodicLatticeOperator<2>&,
                                                         const DispersionSpectrum<2>&,
                                                         const SimulatedDispersionOptions&);
template SimulatedDispersionResult simulateDispersion<3>(const PeriodicLatticeOperator<3>&,
                                                         const DispersionSpectrum<3>&,
                                                         const SimulatedDispersionOptions&);

}  // namespace mfwave
