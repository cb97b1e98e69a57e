#pragma once
// Running a very weak SPH problem (VeryWeakSphProblem): the central-difference integrator with the
// method's smoothing filter and prescribed faces wired in, the probes the method reports (raw and
// deconvolved), and what to blame when its energy grows. Shared by every driver that steps the
// method (lamb3d, the plate's very weak case).

#include "integrators/CentralDifference.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "observers/LinearEnergyLedger.hpp"
#include "observers/Observer.hpp"
#include "observers/ProbeRecorder.hpp"
#include "observers/ReportedProbes.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfwave {

// What makes this variant's energy grow, for the energy ledger's stop message
// (docs/theory/very-weak-sph.md).
std::string veryWeakSphGrowthCause(VeryWeakSphVariant variant);

// Central differences for `problem`: the smoothing (Ding et al. eq. (33)) as the velocity filter,
// the kinetic energy it takes booked as `ledger`'s filter loss when a ledger is given, and eq. (30)
// for the prescribed dofs. The problem and the ledger must outlive the integrator.
template <int D>
std::unique_ptr<CentralDifference> veryWeakSphCentralDifference(VeryWeakSphProblem<D>& problem,
                                                                LinearEnergyLedger* ledger = nullptr);

// Central differences with `smoothing` (may be null) as the velocity filter, its loss booked in
// `ledger` when given: the part of the above a run on ranks uses with its own share of the filter.
std::unique_ptr<CentralDifference> smoothedCentralDifference(ConservativeSmoothing* smoothing,
                                                             LinearEnergyLedger* ledger = nullptr);

// Each probe's value in the state (raw) and the value the method reports: with a deconvolution
// matrix (the published variant) the deconvolved value at the probe (eq. (35)), else the state
// itself. Samples once per time (end() right after a sample of the same step adds nothing); the
// series and their CSV are ReportedProbes'.
class VeryWeakSphProbes : public ReportedProbes {
 public:
  // `components`: unknowns per particle; `deconvolution` holds row i for probe i (deconvolutionRows
  // of the probes' particles), may be null and must outlive the recorder.
  VeryWeakSphProbes(std::vector<Probe> probes, int components, const ParticleMatrix* deconvolution);

  void observe(const StateView& s) override;

 private:
  int components_;
  const ParticleMatrix* deconvolution_;
};

}  // namespace mfwave
