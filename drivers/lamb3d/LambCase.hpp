#pragma once
// One run of the lamb3d study: a scene (possibly re-gridded, re-boxed or with other boundaries)
// through the very weak form SPH and central differences, its probes compared with the exact
// surface response of the half-space.

#include "analysis/SignalComparison.hpp"
#include "io/scene/Scene.hpp"
#include "io/scene/VeryWeakSphSpec.hpp"

#include <string>
#include <vector>

namespace mfwave::lamb3d {

// What distinguishes one run from the scene's own set-up.
struct CaseSettings {
  std::string name;                 // "paper", "strong_filter", "free_block", "spacing_0.25", ...
  GeometrySpec geometry;            // box and spacing of this run
  bool freeFaces = false;           // every face free (the large-block comparison)
  Real smoothingRate = 0;           // 1/s, eq. (33)
  bool writeFrames = false;         // VTK / PNG frames as the scene's [output] asks
};

struct ProbeResult {
  std::string name;
  bool hasExact = false;
  SignalErrors raw;            // the state u^h against the exact response
  SignalErrors deconvolved;    // sharpened by eq. (35)
};

struct CaseResult {
  CaseSettings settings;
  Index particles = 0, ghosts = 0;
  Real smoothingLength = 0;
  Real meanNeighbours = 0;
  Index operatorNonZeros = 0;
  Real operatorMiB = 0;             // K, T, C and M in CSR (values + indices)
  Real stableStepEstimate = 0, stableStepGershgorin = 0;
  Real timeStep = 0;
  long steps = 0;
  double assemblySeconds = 0, runSeconds = 0;
  double peakMemoryMiB = 0;         // of the process when the case ended (cases run smallest first)
  std::vector<ProbeResult> probes;
  std::vector<std::string> files;   // written, relative to the output folder
  std::vector<std::string> notes;

  double particleStepsPerSecond() const {
    return runSeconds > 0 ? static_cast<double>(particles) * static_cast<double>(steps) / runSeconds : 0;
  }
};

struct StudySettings {
  Scene scene;
  VeryWeakSphSpec method;
  Real errorWindow = 6;           // s: the errors are over 0 <= t <= errorWindow
  Real arrivalFraction = 0.1;     // arrival: first |v| >= fraction * |exact peak|
};

// Runs one case and writes "<folder>/<case>-probes.csv" (time, then raw, deconvolved and exact
// columns per probe) and, if asked, frames "<case>_NNNNNN.vtp" with "<case>.pvd".
CaseResult runCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                   bool progress);

}  // namespace mfwave::lamb3d
