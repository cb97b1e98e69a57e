#include "wiring/VeryWeakSphRun.hpp"

#include "methods/very_weak_sph/Deconvolution.hpp"

namespace mfwave {

std::string veryWeakSphGrowthCause(VeryWeakSphVariant variant) {
  if (variant == VeryWeakSphVariant::Galerkin)
    return "the galerkin variant's operator is symmetric positive semi-definite and its dashpots dissipative, so its "
           "energy cannot grow at a stable step: look for a step above the stable limit (integrator.cfl) or a defect";
  if (variant == VeryWeakSphVariant::Consistent)
    return "the consistent variant's corrected boundary rows are not symmetric and feed slowly growing modes, "
           "faster as the spacing falls (docs/theory/very-weak-sph.md); method.smoothing_rate only delays it. "
           "stability.allow_growth = true runs on to show it";
  return "the published operator has growing modes (indefinite interior Hessian stencil, non-symmetric boundary "
         "terms) that only its filter (method.smoothing_rate) holds down (docs/theory/very-weak-sph.md). "
         "stability.allow_growth = true runs on to show it";
}

std::unique_ptr<CentralDifference> smoothedCentralDifference(ConservativeSmoothing* smoothing,
                                                             LinearEnergyLedger* ledger) {
  auto central = std::make_unique<CentralDifference>();
  if (smoothing) {
    if (ledger)
      central->setVelocityFilter([smoothing, ledger](Real step, Vector& v) {
        const Real before = ledger->kineticEnergy(v);
        smoothing->apply(step, v);
        ledger->addFilterLoss(before - ledger->kineticEnergy(v));
      });
    else
      central->setVelocityFilter([smoothing](Real step, Vector& v) { smoothing->apply(step, v); });
  }
  return central;
}

template <int D>
std::unique_ptr<CentralDifference> veryWeakSphCentralDifference(VeryWeakSphProblem<D>& problem,
                                                                LinearEnergyLedger* ledger) {
  std::unique_ptr<CentralDifference> central = smoothedCentralDifference(problem.smoothing(), ledger);
  if (!problem.prescribedDofs().empty())
    central->setPrescribedDisplacement(problem.prescribedDofs(),
                                       [&problem](Real t, Vector& values) { problem.prescribedValues(t, values); });
  return central;
}

template std::unique_ptr<CentralDifference> veryWeakSphCentralDifference<1>(VeryWeakSphProblem<1>&,
                                                                            LinearEnergyLedger*);
template std::unique_ptr<CentralDifference> veryWeakSphCentralDifference<2>(VeryWeakSphProblem<2>&,
                                                                            LinearEnergyLedger*);
template std::unique_ptr<CentralDifference> veryWeakSphCentralDifference<3>(VeryWeakSphProblem<3>&,
                                                                            LinearEnergyLedger*);

VeryWeakSphProbes::VeryWeakSphProbes(std::vector<Probe> probes, int components, const ParticleMatrix* deconvolution)
    : ReportedProbes(std::move(probes)), components_(components), deconvolution_(deconvolution) {}

void VeryWeakSphProbes::observe(const StateView& s) {
  if (!beginSample(s.time)) return;
  for (std::size_t i = 0; i < probes().size(); ++i) {
    const Probe& p = probes()[i];
    const Vector& field = p.quantity == ProbeQuantity::Velocity ? s.velocity : s.displacement;
    const Real raw = field[components_ * p.particle + p.component];
    add(i, raw, deconvolution_ ? deconvolveAt(*deconvolution_, static_cast<Index>(i), field, components_, p.component) : raw);
  }
}

}  // namespace mfwave
