#pragma once
// One run of the rings study: two elastic rings (annuli) on a collision course along x, through
// the updated-Lagrangian SPH, with or without the Monaghan-Gray artificial stress; what it
// measures to tell an intact rebound from fragmentation.

#include "io/run/StudyCases.hpp"
#include "io/scene/Scene.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "wiring/SolidIntegration.hpp"

#include <string>
#include <vector>

namespace mfwave::rings {

// What every case shares: the scene and the ring set-up.
struct StudySettings {
  Scene scene;
  UpdatedLagrangianSphOptions method;  // the scene's [method] (artificial stress switched per case)
  SolidIntegrationSettings integration;
  // The two annuli of the scene ([[shape]] type annulus, [[region]] initial velocities): centred
  // at (-centreOffset, 0) and (centreOffset, 0), the left one moving at +approachSpeed along x and
  // the right one at -approachSpeed.
  Real innerRadius = 0.03;        // m
  Real outerRadius = 0.04;        // m
  Real centreOffset = 0.0425;     // m
  Real approachSpeed = 237.9;     // m/s
  Real linkDistance = 1.5;        // fragments: particles closer than this many spacings are joined
  Real zigzagThreshold = 0.1;     // report the first time the zig-zag indicator exceeds this
  int snapshots = 6;              // position snapshots at evenly spaced times (t = 0 and the end included)
  long trackEvery = 10;           // steps between ledger and ring-motion samples (output.probe_every)
  bool autoPointSize = true;      // PNG particle size from the spacing (output.png_point_size not given)
};

struct CaseSettings {
  std::string name;  // "artificial_stress", "no_artificial_stress"
  bool artificialStress = true;
  bool writeFrames = true;  // VTK / PNG frames as the scene's [output] asks
};

// The record (StudyCase): particles, steps, the mean dt, the end time reached, set-up and loop
// times, peak memory, and as errors (no exact solution) the energy balance's largest drift and
// the fragments beyond the two rings.
struct CaseResult : StudyCase {
  CaseSettings settings;
  Index leftParticles = 0;
  Real spacing = 0, smoothingLength = 0, soundSpeed = 0, approachSpeed = 0;
  Real meanNeighbours = 0;
  long neighbourRebuilds = 0;
  Real firstStep = 0, smallestStep = 0;
  double rhsEvaluations = 0;

  UpdatedLagrangianSphEnergy initialEnergy, finalEnergy;
  Real largestBalanceDrift = 0;  // EnergyLedger::largestBalanceDrift
  Real finalBalanceDrift = 0;    // (balance(end) - balance(0)) / (kinetic + strain)(0)
  Real largestZigzag = 0, firstZigzagTime = -1;
  Real smallestSpacingRatio = 0, finalSpacingRatio = 0;

  Index fragments = 0;                                 // connected pieces at the end (2 = both rings intact)
  Index strayParticles = 0;                            // particles outside the two largest pieces
  Index links = 0;                                     // pairs closer than the link distance at t = 0
  Index tornLinks = 0;                                 // of those, longer than twice the link distance at the end
  std::vector<Index> fragmentSizes;                    // largest first (at most 10 kept)
  Real leftVelocityStart = 0, rightVelocityStart = 0;  // centre-of-mass x velocity
  Real leftVelocityEnd = 0, rightVelocityEnd = 0;
  Real restitutionLeft = 0, restitutionRight = 0;  // -v_end / v_start of each ring
  Real supportRadius = 0;                          // of the kernel: the reach of SPH interactions
  Real contactTime = -1, separationTime = -1;      // gap along x below / back above the support radius
  Real smallestGap = 0;                            // smallest gap along x between the rings

  std::string failure;  // why the run stopped early (empty: it reached the end)
};

// Runs one case and writes "<folder>/<case>-energy.csv" (the ledger), "<case>-rings.csv" (each
// ring's centre of mass and the gap between them), "<case>-positions.csv" (every particle at the
// snapshot times, with its ring and fragment) and, if asked, frames "<case>_NNNNNN.vtp|png".
CaseResult runCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder, bool progress);

}  // namespace mfwave::rings
