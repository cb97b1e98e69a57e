#pragma once
// What the Lamb cases whose systems keep an energy ledger (the very weak SPH, spectral elements)
// share: the ledger's options for a Lamb block, and the time loop run with the ledger, which on a
// blow-up leaves what was recorded readable and otherwise fills the case's energy figures.

#include "io/scene/Scene.hpp"
#include "observers/LinearEnergyLedger.hpp"
#include "observers/ReportedProbes.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "studies/lamb3d/LambCase.hpp"

#include <string>

namespace mfwave::lamb3d {

// The step of a case on a linear operator: integrator.cfl times the central-difference stable step
// (power iteration; the Gershgorin bound when it does not converge, with a note), checked against
// the integrator's own limit before any work (InputError, exit 2, above it). Fills the record's
// stable step, step and simulated time and the case's Gershgorin step; returns dt. `operatorName`
// says what the power iteration ran on, for the step-limit message.
Real chooseLambTimeStep(const LinearOperatorSystem& system, const Scene& scene, const std::string& operatorName,
                        CaseResult& result);

// The ledger of a case on `geometry` (a D-dimensional box of `material`): judged after the loads end,
// its envelope window half the slowest shear period of the block (2 L / c_s, L its longest side),
// the scene's growth and balance limits (no balance check when faces move: reactions do work the
// ledger does not see), stopping the run unless stability.allow_growth.
LinearEnergyLedgerOptions lambLedgerOptions(const Scene& scene, const GeometrySpec& geometry, int dimension,
                                            const Material& material, bool movingFaces, std::string likelyCause);

// Runs `loop` (which holds `monitor` and `ledger`) to the scene's end time. On InstabilityError the
// probes recorded so far (without exact columns) and the energy table are written, then it rethrows;
// otherwise the loop's statistics, the ledger's final fraction, balance drift and growth message go
// to `result` (with a note when growth was allowed) and the energy table to <case>-energy.csv when
// the scene's output asks for it. `writeFiles` false (every rank but the first of a run on ranks):
// nothing is written.
void runLambLoopWithLedger(TimeLoop& loop, SecondOrderIntegrator& integrator, const Scene& scene,
                           const ReportedProbes& recorder, const LinearEnergyLedger& ledger,
                           const StabilityMonitor& monitor, const std::string& folder, CaseResult& result,
                           bool writeFiles = true);

}  // namespace mfwave::lamb3d
