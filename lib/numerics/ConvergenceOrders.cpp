#include "numerics/ConvergenceOrders.hpp"

namespace mfwave {

Real pairwiseOrder(Real coarseSpacing, Real coarseError, Real fineSpacing, Real fineError) {
  return std::log(coarseError / fineError) / std::log(coarseSpacing / fineSpacing);
}

}  // namespace mfwave
