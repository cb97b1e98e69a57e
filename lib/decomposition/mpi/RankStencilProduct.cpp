#include "decomposition/mpi/RankStencilProduct.hpp"

namespace mfwave {

template <int D>
RankStencilProduct<D>::RankStencilProduct(const LatticeStencils<D>& stencils, const BlockDecomposition<D>& decomposition,
                                          int rank, MPI_Comm communicator)
    : exchange_(std::make_unique<HaloExchange<D>>(HaloPlan<D>(decomposition, rank, stencilReach(stencils)), D,
                                                  communicator)),
      rows_(std::make_unique<LocalStencils<D>>(stencils, exchange_->plan().owned(), exchange_->plan().local())),
      local_(static_cast<std::size_t>(exchange_->localSize())) {}

template <int D>
void RankStencilProduct<D>::multiply(const Real* x, Real* y, const std::vector<char>* direct) {
  const Box<D>& own = owned();
  const Box<D>& local = exchange_->plan().local();
  own.forEachNode([&](const std::array<Index, D>& node) {
    const Real* from = x + D * own.localIndex(node);
    Real* to = local_.data() + D * local.localIndex(node);
    for (int c = 0; c < D; ++c) to[c] = from[c];
  });
  exchange_->exchange(local_.data());
  rows_->multiply(local_.data(), y, direct);
}

template class RankStencilProduct<1>;
template class RankStencilProduct<2>;
template class RankStencilProduct<3>;

}  // namespace mfwave
