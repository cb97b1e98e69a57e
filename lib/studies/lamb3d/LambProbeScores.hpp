#pragma once
// What every method of the Lamb study does the same way with its probes once a case has run: score
// each against the exact response of the half-space (LambReference: where the probe sees it, the
// series over the error window, compareSignals), put the errors into the case's record, write
// "<case>-probes.csv" (and, for the figure case, exact.csv). The very weak SPH case and the RK
// collocation case both end here, so their cases.csv and summary.json columns mean the same.

#include "studies/lamb3d/LambCase.hpp"

#include "kernels/Kernel.hpp"
#include "observers/ReportedProbes.hpp"
#include "particles/ParticleSet.hpp"
#include "wiring/LambReference.hpp"

#include <string>
#include <vector>

namespace mfwave::lamb3d {

// Fills result.probes (per probe: raw and reported errors against the exact response where the
// scene has one and the probe reads the loaded face's normal component), the record's errors (each
// probe's reported relative L2 and the largest, the primary error), writes
// "<folder>/<case>-probes.csv" and, when settings.writeFrames, "<folder>/exact.csv" (the exact
// response on a fine time grid, for the figures), lists them in result.files and says in
// result.notes why a probe or the scene has no reference. `floorKernel`: the kernel whose spreading
// of the load gives ProbeResult::kernelFloor (3-D surface probes with study.kernelFloor); null for
// none. `particles` are the ones the probes were resolved on.
template <int D>
void scoreLambProbes(const StudySettings& study, const CaseSettings& settings, const ParticleSet<D>& particles,
                     const ReportedProbes& recorded, const Kernel* floorKernel, const std::string& folder,
                     CaseResult& result);
// The same with each probe's site (position and face tags) given, one per recorded probe in order.
template <int D>
void scoreLambProbes(const StudySettings& study, const CaseSettings& settings, const std::vector<ProbeSite<D>>& sites,
                     const ReportedProbes& recorded, const Kernel* floorKernel, const std::string& folder,
                     CaseResult& result);

}  // namespace mfwave::lamb3d
