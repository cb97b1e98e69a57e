#pragma once
// A plane elastic wave u(x, t) = U e cos(k . x - omega t), omega = c |k|, in an unbounded (or
// periodic) isotropic solid: e = k / |k| for a P wave (c = c_p), e normal to k for an S wave
// (c = c_s). The exact reference of the planewave study (a periodic box holding whole wavelengths).

#include "core/Types.hpp"

namespace mfwave {

template <int D>
class PlaneWave {
 public:
  // Throws InputError("wavevector") for k = 0, InputError("polarisation") for a polarisation not
  // of unit length, InputError("wave_speed") for c <= 0.
  PlaneWave(const Vec<D>& wavevector, const Vec<D>& polarisation, Real waveSpeed, Real amplitude = 1);

  Vec<D> displacement(const Vec<D>& x, Real t) const;
  Vec<D> velocity(const Vec<D>& x, Real t) const;
  Real angularFrequency() const { return omega_; }
  Real period() const;

 private:
  Vec<D> k_, e_;
  Real omega_, amplitude_;
};

}  // namespace mfwave
