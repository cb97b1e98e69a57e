#pragma once
// Standing waves of the 1-D wave equation u_tt = c^2 u_xx on [x0, x0 + L] with u = 0 at both ends:
// u(x, t) = A sin(k (x - x0)) cos(c k t), k = n pi / L. The exact reference of the wave1d study.

#include "core/Types.hpp"

namespace mfwave {

class StandingWave {
 public:
  // mode n >= 1, length L > 0, wave speed c > 0; throws InputError naming the parameter.
  StandingWave(int mode, Real length, Real waveSpeed, Real amplitude = 1, Real origin = 0);

  Real displacement(Real x, Real t) const;
  Real velocity(Real x, Real t) const;
  Real wavenumber() const { return k_; }
  Real angularFrequency() const { return c_ * k_; }
  Real period() const;

 private:
  Real k_, c_, amplitude_, origin_;
};

}  // namespace mfwave
