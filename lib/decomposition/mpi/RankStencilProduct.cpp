#include "decomposition/mpi/RankStencilProduct.hpp"

#include <algorithm>

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
  exchange(x);
  rows_->multiply(local_.data(), y, direct);
}

template <int D>
void RankStencilProduct<D>::exchange(const Real* x) {
  const Box<D>& own = owned();
  const Box<D>& local = exchange_->plan().local();
  // Line by line: an owned line is contiguous in both boxes (x fastest).
  const Index length = D * own.extent(0);
  const long lines = static_cast<long>(own.lineCount());
#pragma omp parallel for schedule(static) if (lines > 16 && own.count() > 20000)
  for (long line = 0; line < lines; ++line) {
    const std::array<Index, D> start = own.lineStart(line);
    std::copy_n(x + D * own.localIndex(start), length, local_.data() + D * local.localIndex(start));
  }
  exchange_->exchange(local_.data());
}

template class RankStencilProduct<1>;
template class RankStencilProduct<2>;
template class RankStencilProduct<3>;

}  // namespace mfwave
