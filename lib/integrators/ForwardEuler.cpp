#include "integrators/ForwardEuler.hpp"

namespace mfwave {

void ForwardEuler::advance(Real dt) {
  system_->rhs(time_, y_, rate_);
  evaluations_ += 1;
  y_.noalias() += dt * rate_;
}

}  // namespace mfwave
