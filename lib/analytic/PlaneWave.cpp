#include "analytic/PlaneWave.hpp"

#include "core/Error.hpp"

#include <cmath>

namespace mfwave {

template <int D>
PlaneWave<D>::PlaneWave(const Vec<D>& wavevector, const Vec<D>& polarisation, Real waveSpeed, Real amplitude)
    : k_(wavevector), e_(polarisation), omega_(waveSpeed * wavevector.norm()), amplitude_(amplitude) {
  if (!(wavevector.norm() > 0)) throw InputError("wavevector", "must not be zero");
  if (std::abs(polarisation.norm() - 1) > 1e-12) throw InputError("polarisation", "must be a unit vector");
  if (!(waveSpeed > 0)) throw InputError("wave_speed", "must be positive");
}

template <int D>
Vec<D> PlaneWave<D>::displacement(const Vec<D>& x, Real t) const {
  return amplitude_ * std::cos(k_.dot(x) - omega_ * t) * e_;
}

template <int D>
Vec<D> PlaneWave<D>::velocity(const Vec<D>& x, Real t) const {
  return amplitude_ * omega_ * std::sin(k_.dot(x) - omega_ * t) * e_;
}

template <int D>
Real PlaneWave<D>::period() const {
  return 2 * kPi / omega_;
}

template class PlaneWave<1>;
template class PlaneWave<2>;
template class PlaneWave<3>;

}  // namespace mfwave
