#include "observers/StabilityMonitor.hpp"

#include "core/Error.hpp"
#include "systems/ParallelVector.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace mfwave {

StabilityMonitor::StabilityMonitor(StabilityMonitorOptions options) : options_(options) {
  if (!(options_.growthFactor > 1)) throw InputError("stability.growth_factor", "must be greater than 1");
  if (options_.window < 1) throw InputError("stability.window", "must be at least 1");
  if (options_.components < 1) throw InputError("stability.components", "must be at least 1");
  if (!(options_.absoluteLimit > 0)) throw InputError("stability.absolute_limit", "must be positive");
  if (!(options_.oscillationThreshold > 0))
    throw InputError("stability.oscillation_threshold", "must be positive");
}

std::string StabilityMonitor::message(const StateView& state, const Vector& field, const char* name, Index worst,
                                      const std::string& why) const {
  std::ostringstream message;
  message.precision(6);
  const long particle = static_cast<long>(worst / options_.components);
  const long component = static_cast<long>(worst % options_.components);
  message << "numerical instability at step " << state.step << ", t = " << state.time << ": " << why << " in "
          << name << " of particle " << particle << " (component " << component << ", value " << field[worst]
          << ")";
  return message.str();
}

void StabilityMonitor::fail(const StateView& state, const Vector& field, const char* name, Index worst,
                            const std::string& why) const {
  throw InstabilityError(message(state, field, name, worst, why), state.step, state.time,
                         static_cast<long>(worst / options_.components));
}

namespace {

// The scans run over fixed blocks of entries, in parallel, and combine the blocks in order: the
// results are those of one pass in index order, on any thread count. Every step reads the whole
// state here, so on the lattice operators (tens of millions of unknowns) a serial scan costs as
// much as the step.
constexpr Index kScanBlock = Index{1} << 14;

Index scanBlocks(Index n) { return std::max<Index>(1, (n + kScanBlock - 1) / kScanBlock); }

// f(block) for every block: on the calling thread for a few blocks (a small state observed every
// step must not pay for a parallel region), else OpenMP-parallel.
template <class Function>
void forEachScanBlock(Index blocks, Function&& f) {
  if (blocks <= 4) {
    for (Index b = 0; b < blocks; ++b) f(b);
    return;
  }
#pragma omp parallel for schedule(static)
  for (long b = 0; b < static_cast<long>(blocks); ++b) f(static_cast<Index>(b));
}

}  // namespace

Real StabilityMonitor::scan(const StateView& state, const Vector& field, const char* name, Index& worst) const {
  const Index n = field.size(), blocks = scanBlocks(n);
  std::vector<Real>& blockLargest = blocks_.largest;
  std::vector<Index>& blockWorst = blocks_.worst;
  std::vector<Index>& blockNonFinite = blocks_.nonFinite;
  blockLargest.assign(static_cast<std::size_t>(blocks), 0.0);
  blockWorst.assign(static_cast<std::size_t>(blocks), 0);
  blockNonFinite.assign(static_cast<std::size_t>(blocks), -1);
  forEachScanBlock(blocks, [&](Index b) {
    const Index begin = b * kScanBlock, end = std::min(n, begin + kScanBlock);
    Real largest = 0;
    Index at = begin, nonFinite = -1;
    for (Index i = begin; i < end; ++i) {
      const Real value = std::abs(field[i]);
      if (!std::isfinite(value)) {
        nonFinite = i;
        break;
      }
      if (value > largest) {
        largest = value;
        at = i;
      }
    }
    blockLargest[static_cast<std::size_t>(b)] = largest;
    blockWorst[static_cast<std::size_t>(b)] = at;
    blockNonFinite[static_cast<std::size_t>(b)] = nonFinite;
  });
  // The first non-finite entry, else the first entry of the largest magnitude.
  Real amplitude = 0;
  worst = 0;
  for (std::size_t b = 0; b < blockLargest.size(); ++b) {
    if (blockNonFinite[b] >= 0) {
      worst = blockNonFinite[b];
      fail(state, field, name, worst, "non-finite value");
    }
    if (blockLargest[b] > amplitude) {
      amplitude = blockLargest[b];
      worst = blockWorst[b];
    }
  }
  if (amplitude > options_.absoluteLimit) {
    std::ostringstream why;
    why << "amplitude " << amplitude << " above the limit " << options_.absoluteLimit;
    fail(state, field, name, worst, why.str());
  }
  return amplitude;
}

bool StabilityMonitor::grewAgainstHistory(History& history, Real amplitude) const {
  const bool grew = history.reference > 0 && amplitude > options_.growthFactor * history.reference;
  // The reference is the largest amplitude seen at least `window` observations ago.
  history.amplitudes.push_back(amplitude);
  if (static_cast<long>(history.amplitudes.size()) > options_.window) {
    history.reference = std::max(history.reference, history.amplitudes.front());
    history.amplitudes.pop_front();
  }
  return grew;
}

bool StabilityMonitor::grewSinceQuiet(History& history, Real amplitude, bool judging) const {
  if (!judging) {
    history.quietReference = std::max(history.quietReference, amplitude);
    return false;
  }
  return history.quietReference > 0 && amplitude > options_.growthFactor * history.quietReference;
}

Real StabilityMonitor::oscillationRatio(const Vector& u) const {
  // |u - 2 u_prev + u_before| / |u_prev|, both sums of squares per block, then over blocks in order.
  const Index n = u.size(), blocks = scanBlocks(n);
  std::vector<Real>& secondDifference = blocks_.squares;
  std::vector<Real>& scale = blocks_.scaleSquares;
  secondDifference.assign(static_cast<std::size_t>(blocks), 0.0);
  scale.assign(static_cast<std::size_t>(blocks), 0.0);
  forEachScanBlock(blocks, [&](Index b) {
    const Index begin = b * kScanBlock, end = std::min(n, begin + kScanBlock);
    Real d2 = 0, p2 = 0;
    for (Index i = begin; i < end; ++i) {
      const Real d = u[i] - 2 * previous_[i] + beforePrevious_[i];
      d2 += d * d;
      p2 += previous_[i] * previous_[i];
    }
    secondDifference[static_cast<std::size_t>(b)] = d2;
    scale[static_cast<std::size_t>(b)] = p2;
  });
  Real d2 = 0, p2 = 0;
  for (std::size_t b = 0; b < scale.size(); ++b) {
    d2 += secondDifference[b];
    p2 += scale[b];
  }
  if (p2 == 0) return 0;
  return std::sqrt(d2) / std::sqrt(p2);
}

void StabilityMonitor::observe(const StateView& state) {
  Index worstU = 0, worstV = 0;
  const Real amplitudeU = scan(state, state.displacement, "displacement", worstU);
  const Real amplitudeV = scan(state, state.velocity, "velocity", worstV);
  const bool grewU = grewAgainstHistory(displacement_, amplitudeU);
  const bool grewV = grewAgainstHistory(velocity_, amplitudeV);
  ++observations_;
  if (observations_ >= 3) {
    lastRatio_ = oscillationRatio(state.displacement);
    if ((grewU || grewV) && lastRatio_ > options_.oscillationThreshold) {
      std::ostringstream why;
      why << "runaway growth of a grid-scale oscillation (amplitude grew more than " << options_.growthFactor
          << " times within " << options_.window << " observations; temporal second-difference ratio "
          << lastRatio_ << ", a mode at the time step's Nyquist limit: the step is too large for this operator)";
      if (grewU)
        fail(state, state.displacement, "displacement", worstU, why.str());
      else
        fail(state, state.velocity, "velocity", worstV, why.str());
    }
  }
  if (state.time >= options_.quietAfter) ++quietObservations_;
  const bool judging = quietObservations_ > options_.window;
  const bool quietU = grewSinceQuiet(displacement_, amplitudeU, judging);
  const bool quietV = grewSinceQuiet(velocity_, amplitudeV, judging);
  if (quietU && quietV && growthMessage_.empty()) {
    std::ostringstream why;
    why << "growth after the loads ended (displacement and velocity both above " << options_.growthFactor
        << " times their largest values until " << options_.window << " observations after t = "
        << options_.quietAfter << ", from when no load acts: a growing mode of the operator, a negative or complex "
        << "omega^2, or a step above the integrator's limit)";
    if (options_.stopGrowthAfterLoads) fail(state, state.displacement, "displacement", worstU, why.str());
    growthMessage_ = message(state, state.displacement, "displacement", worstU, why.str());
  }
  // Keep the last two displacements (swap buffers: one copy per observation).
  beforePrevious_.swap(previous_);
  assignCopy(previous_, state.displacement);
}

namespace {

void saveHistory(StateArchive archive, const std::deque<Real>& amplitudes, Real reference, Real quietReference) {
  archive.put("amplitudes", std::vector<Real>(amplitudes.begin(), amplitudes.end()));
  archive.put("references", std::vector<Real>{reference, quietReference});
}

void restoreHistory(const StateArchive& archive, std::deque<Real>& amplitudes, Real& reference, Real& quietReference) {
  const std::vector<Real>& stored = archive.get("amplitudes");
  amplitudes.assign(stored.begin(), stored.end());
  const std::vector<Real>& references = archive.numbers("references", 2);
  reference = references[0];
  quietReference = references[1];
}

}  // namespace

void StabilityMonitor::saveState(StateArchive& archive) const {
  saveHistory(archive.section("displacement"), displacement_.amplitudes, displacement_.reference,
              displacement_.quietReference);
  saveHistory(archive.section("velocity"), velocity_.amplitudes, velocity_.reference, velocity_.quietReference);
  archive.put("previous", previous_);
  archive.put("before_previous", beforePrevious_);
  archive.put("counters", std::vector<Real>{static_cast<Real>(observations_), static_cast<Real>(quietObservations_),
                                            lastRatio_});
  archive.putText("growth_message", growthMessage_);
}

void StabilityMonitor::restoreState(const StateArchive& archive) {
  restoreHistory(archive.section("displacement"), displacement_.amplitudes, displacement_.reference,
                 displacement_.quietReference);
  restoreHistory(archive.section("velocity"), velocity_.amplitudes, velocity_.reference, velocity_.quietReference);
  archive.getResized("previous", previous_);
  archive.getResized("before_previous", beforePrevious_);
  const std::vector<Real>& counters = archive.numbers("counters", 3);
  observations_ = static_cast<long>(counters[0]);
  quietObservations_ = static_cast<long>(counters[1]);
  lastRatio_ = counters[2];
  growthMessage_ = archive.text("growth_message");
}

}  // namespace mfwave
