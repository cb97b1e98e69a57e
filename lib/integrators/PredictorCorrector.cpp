#include "integrators/PredictorCorrector.hpp"

namespace mfwave {

void PredictorCorrector::start() {
  rate_.resize(y_.size());
  predict_.resize(y_.size());
}

void PredictorCorrector::advance(Real dt) {
  system_->rhs(time_, y_, rate_);
  predict_ = y_ + (0.5 * dt) * rate_;
  system_->rhs(time_ + 0.5 * dt, predict_, rate_);
  evaluations_ += 2;
  y_.noalias() += dt * rate_;
}

}  // namespace mfwave
