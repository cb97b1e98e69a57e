#pragma once
// One run of the plate study: the cantilever plate of Gray, Monaghan and Swift (2001) at one
// resolution and one start velocity, by the updated-Lagrangian SPH (the study's method) or, for
// the small-deformation comparison, by the very weak form SPH, or by the total-Lagrangian SPH; its tip history analysed for the
// period and the amplitude and compared with the thin-plate and Timoshenko periods.

#include "numerics/Oscillation.hpp"

#include "analytic/CantileverPlate.hpp"
#include "io/run/StudyCases.hpp"
#include "io/scene/Scene.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSphOptions.hpp"
#include "observers/TimeSeries.hpp"

#include <limits>
#include <string>
#include <vector>

namespace mfwave::plate {

enum class PlateMethod { UpdatedLagrangian, VeryWeak, TotalLagrangian };

// What the scene fixes for every case.
struct PlateStudy {
  Scene scene;
  Real length = 0.2, thickness = 0.02, lowerY = -0.01;  // the plate [0, L] x [lowerY, lowerY + H]
  Index clampLayers = 3;                                // fixed columns at x < 0 (updated-Lagrangian SPH)
  UpdatedLagrangianSphOptions sph;                      // [method]
  Real stepFactor = 1;                                  // integrator.cfl: a factor on the method's step
  long tipEvery = 10;                                   // steps between tip samples (output.probe_every)
  long energyEvery = 100;                               // steps between energy-ledger rows
  long pngFrames = 8;                                   // PNG pictures of the main case
  Real shearCoefficient = Real(5) / 6;                  // Timoshenko kappa
  // The very weak form case: h / dx and the filter rate (0: none) of its consistent variant.
  Real veryWeakSmoothingLengthRatio = 1;
  Real veryWeakSmoothingRate = 1e4;
  Real veryWeakCfl = 0.5;         // central-difference step / the operator's stable step
  Index veryWeakGhostLayers = 2;  // ghost layers on every face (they complete the kernel sums)
  // The total-Lagrangian cases: the hourglass penalty (times Young's modulus) and the
  // central-difference step over the linearised system's limit.
  Real totalLagrangianHourglass = 1;
  Real totalLagrangianCfl = 0.5;
};

// What distinguishes one run.
struct PlateCaseSettings {
  std::string name;  // "ulsph_Hdp5_Vf0.05", "vwsph_Hdp5_Vf0.01", ...
  PlateMethod method = PlateMethod::UpdatedLagrangian;
  Index rows = 5;              // H / dp: particles (SPH) or intervals (very weak form) across the thickness
  Real velocityFactor = 0.05;  // V_f
  Real endTime = 1;
  bool writeFrames = false;  // VTK frames (and PNG pictures) as the scene's [output] asks
};

// The record (StudyCase): particles (all, clamp included), steps, the mean dt, set-up and loop times,
// and the period errors (analyseTip).
struct PlateCaseResult : StudyCase {
  PlateCaseSettings settings;
  Real spacing = 0;          // dp
  Index fixedParticles = 0;  // clamp particles (SPH) or clamped nodes (very weak form)
  Real smoothingLength = 0;
  Real meanNeighbours = 0;
  long neighbourRebuilds = 0;
  Oscillation tip;             // of the tip's transverse displacement
  Real tipStartVelocity = 0;   // v_y of the tip column at t = 0
  Real expectedAmplitude = 0;  // tipStartVelocity / (2 pi / measured period)
  Real thinPeriod = 0, timoshenkoPeriod = 0;
  // Energy: the largest |balance(t) - balance(0)| / E(0) over the run (the energy ledger), and the
  // ledger's terms at the end over E(0).
  Real energyDrift = std::numeric_limits<Real>::quiet_NaN();
  Real viscousFraction = std::numeric_limits<Real>::quiet_NaN();
  Real artificialStressFraction = std::numeric_limits<Real>::quiet_NaN();
  Real largestZigzag = std::numeric_limits<Real>::quiet_NaN();
  // max over the run of zigzag^2 kinetic / E(0): the particle-scale part of the kinetic energy
  // (the zig-zag ratio alone is large whenever the whole plate is near rest, at every turn).
  Real largestZigzagEnergy = std::numeric_limits<Real>::quiet_NaN();
  Real smallestSpacingRatio = std::numeric_limits<Real>::quiet_NaN();

  static constexpr int earlyPeriods = 5;  // earlyPeriod(): over the first five periods
  Real periodsRun() const { return tip.period > 0 ? settings.endTime / tip.period : 0; }
  Real thinError() const { return tip.period / thinPeriod - 1; }
  Real timoshenkoError() const { return tip.period / timoshenkoPeriod - 1; }
};

// Runs one case; writes "<folder>/<case>-tip.csv", "<folder>/<case>-energy.csv" and, when asked,
// frames "<case>_NNNNNN.vtp" with "<case>.pvd" and PNG pictures "<case>_NNNNNN.png".
PlateCaseResult runPlateCase(const PlateStudy& study, const PlateCaseSettings& settings, const std::string& folder,
                             bool progress);

// The cell-centred particles and clamp of the SPH cases at settings.rows across, with the result's
// spacing, particle and clamp counts filled in; and the first mode's velocity v_y on them (GMS).
struct PlateLattice;
PlateLattice sphCaseParticles(const PlateStudy& study, const PlateCaseSettings& settings, PlateCaseResult& result);
Vector firstModeVelocity(const PlateLattice& lattice, const CantileverPlate& plate, Real velocityFactor);

// Fills the tip analysis (period, amplitudes), the reference periods, the expected amplitude and
// the record's errors (ranked by |period error vs Timoshenko|) of `result` from the tip history
// (columns u_x, u_y, v_x, v_y). Shared by both methods' runs.
void analyseTip(PlateCaseResult& result, const TimeSeries& tip, const CantileverPlate& plate, Real shearCoefficient);

}  // namespace mfwave::plate
