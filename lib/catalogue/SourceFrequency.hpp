#pragma once
// The dominant frequency of a scene's sources, for the plan's points per wavelength and phase error.
//
// A Ricker wavelet's is its peak frequency (the maximum of its spectrum, the seismologists'
// convention). For any other history f(t) (triangle, ramp, table) it is the maximum of the load
// rate's amplitude spectrum |R(nu)| = 2 pi nu |F(nu)|, the frequencies a velocity probe sees
// (Ding-Long-Wu's triangle on (0, 2): 0.371 Hz); when that maximum sits at nu -> 0 (a ramp: the
// rate is a box), the frequency where |R| has fallen to half its maximum. F is computed by
// quadrature of f on [0, min(end time, quiet time)].

#include "io/scene/Scene.hpp"

#include <string>

namespace mfwave {

struct SourceFrequency {
  bool found = false;       // false: the scene has no time-dependent source (initial conditions only)
  Real frequency = 0;       // Hz, the largest of the sources' dominant frequencies
  std::string source;       // which key gives it, e.g. "load[0].time_function"
  std::string rule;         // "Ricker peak frequency" or "peak of the load rate's spectrum"
};

// The dominant frequency of one history over [0, endTime].
Real dominantFrequency(const TimeFunction& f, Real endTime, std::string* rule = nullptr);

// Over the scene's loads and time-dependent boundary values.
SourceFrequency sceneSourceFrequency(const Scene& scene);

}  // namespace mfwave
