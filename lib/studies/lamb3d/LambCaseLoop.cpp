#include "studies/lamb3d/LambCaseLoop.hpp"

#include "core/Error.hpp"
#include "numerics/StableTimeStep.hpp"
#include "io/run/RunSummary.hpp"
#include "io/scene/StepLimitCheck.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace mfwave::lamb3d {

Real chooseLambTimeStep(const LinearOperatorSystem& system, const Scene& scene, const std::string& operatorName,
                        CaseResult& result) {
  const std::string& name = result.settings.name;
  const StableTimeStep stable = centralDifferenceStableStep(system, 1e-6, 5000);
  result.record.stableTimeStep = stable.estimate();
  result.stableStepGershgorin = stable.safe();
  const Real stableStep = stable.usable();
  if (!stable.converged) result.notes.push_back(name + ": power iteration did not converge; the Gershgorin step is used");
  const Real dt = scene.integrator.timeStepFor(stableStep);
  result.record.timeStep = dt;
  result.record.simulatedTime = scene.integrator.endTime;
  const StepLimitCheck check =
      checkStepLimit(scene.integrator, scene.stability, 2 / stableStep, dt, stableStep,
                     stable.converged ? "a power iteration on " + operatorName : std::string("the Gershgorin bound"),
                     "in case " + name);
  if (!check.note.empty()) result.notes.push_back(check.note);
  return dt;
}

LinearEnergyLedgerOptions lambLedgerOptions(const Scene& scene, const GeometrySpec& geometry, int dimension,
                                            const Material& material, bool movingFaces, std::string likelyCause) {
  LinearEnergyLedgerOptions options;
  options.quietAfter = loadsQuietAfter(scene);
  Real side = 0;
  for (std::size_t a = 0; a < static_cast<std::size_t>(dimension); ++a)
    side = std::max(side, geometry.upper[a] - geometry.lower[a]);
  options.envelopeWindow = 2 * side / material.sWaveSpeed();
  options.growthFactor = scene.stability.energyGrowthFactor;
  options.balanceLimit = movingFaces ? 0 : scene.stability.energyBalanceLimit;
  options.components = dimension;
  options.likelyCause = std::move(likelyCause);
  options.stop = !scene.stability.allowGrowth;
  return options;
}

void runLambLoopWithLedger(TimeLoop& loop, SecondOrderIntegrator& integrator, const Scene& scene,
                           const ReportedProbes& recorder, const LinearEnergyLedger& ledger,
                           const StabilityMonitor& monitor, const std::string& folder, CaseResult& result,
                           bool writeFiles) {
  const std::string& name = result.settings.name;
  const std::string energyFile = name + "-energy.csv";
  RunStatistics stats;
  try {
    stats = loop.run(integrator, scene.integrator.endTime);
  } catch (const InstabilityError&) {
    // What was recorded up to the stop stays readable: the probes (without the exact columns) and
    // the energy ledger.
    if (!writeFiles) throw;
    recorder.writeCsv(folder + "/" + name + "-probes.csv", std::vector<std::vector<Real>>(recorder.probes().size()));
    if (scene.output.energy) ledger.series().writeCsv(folder + "/" + energyFile);
    throw;
  }
  result.recordLoop(stats);
  result.energyFinalFraction = ledger.finalEnergyFraction();
  result.energyBalanceDrift = ledger.largestBalanceDrift();
  result.energyGrowth = ledger.growthMessage();
  noteAllowedGrowth(result.notes, name, {result.energyGrowth, monitor.growthMessage()});
  if (scene.output.energy && writeFiles) {
    ledger.series().writeCsv(folder + "/" + energyFile);
    result.files.push_back(energyFile);
  }
}

}  // namespace mfwave::lamb3d
