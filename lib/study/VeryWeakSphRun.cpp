#include "study/VeryWeakSphRun.hpp"

#include "core/AtomicFile.hpp"
#include "methods/very_weak_sph/Deconvolution.hpp"

#include <iomanip>

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

template <int D>
std::unique_ptr<CentralDifference> veryWeakSphCentralDifference(VeryWeakSphProblem<D>& problem,
                                                                LinearEnergyLedger* ledger) {
  auto central = std::make_unique<CentralDifference>();
  if (ConservativeSmoothing* smoothing = problem.smoothing()) {
    if (ledger)
      central->setVelocityFilter([smoothing, ledger](Real step, Vector& v) {
        const Real before = ledger->kineticEnergy(v);
        smoothing->apply(step, v);
        ledger->addFilterLoss(before - ledger->kineticEnergy(v));
      });
    else
      central->setVelocityFilter([smoothing](Real step, Vector& v) { smoothing->apply(step, v); });
  }
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
    : probes_(std::move(probes)),
      components_(components),
      deconvolution_(deconvolution),
      raw_(probes_.size()),
      reported_(probes_.size()) {}

void VeryWeakSphProbes::observe(const StateView& s) {
  if (!times_.empty() && s.time <= times_.back()) return;
  times_.push_back(s.time);
  for (std::size_t i = 0; i < probes_.size(); ++i) {
    const Probe& p = probes_[i];
    const Vector& field = p.quantity == ProbeQuantity::Velocity ? s.velocity : s.displacement;
    raw_[i].push_back(field[components_ * p.particle + p.component]);
    reported_[i].push_back(deconvolution_ ? deconvolveAt(*deconvolution_, p.particle, field, components_, p.component)
                                          : raw_[i].back());
  }
}

void VeryWeakSphProbes::writeCsv(const std::string& path, const std::vector<std::vector<Real>>& exact) const {
  AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "t [s]";
  for (std::size_t i = 0; i < probes_.size(); ++i) {
    out << ',' << probes_[i].name << "_raw," << probes_[i].name << "_reported";
    if (!exact[i].empty()) out << ',' << probes_[i].name << "_exact";
  }
  out << '\n' << std::setprecision(10);
  for (std::size_t k = 0; k < times_.size(); ++k) {
    out << times_[k];
    for (std::size_t i = 0; i < probes_.size(); ++i) {
      out << ',' << raw_[i][k] << ',' << reported_[i][k];
      if (!exact[i].empty()) out << ',' << exact[i][k];
    }
    out << '\n';
  }
  file.commit();
}

}  // namespace mfwave
