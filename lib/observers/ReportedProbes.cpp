#include "observers/ReportedProbes.hpp"

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"

#include <iomanip>

namespace mfwave {

ReportedProbes::ReportedProbes(std::vector<Probe> probes)
    : probes_(std::move(probes)), raw_(probes_.size()), reported_(probes_.size()) {}

bool ReportedProbes::beginSample(Real time) {
  if (!times_.empty() && time <= times_.back()) return false;
  times_.push_back(time);
  return true;
}

void ReportedProbes::add(std::size_t i, Real raw, Real reported) {
  raw_[i].push_back(raw);
  reported_[i].push_back(reported);
}

void ReportedProbes::writeCsv(const std::string& path, const std::vector<std::vector<Real>>& exact) const {
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

NodalProbes::NodalProbes(std::vector<Probe> probes, int dimension, Real scale)
    : ReportedProbes(std::move(probes)), dimension_(dimension), scale_(scale) {}

void NodalProbes::observe(const StateView& s) {
  if (!beginSample(s.time)) return;
  for (std::size_t i = 0; i < probes().size(); ++i) {
    const Probe& p = probes()[i];
    const Vector& field = p.quantity == ProbeQuantity::Velocity ? s.velocity : s.displacement;
    const Real value = field[dimension_ * p.particle + p.component] / scale_;
    add(i, value, value);
  }
}

void ReportedProbes::saveState(StateArchive& archive) const {
  archive.put("times", times_);
  for (std::size_t i = 0; i < probes_.size(); ++i) {
    archive.put("raw" + std::to_string(i), raw_[i]);
    archive.put("reported" + std::to_string(i), reported_[i]);
  }
}

void ReportedProbes::restoreState(const StateArchive& archive) {
  times_ = archive.get("times");
  for (std::size_t i = 0; i < probes_.size(); ++i) {
    raw_[i] = archive.get("raw" + std::to_string(i));
    reported_[i] = archive.get("reported" + std::to_string(i));
    if (raw_[i].size() != times_.size() || reported_[i].size() != times_.size())
      throw InputError("--restart", "the checkpoint's probe " + std::to_string(i) + " has another number of samples than times");
  }
}

}  // namespace mfwave
