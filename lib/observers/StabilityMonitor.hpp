#pragma once
// Stops a run at the first sign of numerical instability and says where and when: the first
// non-finite value, an amplitude above an absolute limit, or runaway growth of grid-scale
// oscillations in time.
//
// Why "grid-scale in time": a response from rest to a sharp source (a Ricker wavelet, a step) can
// grow by many orders of magnitude within a few dozen steps, so amplitude growth alone raises
// false alarms. What distinguishes an explicit scheme's instability is that the growing mode sits
// at or beyond the time grid's Nyquist limit: the mode that escapes central difference or leapfrog
// first has omega dt > 2 and flips sign every step, and an unstable Runge-Kutta mode has
// omega dt > 2.8. The monitor measures the temporal second difference of the displacement,
// r = ||u_k - 2 u_{k-1} + u_{k-2}|| / ||u_{k-1}||, which is (omega dt)^2 for a mode of frequency
// omega resolved in time and about 4 for a sign-flipping one; a resolved physical response has
// r well below 1. Runaway growth is declared when the amplitude has grown by more than
// `growthFactor` against its history at least `window` observations old AND r exceeds
// `oscillationThreshold`. Add the monitor with every = 1 so r sees consecutive steps.
// Slow growth (a complex eigenvalue pair, a negative omega^2) is not grid-scale. Once the loads
// have ended (`quietAfter`), a passive linear system can no longer gain energy, so when BOTH the
// displacement and the velocity exceed `growthFactor` times their quiet reference (the largest
// amplitude up to `window` observations after the loads ended) the run is stopped as unstable at
// any frequency, however slow the growth. Both, because one alone grows in physical motion: the
// displacement of a body set moving (u = v0 t from 0), the velocity of a body released from a
// displacement (from 0 at the first step); an unstable mode u ~ e^{st} grows in both.
// absoluteLimit and the energy ledgers (LinearEnergyLedger) remain the guards while loads act.

#include "observers/Observer.hpp"

#include <deque>
#include <limits>
#include <string>
#include <vector>

namespace mfwave {

struct StabilityMonitorOptions {
  Real growthFactor = 1e3;
  long window = 50;
  // r above this marks grid-scale oscillation in time: 2 means a period shorter than 4 steps.
  Real oscillationThreshold = 2;
  // Any amplitude above this bound stops the run at once (catches slow growth over long runs).
  Real absoluteLimit = std::numeric_limits<Real>::infinity();
  // Unknowns per particle, to report the particle (dof / components) and the component.
  int components = 1;
  // Every load is zero after this time (TimeFunction::quietAfter; 0 for free vibration from an
  // initial state); from then on growth is judged at any frequency. +infinity: never.
  Real quietAfter = std::numeric_limits<Real>::infinity();
  // false (stability.allow_growth): growth after the loads is recorded (growthMessage()) and the run
  // goes on, to show it on purpose. Non-finite values, the absolute limit and grid-scale growth
  // still stop.
  bool stopGrowthAfterLoads = true;
};

class StabilityMonitor : public Observer {
 public:
  explicit StabilityMonitor(StabilityMonitorOptions options = {});
  // Throws InstabilityError naming the step, time, particle and component.
  void observe(const StateView& state) override;

  // The last temporal second-difference ratio r (0 until three observations were made).
  Real oscillationRatio() const { return lastRatio_; }
  // With stopGrowthAfterLoads = false: the message the run would have stopped with (empty if none).
  const std::string& growthMessage() const { return growthMessage_; }

  // The amplitude histories, references, the last two displacements and the counters.
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

 private:
  struct History {
    std::deque<Real> amplitudes;
    Real reference = 0;
    Real quietReference = 0;  // largest amplitude up to `window` observations after quietAfter
  };
  // Largest |value| and where; throws at a non-finite value or above the absolute limit.
  Real scan(const StateView& state, const Vector& field, const char* name, Index& worst) const;
  bool grewAgainstHistory(History& history, Real amplitude) const;
  // Updates the quiet reference while it is being taken; afterwards, whether the amplitude is above
  // growthFactor times it.
  bool grewSinceQuiet(History& history, Real amplitude, bool judging) const;
  std::string message(const StateView& state, const Vector& field, const char* name, Index worst,
                      const std::string& why) const;
  [[noreturn]] void fail(const StateView& state, const Vector& field, const char* name, Index worst,
                         const std::string& why) const;
  Real oscillationRatio(const Vector& u) const;

  StabilityMonitorOptions options_;
  History displacement_, velocity_;
  Vector previous_, beforePrevious_;
  // Per-block partial results of the scans (scan, oscillationRatio), kept between observations.
  struct BlockScratch {
    std::vector<Real> largest, squares, scaleSquares;
    std::vector<Index> worst, nonFinite;
  };
  mutable BlockScratch blocks_;
  long observations_ = 0;
  long quietObservations_ = 0;  // observations at or after quietAfter
  Real lastRatio_ = 0;
  std::string growthMessage_;
};

}  // namespace mfwave
