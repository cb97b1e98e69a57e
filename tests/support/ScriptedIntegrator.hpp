#pragma once
// A stand-in integrator for observer and output tests: each step runs script(step, u, v), so
// states, growth, NaNs and step counts are exactly known; time = step * dt.

#include "integrators/Integrator.hpp"

#include <functional>

namespace mfwave::testing {

class ScriptedIntegrator : public Integrator {
 public:
  ScriptedIntegrator(Vector u, Vector v, Real dt, std::function<void(long, Vector&, Vector&)> script)
      : u_(std::move(u)), v_(std::move(v)), dt_(dt), script_(std::move(script)) {}
  std::string name() const override { return "scripted"; }
  void step() override {
    ++steps_;
    script_(steps_, u_, v_);
  }
  Real time() const override { return static_cast<Real>(steps_) * dt_; }
  long stepCount() const override { return steps_; }
  Real stepSize() const override { return dt_; }
  StateView state() const override { return {steps_, time(), u_, v_}; }

 private:
  Vector u_, v_;
  Real dt_;
  long steps_ = 0;
  std::function<void(long, Vector&, Vector&)> script_;
};

}  // namespace mfwave::testing
