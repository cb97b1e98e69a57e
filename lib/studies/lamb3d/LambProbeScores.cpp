#include "studies/lamb3d/LambProbeScores.hpp"

#include "core/AtomicFile.hpp"
#include "wiring/LambReference.hpp"

#include <algorithm>
#include <iomanip>
#include <optional>
#include <vector>

namespace mfwave::lamb3d {

template <int D>
void scoreLambProbes(const StudySettings& study, const CaseSettings& settings, const ParticleSet<D>& particles,
                     const ReportedProbes& recorded, const Kernel* floorKernel, const std::string& folder,
                     CaseResult& result) {
  std::vector<ProbeSite<D>> sites;
  for (const Probe& p : recorded.probes()) sites.push_back(probeSite<D>(particles, p.particle));
  scoreLambProbes<D>(study, settings, sites, recorded, floorKernel, folder, result);
}

template <int D>
void scoreLambProbes(const StudySettings& study, const CaseSettings& settings, const std::vector<ProbeSite<D>>& sites,
                     const ReportedProbes& recorded, const Kernel* floorKernel, const std::string& folder,
                     CaseResult& result) {
  const Scene& scene = study.scene;
  CaseRecord& record = result.record;
  const std::vector<Probe>& probes = recorded.probes();
  // errors against the exact half-space response, for probes reading the loaded face's normal component
  const std::string referenceProblem = lambReferenceUnavailable(scene);
  std::optional<LambExactResponse> exact;
  if (referenceProblem.empty()) exact.emplace(scene);
  else result.notes.push_back(referenceProblem);
  std::vector<std::vector<Real>> exactSeries(probes.size());
  std::vector<LambReceiver> receivers(probes.size());
  for (std::size_t i = 0; i < probes.size(); ++i) {
    ProbeResult r;
    r.name = probes[i].name;
    const bool velocity = probes[i].quantity == ProbeQuantity::Velocity;
    if (exact) {
      if (const auto receiver = lambReceiver<D>(scene, sites[i], probes[i])) {
        receivers[i] = *receiver;
        exactSeries[i] = exact->series(*receiver, recorded.times(), velocity, study.errorWindow);
        r.hasExact = true;
        r.raw = compareSignals(recorded.times(), recorded.raw(i), exactSeries[i], study.errorWindow,
                               study.arrivalFraction);
        r.reported = compareSignals(recorded.times(), recorded.reported(i), exactSeries[i], study.errorWindow,
                                    study.arrivalFraction);
        if (floorKernel && study.kernelFloor && exact->square() && receiver->depth == 0) {
          // Over the error window only (a long run's later samples would cost minutes).
          const std::vector<Real>& times = recorded.times();
          const auto inWindow = static_cast<std::ptrdiff_t>(
              std::upper_bound(times.begin(), times.end(), study.errorWindow) - times.begin());
          const std::vector<Real> windowTimes(times.begin(), times.begin() + inWindow);
          const std::vector<Real> windowExact(exactSeries[i].begin(), exactSeries[i].begin() + inWindow);
          r.kernelFloor = compareSignals(windowTimes,
                                         kernelSmoothedLambSeries(*exact->square(), *floorKernel, receiver->offset,
                                                                  windowTimes, velocity),
                                         windowExact, study.errorWindow, study.arrivalFraction)
                              .relativeL2;
        }
      } else {
        result.notes.push_back("probe " + r.name +
                               ": no exact reference (not the normal component on the loaded face, or in 3-D not "
                               "below the load centre)");
      }
    }
    result.probes.push_back(r);
  }
  // The record's primary error: the largest reported relative L2 error over the probes with an exact response.
  Real largest = -1;
  for (const ProbeResult& p : result.probes)
    if (p.hasExact) {
      record.errors.push_back({p.name + "_relative_l2", p.reported.relativeL2});
      largest = std::max(largest, p.reported.relativeL2);
    }
  if (largest >= 0) {
    record.errors.push_back({"largest_relative_l2", largest});
    record.primaryError = "largest_relative_l2";
  }
  recorded.writeCsv(folder + "/" + settings.name + "-probes.csv", exactSeries);
  if (exact && settings.writeFrames) {
    // The exact response on a fine time grid, for the figures (the errors use the run's samples).
    constexpr int samples = 600;
    std::vector<Real> times;
    for (int k = 0; k <= samples; ++k) times.push_back(scene.integrator.endTime * k / samples);
    std::vector<std::vector<Real>> columns(probes.size());
    for (std::size_t i = 0; i < probes.size(); ++i)
      if (result.probes[i].hasExact)
        columns[i] = exact->series(receivers[i], times, probes[i].quantity == ProbeQuantity::Velocity,
                                   study.errorWindow);
    AtomicFile file(folder + "/exact.csv");
    file.stream() << "t [s]";
    for (std::size_t i = 0; i < probes.size(); ++i)
      if (result.probes[i].hasExact) file.stream() << ',' << probes[i].name << "_exact";
    file.stream() << '\n' << std::setprecision(10);
    for (std::size_t k = 0; k < times.size(); ++k) {
      file.stream() << times[k];
      for (std::size_t i = 0; i < probes.size(); ++i)
        if (result.probes[i].hasExact) file.stream() << ',' << columns[i][k];
      file.stream() << '\n';
    }
    file.commit();
    result.files.push_back("exact.csv");
  }
  result.files.push_back(settings.name + "-probes.csv");
}

template void scoreLambProbes<2>(const StudySettings&, const CaseSettings&, const ParticleSet<2>&,
                                 const ReportedProbes&, const Kernel*, const std::string&, CaseResult&);
template void scoreLambProbes<3>(const StudySettings&, const CaseSettings&, const ParticleSet<3>&,
                                 const ReportedProbes&, const Kernel*, const std::string&, CaseResult&);
template void scoreLambProbes<2>(const StudySettings&, const CaseSettings&, const std::vector<ProbeSite<2>>&,
                                 const ReportedProbes&, const Kernel*, const std::string&, CaseResult&);
template void scoreLambProbes<3>(const StudySettings&, const CaseSettings&, const std::vector<ProbeSite<3>>&,
                                 const ReportedProbes&, const Kernel*, const std::string&, CaseResult&);

}  // namespace mfwave::lamb3d
