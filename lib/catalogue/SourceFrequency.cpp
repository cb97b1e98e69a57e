#include "catalogue/SourceFrequency.hpp"

#include "numerics/FourierTransform.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mfwave {

Real dominantFrequency(const TimeFunction& f, Real endTime, std::string* rule) {
  if (f.kind() == TimeFunction::Kind::Constant) return 0;
  if (f.kind() == TimeFunction::Kind::Ricker) {
    if (rule) *rule = "Ricker peak frequency";
    return f.parameters().at(0);  // ricker(peak_frequency, delay, amplitude)
  }
  if (rule) *rule = "peak of the load rate's amplitude spectrum";
  const Real quiet = f.quietAfter();
  const Real span = std::isfinite(quiet) ? std::min(std::max(quiet, Real(0)), endTime) : endTime;
  if (!(span > 0)) return 0;
  // Samples of f, its rate by differences, and |R(nu)| on nu = j / (8 span) up to the sampling's
  // Nyquist frequency / 4: the FFT of the rate padded with zeros to 8 n points resolves the peak.
  const int n = 2048, padded = 8 * n;
  const Real dt = span / n;
  ComplexVector rate(static_cast<std::size_t>(padded), 0);
  for (int i = 0; i < n; ++i) rate[static_cast<std::size_t>(i)] = (f((i + 1) * dt) - f(i * dt)) / dt;
  forwardFourierTransform(rate, 1, padded);
  const Real dnu = 1 / (8 * span);
  const int frequencies = static_cast<int>(std::floor(0.25 / (2 * dt) / dnu));
  std::vector<Real> amplitude(static_cast<std::size_t>(frequencies + 1));
  for (std::size_t j = 0; j < amplitude.size(); ++j) amplitude[j] = std::abs(rate[j]) * dt;
  const auto peak = std::max_element(amplitude.begin(), amplitude.end());
  const std::size_t at = static_cast<std::size_t>(peak - amplitude.begin());
  if (at > 0) {
    // Parabolic refinement of the peak between its neighbours.
    if (at + 1 < amplitude.size()) {
      const Real a = amplitude[at - 1], b = amplitude[at], c = amplitude[at + 1];
      const Real shift = (a - 2 * b + c) != 0 ? 0.5 * (a - c) / (a - 2 * b + c) : 0;
      return (static_cast<Real>(at) + shift) * dnu;
    }
    return static_cast<Real>(at) * dnu;
  }
  // The maximum at nu -> 0: where the spectrum has fallen to half of it.
  if (rule) *rule = "half-maximum of the load rate's amplitude spectrum";
  for (std::size_t j = 1; j < amplitude.size(); ++j)
    if (amplitude[j] <= 0.5 * *peak) return static_cast<Real>(j) * dnu;
  return static_cast<Real>(amplitude.size() - 1) * dnu;
}

SourceFrequency sceneSourceFrequency(const Scene& scene) {
  SourceFrequency out;
  const Real end = scene.integrator.endTime;
  const auto consider = [&](const TimeFunction& f, const std::string& key) {
    std::string rule;
    const Real nu = dominantFrequency(f, end, &rule);
    if (nu > out.frequency) {
      out.found = true;
      out.frequency = nu;
      out.source = key;
      out.rule = rule;
    }
  };
  for (std::size_t i = 0; i < scene.loads.size(); ++i)
    consider(scene.loads[i].timeFunction, "load[" + std::to_string(i) + "].time_function");
  for (std::size_t i = 0; i < scene.boundaries.size(); ++i) {
    const BoundaryType t = scene.boundaries[i].type;
    if (t == BoundaryType::Traction || t == BoundaryType::Displacement)
      consider(scene.boundaries[i].timeFunction, "boundary[" + std::to_string(i) + "].time_function");
  }
  return out;
}

}  // namespace mfwave
