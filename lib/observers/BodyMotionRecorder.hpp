#pragma once
// The motion of bodies (groups of particles) from a particle view: each body's centre of mass and
// the velocity of its centre of mass (mass-weighted means of the current positions and of v), and
// its extent (smallest and largest coordinate along each axis), with the step just taken. Two
// rings colliding, a projectile and its target, the pieces of a broken bar: whatever the method,
// as long as its view holds the current positions in a particle set -- the moved copy a
// ViewAdapter keeps for a first-order method (SolidStateAdapter::particles()), or the fixed
// particles of a linear method with `addDisplacement` (x = X + u).

#include "core/Types.hpp"
#include "observers/Observer.hpp"
#include "particles/ParticleSet.hpp"

#include <string>
#include <vector>

namespace mfwave {

template <int D>
class BodyMotionRecorder : public Observer {
 public:
  struct Body {
    std::string name;
    std::vector<Index> members;
  };
  struct Sample {
    Real time = 0;
    Real dt = 0;  // the step just taken (0 for the initial state)
    std::vector<Vec<D>> centre, velocity, lower, upper;  // per body
  };

  // `positions` must outlive the recorder (and, when it moves, be moved before each view is
  // shown); `masses` has one entry per particle of `positions`.
  BodyMotionRecorder(const ParticleSet<D>& positions, std::vector<Real> masses, std::vector<Body> bodies,
                     bool addDisplacement = false);

  // Samples the view, once per step; a view with a non-finite position or velocity is left out
  // (the run's monitors report it).
  void observe(const StateView& state) override;
  void end(const StateView& state) override { observe(state); }

  // The samples so far (each: time, dt, then per body centre, velocity, lower, upper) and the
  // last step sampled.
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<Sample>& samples() const { return samples_; }

 private:
  const ParticleSet<D>& positions_;
  std::vector<Real> masses_;
  std::vector<Body> bodies_;
  bool addDisplacement_;
  std::vector<Sample> samples_;
  long lastStep_ = -1;
};

extern template class BodyMotionRecorder<1>;
extern template class BodyMotionRecorder<2>;
extern template class BodyMotionRecorder<3>;

}  // namespace mfwave
