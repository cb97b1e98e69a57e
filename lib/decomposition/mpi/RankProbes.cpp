#include "decomposition/mpi/RankProbes.hpp"

#include "core/Error.hpp"

#include <string>

namespace mfwave {

RankProbes::RankProbes(std::vector<Probe> probes, const LocalParticle& localParticle, int components,
                       MPI_Comm communicator, const Rows* rows)
    : ReportedProbes(std::move(probes)), components_(components), communicator_(communicator) {
  const std::vector<Probe>& all = this->probes();
  std::vector<int> owners(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    const bool velocity = all[i].quantity == ProbeQuantity::Velocity;
    reads_.push_back({localParticle(all[i].particle), all[i].component, velocity});
    owners[i] = reads_.back().local >= 0 ? 1 : 0;
  }
  MPI_Allreduce(MPI_IN_PLACE, owners.data(), static_cast<int>(owners.size()), MPI_INT, MPI_SUM, communicator_);
  for (std::size_t i = 0; i < owners.size(); ++i)
    if (owners[i] != 1)
      throw Error("probe \"" + all[i].name + "\" is owned by " + std::to_string(owners[i]) +
                  " ranks; it must be owned by exactly one");
  if (rows) {
    if (rows->rows() != static_cast<Index>(all.size()))
      throw Error("deconvolution rows: " + std::to_string(rows->rows()) + " for " + std::to_string(all.size()) +
                  " probes; need one per probe");
    for (std::size_t i = 0; i < all.size(); ++i) {
      const Probe& p = all[i];
      rowStart_.push_back(reads_.size());
      for (Rows::InnerIterator it(*rows, static_cast<int>(i)); it; ++it) {
        reads_.push_back({localParticle(it.col()), p.component, p.quantity == ProbeQuantity::Velocity});
        weights_.push_back(it.value());
      }
    }
    rowStart_.push_back(reads_.size());
  }
  values_.resize(reads_.size());
}

void RankProbes::observe(const StateView& s) {
  if (!beginSample(s.time)) return;
  for (std::size_t k = 0; k < reads_.size(); ++k) {
    const Read& r = reads_[k];
    const Vector& field = r.velocity ? s.velocity : s.displacement;
    values_[k] = r.local >= 0 ? field[components_ * r.local + r.component] : -0.0;
  }
  MPI_Allreduce(MPI_IN_PLACE, values_.data(), static_cast<int>(values_.size()), MPI_DOUBLE, MPI_SUM, communicator_);
  const std::size_t count = probes().size();
  for (std::size_t i = 0; i < count; ++i) {
    if (rowStart_.empty()) {
      add(i, values_[i], values_[i]);
      continue;
    }
    // deconvolveAt's sum, in the row's order
    Real sum = 0;
    for (std::size_t k = rowStart_[i]; k < rowStart_[i + 1]; ++k) sum += weights_[k - count] * values_[k];
    add(i, values_[i], sum);
  }
}

}  // namespace mfwave
