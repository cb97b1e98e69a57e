#pragma once
// One run of the lamb3d study: a scene (possibly re-gridded, re-boxed or with other boundaries)
// through the very weak form SPH and central differences, its probes compared with the exact
// surface response of the half-space.

#include "analysis/SignalComparison.hpp"
#include "io/run/StudyCases.hpp"
#include "io/scene/Scene.hpp"
#include "study/VeryWeakSphSpec.hpp"

#include <limits>
#include <string>
#include <vector>

namespace mfwave::lamb3d {

// What distinguishes one run from the scene's own set-up.
struct CaseSettings {
  std::string name;                 // "galerkin_0.5", "published_0.25", "strong_filter", "free_block", ...
  GeometrySpec geometry;            // box and spacing of this run
  bool freeFaces = false;           // every face free (the large-block comparison)
  VeryWeakSphSpec method;           // variant, corrections, smoothing (rate at this spacing), deconvolution
  bool writeFrames = false;         // VTK / PNG frames as the scene's [output] asks
};

struct ProbeResult {
  std::string name;
  bool hasExact = false;
  SignalErrors raw;        // the state against the exact response
  SignalErrors reported;   // what the method reports: deconvolved by eq. (35) when it is on, else the state
  // Relative L2 distance of the exact response to the load spread over the surface by the kernel
  // (its plane density) from the exact response: the part of the error that the kernel's width
  // alone explains. NaN when not computed.
  Real kernelFloor = std::numeric_limits<Real>::quiet_NaN();
};

// The record (StudyCase) holds particles, steps, dt, the stable step estimate, the set-up
// (assembly) and loop times and the peak memory (of the process when the case ended: cases run
// smallest first).
struct CaseResult : StudyCase {
  CaseSettings settings;
  Index ghosts = 0;
  Real smoothingLength = 0;
  Real meanNeighbours = 0;
  Index operatorNonZeros = 0;
  Real operatorMiB = 0;             // K, T, C and M in CSR (values + indices)
  Real stableStepGershgorin = 0;
  // The energy ledger: kinetic + |strain| at the end over its largest value, the largest balance
  // drift over the largest energy, and the growth the run went on through (stability.allow_growth).
  Real energyFinalFraction = 0, energyBalanceDrift = 0;
  std::string energyGrowth;
  std::vector<ProbeResult> probes;
};

struct StudySettings {
  Scene scene;
  Real errorWindow = 6;           // s: the errors are over 0 <= t <= errorWindow
  Real arrivalFraction = 0.1;     // arrival: first |v| >= fraction * |exact peak|
  bool kernelFloor = false;       // compute ProbeResult::kernelFloor
};

// Runs one case and writes "<folder>/<case>-probes.csv" (time, then raw, reported and exact
// columns per probe) and, if asked, frames "<case>_NNNNNN.vtp" with "<case>.pvd".
CaseResult runCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                   bool progress);

}  // namespace mfwave::lamb3d
