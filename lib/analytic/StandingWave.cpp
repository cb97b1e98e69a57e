#include "analytic/StandingWave.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <string>

namespace mfwave {

StandingWave::StandingWave(int mode, Real length, Real waveSpeed, Real amplitude, Real origin)
    : c_(waveSpeed), amplitude_(amplitude), origin_(origin) {
  if (mode < 1) throw InputError("mode", "must be at least 1, got " + std::to_string(mode));
  if (!(length > 0)) throw InputError("length", "must be positive");
  if (!(waveSpeed > 0)) throw InputError("wave_speed", "must be positive");
  k_ = mode * kPi / length;
}

Real StandingWave::displacement(Real x, Real t) const {
  return amplitude_ * std::sin(k_ * (x - origin_)) * std::cos(c_ * k_ * t);
}

Real StandingWave::velocity(Real x, Real t) const {
  return -amplitude_ * c_ * k_ * std::sin(k_ * (x - origin_)) * std::sin(c_ * k_ * t);
}

Real StandingWave::period() const { return 2 * kPi / (c_ * k_); }

}  // namespace mfwave
