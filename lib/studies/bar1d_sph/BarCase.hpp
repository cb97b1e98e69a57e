#pragma once
// One case of the bar1d-sph study: the two bars at one particle spacing, run to the end time, and
// its errors against the exact solution.

#include "io/run/StudyCases.hpp"
#include "io/scene/OutputSpec.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSphOptions.hpp"
#include "wiring/SolidIntegration.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace mfwave::bar1dsph {

struct Settings {
  UpdatedLagrangianSphOptions options;
  SolidIntegrationSettings integration;
  Real halfLength = 1;       // each bar is L long: [-L, 0] and [0, L]
  Real impactSpeed = 0.01;   // v0
  Real plateauFraction = 0.5;
  Real endTime = 0.5;
  std::vector<Real> spacings;
  Real frameSpacing = 0;     // the case at this spacing writes VTK frames (when output.vtk)
  OutputSpec output;
};

struct CaseResult : StudyCase {
  Real dx = 0;
  Real meanNeighbours = 0;
  Real l1Velocity = 0;          // ||v - v_exact||_1 / ||v_exact||_1 at the end time
  Real l1Stress = 0;            // ||sigma - sigma_exact||_1 / ||sigma_exact||_1
  Real plateauStressError = 0;  // (mean sigma over |x| < f c t) / (-rho c v0) - 1
  Real frontErrorOverDx = 0;    // (measured right front - c t) / dx
  Real balanceDrift = 0;        // EnergyLedger::largestBalanceDrift
  Real orderVelocity = std::nan(""), orderStress = std::nan("");
};

// "profile-<dx>.csv": x, v, v_exact, sigma, sigma_exact at the end time.
std::string profileFileName(Real dx);

CaseResult runCase(const Settings& settings, Real dx, const std::string& folder, bool writeFrames);

}  // namespace mfwave::bar1dsph
