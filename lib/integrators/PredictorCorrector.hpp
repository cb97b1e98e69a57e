#pragma once
// The midpoint predictor-corrector of SPH codes (Monaghan 1989, 1992), i.e. the explicit midpoint
// Runge-Kutta method:
//   y*      = y_n + dt/2 F(t_n, y_n)             (predictor, to the half step)
//   y_{n+1} = y_n + dt F(t_n + dt/2, y*)         (corrector, with the midpoint rate)
// Second order, two evaluations per step. On an undamped oscillation it is weakly unstable: the
// amplitude grows by sqrt(1 + (omega dt)^4 / 4) per step (docs/theory/time-integration.md), which
// SPH's artificial viscosity usually hides.

#include "integrators/ExplicitFirstOrderIntegrator.hpp"

namespace mfwave {

class PredictorCorrector : public ExplicitFirstOrderIntegrator {
 public:
  std::string name() const override { return "predictor_corrector"; }

 protected:
  void start() override;
  void advance(Real dt) override;

 private:
  Vector rate_;     // F (work)
  Vector predict_;  // y* (work)
};

}  // namespace mfwave
