#pragma once
// One case of the wave1d study: a standing wave in a fixed-fixed bar, u_tt = c^2 u_xx, on a line of
// particles by the reference finite-difference operator and one integrator at one resolution,
// against the exact solution; and the check, before any case, of every integrator's step against
// its limit.

#include "io/run/StudyCases.hpp"
#include "io/scene/Scene.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace mfwave::wave1d {

struct Study {
  Scene scene;
  int mode = 1;
  std::vector<int> cells;
  std::vector<std::string> integrators;
  std::vector<std::string> notes;  // for the summary: steps run above the limit on purpose
};

struct CaseResult : StudyCase {
  std::string integrator;
  int cells = 0;
  Real dx = 0;
  Real error = 0;
  Real energyDrift = 0;
  Real order = std::nan("");  // against the next coarser case of the same integrator
};

// Runs one case; with `writeSeries`, writes "<folder>/<integrator>-<cells>-probe.csv" (u at the
// quarter point) and "<folder>/<integrator>-<cells>-energy.csv".
CaseResult runCase(const Study& study, const std::string& integratorName, int cellCount, const std::string& folder,
                   bool writeSeries);

// Before any work: every integrator's step against its limit L / omega_max (io/scene/StepLimitCheck)
// with omega_max = 2 c / dx, the Gershgorin bound of the finite-difference Laplacian (its largest
// eigenvalue with fixed ends is (2 c / dx)^2 cos^2(pi / 2N)). A step above it grows at every
// resolution, so it is refused naming the key (exit 2), unless stability.allow_growth asks to run
// there on purpose (the monitor then stops the blow-up, exit 3).
void refuseStepsAboveTheLimit(Study& study);

}  // namespace mfwave::wave1d
