#pragma once
// A lattice operator applied on one rank (issue 22): the rank's owned values copied into its local
// box, the halo exchanged (HaloExchange, reach of these stencils), the owned rows applied
// (LocalStencils). Each owned row of the result is the serial product's row bit for bit. The
// stiffness of DistributedLatticeSystem and the smoothing filter of a run on ranks are two.

#include "decomposition/BlockDecomposition.hpp"
#include "decomposition/LocalStencils.hpp"
#include "decomposition/mpi/HaloExchange.hpp"
#include "lattice/LatticeStencils.hpp"

#include <mpi.h>

#include <memory>
#include <utility>
#include <vector>

namespace mfwave {

// C components per node, as the stencils' (LatticeStencils<D, C>).
template <int D, int C = D>
class RankStencilProduct {
 public:
  // `stencils` and `decomposition` must outlive this object.
  RankStencilProduct(const LatticeStencils<D, C>& stencils, const BlockDecomposition<D>& decomposition, int rank,
                     MPI_Comm communicator);

  // y = the owned rows applied to x, both C values per owned node in the owned box's order (y must
  // not alias x). Collective: every rank calls it. `direct` as LocalStencils::multiply's.
  void multiply(const Real* x, Real* y, const std::vector<char>* direct = nullptr);
  // The products one by one (LocalStencils::forEachProduct) after the same exchange, so a caller
  // fuses its use of each row with the product, as the serial fused solve does.
  // The rows that read no halo node run while the halo messages are in flight, the others after
  // they arrive; each line is computed whole either way, so every row is the serial one.
  template <class Function, class Direct>
  void forEachProduct(const Real* x, Function&& f, Direct&& direct) {
    startExchange(x);
    rows_->forEachProduct(local_.data(), f, direct, OwnedLines::WithoutHalo);
    exchange_->finish(local_.data());
    rows_->forEachProduct(local_.data(), f, direct, OwnedLines::WithHalo);
  }

  const Box<D>& owned() const { return exchange_->plan().owned(); }
  const HaloExchange<D>& exchange() const { return *exchange_; }

 private:
  // x (owned) into the local box, and its halo messages posted (HaloExchange::start).
  void startExchange(const Real* x);

  std::unique_ptr<HaloExchange<D>> exchange_;
  std::unique_ptr<LocalStencils<D, C>> rows_;
  std::vector<Real> local_;  // the local box's values
};

extern template class RankStencilProduct<1>;
extern template class RankStencilProduct<2>;
extern template class RankStencilProduct<3>;
extern template class RankStencilProduct<2, 1>;
extern template class RankStencilProduct<3, 1>;

}  // namespace mfwave
