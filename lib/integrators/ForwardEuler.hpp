#pragma once
// Forward Euler on y' = F(t, y): y_{n+1} = y_n + dt F(t_n, y_n). First order, one evaluation per
// step. A reference and a baseline only: on an undamped wave (eigenvalues +-i omega) it is
// unstable for every dt, the amplitude growing by sqrt(1 + (omega dt)^2) per step
// (docs/theory/time-integration.md).

#include "integrators/ExplicitFirstOrderIntegrator.hpp"

namespace mfwave {

class ForwardEuler : public ExplicitFirstOrderIntegrator {
 public:
  std::string name() const override { return "forward_euler"; }

 protected:
  void start() override { rate_.resize(y_.size()); }
  void advance(Real dt) override;

 private:
  Vector rate_;  // F(t_n, y_n) (work)
};

}  // namespace mfwave
