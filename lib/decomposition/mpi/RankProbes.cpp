#include "decomposition/mpi/RankProbes.hpp"

#include "core/Error.hpp"

#include <string>

namespace mfwave {

RankProbes::RankProbes(std::vector<Probe> probes, std::vector<Index> localParticle, int components,
                       MPI_Comm communicator)
    : ReportedProbes(std::move(probes)),
      local_(std::move(localParticle)),
      components_(components),
      communicator_(communicator) {
  if (local_.size() != this->probes().size())
    throw Error("RankProbes: " + std::to_string(local_.size()) + " local particles for " +
                std::to_string(this->probes().size()) + " probes");
  std::vector<int> owners(local_.size());
  for (std::size_t i = 0; i < local_.size(); ++i) owners[i] = local_[i] >= 0 ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, owners.data(), static_cast<int>(owners.size()), MPI_INT, MPI_SUM, communicator_);
  for (std::size_t i = 0; i < owners.size(); ++i)
    if (owners[i] != 1)
      throw Error("probe \"" + this->probes()[i].name + "\" is owned by " + std::to_string(owners[i]) +
                  " ranks; it must be owned by exactly one");
  values_.resize(local_.size());
}

void RankProbes::observe(const StateView& s) {
  if (!beginSample(s.time)) return;
  for (std::size_t i = 0; i < local_.size(); ++i) {
    const Probe& p = probes()[i];
    const Vector& field = p.quantity == ProbeQuantity::Velocity ? s.velocity : s.displacement;
    values_[i] = local_[i] >= 0 ? field[components_ * local_[i] + p.component] : -0.0;
  }
  MPI_Allreduce(MPI_IN_PLACE, values_.data(), static_cast<int>(values_.size()), MPI_DOUBLE, MPI_SUM, communicator_);
  for (std::size_t i = 0; i < values_.size(); ++i) add(i, values_[i], values_[i]);
}

}  // namespace mfwave
