#include "decomposition/mpi/RankStencilProduct.hpp"

#include <algorithm>

namespace mfwave {

template <int D, int C>
RankStencilProduct<D, C>::RankStencilProduct(const LatticeStencils<D, C>& stencils, const BlockDecomposition<D>& decomposition,
                                          int rank, MPI_Comm communicator)
    : exchange_(std::make_unique<HaloExchange<D>>(HaloPlan<D>(decomposition, rank, stencilReach(stencils)), C,
                                                  communicator)),
      rows_(std::make_unique<LocalStencils<D, C>>(stencils, exchange_->plan().owned(), exchange_->plan().local())),
      local_(static_cast<std::size_t>(exchange_->localSize())) {}

template <int D, int C>
void RankStencilProduct<D, C>::multiply(const Real* x, Real* y, const std::vector<char>* direct) {
  // As forEachProduct: the rows that need no halo while it is in flight, then the others.
  startExchange(x);
  rows_->multiply(local_.data(), y, direct, OwnedLines::WithoutHalo);
  exchange_->finish(local_.data());
  rows_->multiply(local_.data(), y, direct, OwnedLines::WithHalo);
}

template <int D, int C>
void RankStencilProduct<D, C>::startExchange(const Real* x) {
  const Box<D>& own = owned();
  const Box<D>& local = exchange_->plan().local();
  // Line by line: an owned line is contiguous in both boxes (x fastest).
  const Index length = C * own.extent(0);
  const long lines = static_cast<long>(own.lineCount());
#pragma omp parallel for schedule(static) if (lines > 16 && own.count() > 20000)
  for (long line = 0; line < lines; ++line) {
    const std::array<Index, D> start = own.lineStart(line);
    std::copy_n(x + C * own.localIndex(start), length, local_.data() + C * local.localIndex(start));
  }
  exchange_->start(local_.data());
}

template class RankStencilProduct<1>;
template class RankStencilProduct<2>;
template class RankStencilProduct<3>;
template class RankStencilProduct<2, 1>;
template class RankStencilProduct<3, 1>;

}  // namespace mfwave
