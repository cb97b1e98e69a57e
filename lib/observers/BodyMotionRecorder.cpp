#include "observers/BodyMotionRecorder.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mfwave {

template <int D>
BodyMotionRecorder<D>::BodyMotionRecorder(const ParticleSet<D>& positions, std::vector<Real> masses,
                                          std::vector<Body> bodies, bool addDisplacement)
    : positions_(positions), masses_(std::move(masses)), bodies_(std::move(bodies)), addDisplacement_(addDisplacement) {
  if (static_cast<Index>(masses_.size()) != positions_.size())
    throw Error("BodyMotionRecorder: " + std::to_string(masses_.size()) + " masses for " +
                std::to_string(positions_.size()) + " particles");
  for (const Body& body : bodies_) {
    if (body.members.empty()) throw Error("BodyMotionRecorder: body '" + body.name + "' has no particles");
    for (const Index i : body.members)
      if (i < 0 || i >= positions_.size())
        throw Error("BodyMotionRecorder: body '" + body.name + "' names particle " + std::to_string(i) +
                    " of " + std::to_string(positions_.size()));
  }
}

template <int D>
void BodyMotionRecorder<D>::observe(const StateView& s) {
  if (s.step == lastStep_) return;  // end() right after a sample of the same step
  lastStep_ = s.step;
  Sample sample;
  sample.time = s.time;
  sample.dt = s.step > 0 ? s.dt : 0;
  const Real infinity = std::numeric_limits<Real>::infinity();
  for (const Body& body : bodies_) {
    Real mass = 0;
    Vec<D> moment = Vec<D>::Zero(), momentum = Vec<D>::Zero();
    Vec<D> lower = Vec<D>::Constant(infinity), upper = Vec<D>::Constant(-infinity);
    for (const Index i : body.members) {
      const Real m = masses_[static_cast<std::size_t>(i)];
      mass += m;
      for (int a = 0; a < D; ++a) {
        Real x = positions_.coordinate(a)[static_cast<std::size_t>(i)];
        if (addDisplacement_) x += s.displacement[i * D + a];
        moment[a] += m * x;
        momentum[a] += m * s.velocity[i * D + a];
        lower[a] = std::min(lower[a], x);
        upper[a] = std::max(upper[a], x);
      }
    }
    if (!moment.allFinite() || !momentum.allFinite()) return;  // left out: not finite
    sample.centre.push_back(moment / mass);
    sample.velocity.push_back(momentum / mass);
    sample.lower.push_back(lower);
    sample.upper.push_back(upper);
  }
  samples_.push_back(std::move(sample));
}

template <int D>
void BodyMotionRecorder<D>::saveState(StateArchive& archive) const {
  std::vector<Real> samples;
  for (const Sample& sample : samples_) {
    samples.push_back(sample.time);
    samples.push_back(sample.dt);
    for (std::size_t b = 0; b < bodies_.size(); ++b)
      for (const std::vector<Vec<D>>* part : {&sample.centre, &sample.velocity, &sample.lower, &sample.upper})
        for (int a = 0; a < D; ++a) samples.push_back((*part)[b][a]);
  }
  archive.put("samples", std::move(samples));
  archive.putScalar("last_step", static_cast<Real>(lastStep_));
}

template <int D>
void BodyMotionRecorder<D>::restoreState(const StateArchive& archive) {
  const std::vector<Real>& samples = archive.get("samples");
  const std::size_t width = 2 + 4 * D * bodies_.size();  // numbers per sample
  if (samples.size() % width != 0)
    throw InputError("--restart", "the checkpoint's body motion is not of " + std::to_string(bodies_.size()) +
                                      " bodies in " + std::to_string(D) + "-D");
  samples_.clear();
  for (std::size_t at = 0; at < samples.size();) {
    Sample sample;
    sample.time = samples[at++];
    sample.dt = samples[at++];
    for (std::size_t b = 0; b < bodies_.size(); ++b)
      for (std::vector<Vec<D>>* part : {&sample.centre, &sample.velocity, &sample.lower, &sample.upper}) {
        Vec<D> value;
        for (int a = 0; a < D; ++a) value[a] = samples[at++];
        part->push_back(value);
      }
    samples_.push_back(std::move(sample));
  }
  lastStep_ = archive.integer("last_step");
}

template class BodyMotionRecorder<1>;
template class BodyMotionRecorder<2>;
template class BodyMotionRecorder<3>;

}  // namespace mfwave
