#pragma once
// One case of the bar1d study (Luo, Liu and Huang): the fixed-free bar at one resolution by
// strong-form collocation (reproducing kernel or radial basis) and a constrained integrator, its
// errors against the exact solution by characteristics (FixedFreeBarImpact). Before stepping, the
// operator's whole spectrum: growing modes are refused, the step is checked against its limit.

#include "io/run/StudyCases.hpp"
#include "io/scene/Scene.hpp"
#include "wiring/CollocationSpec.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace mfwave::bar1d {

struct Study {
  Scene scene;
  CollocationSpec method;
  Real v0 = -1;
  std::vector<int> nodes;
  int errorPoints = 2001;
  int errorSamples = 50;
};

struct CaseResult : StudyCase {
  int nodes = 0;
  Real h = 0;
  Real errorU = 0, errorV = 0, maxErrorU = 0;
  Real orderU = std::nan(""), orderV = std::nan("");
};

// Runs one case with `nodeCount` nodes; with `writeSeries`, writes "<folder>/nodes-<n>-errors.csv"
// (the errors over time) and "<folder>/nodes-<n>-profile.csv" (u and v against the exact ones at
// the end).
CaseResult runCase(const Study& study, int nodeCount, const std::string& folder, bool writeSeries);

}  // namespace mfwave::bar1d
